#pragma once
#include "functionObjects/FunctionObject.hpp"
#include "verification/ShockTubeSolution.hpp"

#include <memory>

namespace mfdyn {

class RiemannError final : public FunctionObject {
public:
    RiemannError(const Dictionary& dict, const std::string& name, const RunContext& context);
    static KeywordSchema keywords();
    void write() override;
    std::vector<ErrorNorm> errorNorms() const override { return norms_.latest(); }
    std::vector<std::string> summary() const override { return summary_; }
    // starPressure, starVelocity: the plateau medians against the exact star state.
    std::vector<ReferenceValue> referenceValues() const override { return references_; }
    std::optional<std::vector<std::string>> fieldsRead() const override;

private:
    RiemannError(const KeywordValues& values, const std::string& name, const RunContext& context);
    std::unique_ptr<ShockTubeSolution> exact_;
    double t0_;
    double from_, to_;
    std::vector<std::string> fields_;
    ErrorNormWriter norms_;
    std::unique_ptr<CsvFile> star_;
    std::unique_ptr<CsvFile> shock_;  // shock.csv, where the right wave is a shock
    std::vector<std::string> summary_;
    std::vector<ReferenceValue> references_;
};

}  // namespace mfdyn
