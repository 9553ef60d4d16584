#pragma once
#include "functionObjects/FunctionObject.hpp"
#include "functionObjects/Interpolation.hpp"

namespace mfdyn {

class Probes final : public FunctionObject {
public:
    Probes(const Dictionary& dict, const std::string& name, const RunContext& context);
    static KeywordSchema keywords();
    void write() override;
    std::optional<std::vector<std::string>> fieldsRead() const override;

private:
    Probes(const KeywordValues& values, const std::string& name, const RunContext& context);
    std::vector<std::string> fields_;
    std::vector<SamplePoint> points_;
    Interpolation interpolation_;
    bool warned_ = false;
    std::unique_ptr<CsvFile> csv_;
};

}  // namespace mfdyn
