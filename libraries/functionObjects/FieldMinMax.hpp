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
    // `vonMisesStress` where the run has no such field: computed from cauchyStress.
    bool derived(const std::string& field) const;
    std::vector<std::string> fields_;
    bool components_;
    std::unique_ptr<CsvFile> csv_;
};

}  // namespace mfdyn
