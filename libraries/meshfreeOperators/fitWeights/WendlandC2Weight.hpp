#pragma once
// Wendland's C2 function as a fit weight, (1 - q)^4 (1 + 4q) on q = |x - y| / h <= 1. Equations in
// the .cpp.
#include "meshfreeOperators/fitWeights/FitWeight.hpp"

namespace mfdyn {

class WendlandC2Weight : public FitWeight {
public:
    explicit WendlandC2Weight(const Dictionary& dict);
    static KeywordSchema keywords() { return commonKeywords("wendlandC2"); }

    double shape(double q) const override;
    double shapeDerivative(double q) const override;
};

}  // namespace mfdyn
