#pragma once
#include "functionObjects/FunctionObject.hpp"
#include "verification/IsothermalShockBar.hpp"

#include <memory>

namespace mfdyn {

class IsothermalShockBarError final : public FunctionObject {
public:
    IsothermalShockBarError(const Dictionary& dict, const std::string& name, const RunContext& context);
    static KeywordSchema keywords();
    void write() override;
    std::vector<ErrorNorm> errorNorms() const override { return norms_.latest(); }
    std::vector<std::string> summary() const override { return summary_; }
    std::vector<ReferenceValue> referenceValues() const override { return references_; }
    std::optional<std::vector<std::string>> fieldsRead() const override;

private:
    IsothermalShockBarError(const KeywordValues& values, const std::string& name, const RunContext& context);
    std::unique_ptr<IsothermalShockBar> exact_;
    double t0_;
    double from_, to_;
    double frontWindow_;
    std::vector<std::string> fields_;
    ErrorNormWriter norms_;
    std::unique_ptr<CsvFile> plateaus_, fronts_, contact_;
    std::vector<std::string> summary_;
    std::vector<ReferenceValue> references_;  // the plateau medians of the latest write
};

}  // namespace mfdyn
