#pragma once
// The truncated Gaussian fit weight exp(-alpha q^2), q = |x - y| / h <= 1. Equations in the .cpp.
#include "meshfreeOperators/fitWeights/FitWeight.hpp"

namespace mfdyn {

class TruncatedGaussianWeight : public FitWeight {
public:
    explicit TruncatedGaussianWeight(const Dictionary& dict);
    static KeywordSchema keywords();

    double alpha() const { return alpha_; }
    double shape(double q) const override;
    double shapeDerivative(double q) const override;

private:
    TruncatedGaussianWeight(const Dictionary& dict, const KeywordValues& values);
    double alpha_;
};

}  // namespace mfdyn
