#pragma once
#include "functionObjects/FunctionObject.hpp"

namespace mfdyn {

class FieldMinMax final : public FunctionObject {
public:
    FieldMinMax(const Dictionary& dict, const std::string& name, const RunContext& context);
    static KeywordSchema keywords();
    void write() override;

private:
    FieldMinMax(const KeywordValues& values, const std::string& name, const RunContext& context);
    std::vector<std::string> fields_;
    bool components_;
    std::unique_ptr<CsvFile> csv_;
};

}  // namespace mfdyn
