#pragma once
// The cubic B-spline (M4) as a fit weight on q = |x - y| / h <= 1. Equations in the .cpp.
#include "meshfreeOperators/fitWeights/FitWeight.hpp"

namespace mfdyn {

class CubicSplineWeight : public FitWeight {
public:
    explicit CubicSplineWeight(const Dictionary& dict);
    static KeywordSchema keywords() { return commonKeywords("cubicSpline"); }

    double shape(double q) const override;
    double shapeDerivative(double q) const override;
};

}  // namespace mfdyn
