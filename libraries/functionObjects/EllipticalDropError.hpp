#pragma once
// ellipticalDropError: a 2D run of the elliptical drop (Monaghan 1994; Zisis 2017 §4.5.1) against
// the exact ellipse of libraries/verification/EllipticalDrop. Equations and keywords:
// EllipticalDropError.cpp.
#include "functionObjects/FunctionObject.hpp"
#include "verification/EllipticalDrop.hpp"

#include <memory>

namespace mfdyn {

class EllipticalDropError final : public FunctionObject {
public:
    EllipticalDropError(const Dictionary& dict, const std::string& name, const RunContext& context);
    static KeywordSchema keywords();
    void write() override;
    std::vector<ErrorNorm> errorNorms() const override { return norms_.latest(); }
    std::vector<std::string> summary() const override { return summary_; }
    // a, b, ab: the semi-axes and their product against the exact ones.
    std::vector<ReferenceValue> referenceValues() const override { return references_; }

private:
    EllipticalDropError(const KeywordValues& values, const std::string& name, const RunContext& context);
    EllipticalDrop exact_;
    double radius_;
    ErrorNormWriter norms_;
    std::unique_ptr<CsvFile> axes_;
    std::vector<std::string> summary_;
    std::vector<ReferenceValue> references_;
};

}  // namespace mfdyn
