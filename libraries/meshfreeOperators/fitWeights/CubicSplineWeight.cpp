// Cubic B-spline fit weight (Schoenberg's M4, Monaghan 1992 Annu. Rev. Astron. Astrophys. 30:543,
// eq. 2.6, with its support 2h mapped onto q = |x - y| / h in [0, 1] and scaled to W(0) = 1):
//
//     W(q)  = 1 - 6 q^2 + 6 q^3,  dW/dq = -12 q + 18 q^2    for q <= 1/2
//     W(q)  = 2 (1 - q)^3,        dW/dq = -6 (1 - q)^2      for 1/2 < q <= 1, else 0
//
// C2 everywhere (the knot at q = 1/2 included), zero slope at q = 0.
#include "meshfreeOperators/fitWeights/CubicSplineWeight.hpp"

namespace mfdyn {

CubicSplineWeight::CubicSplineWeight(const Dictionary& dict) : FitWeight(dict, keywords().read(dict)) {}

double CubicSplineWeight::shape(double q) const {
    if (q <= 0.5) return 1.0 - 6.0 * q * q + 6.0 * q * q * q;
    const double a = 1.0 - q;
    return 2.0 * a * a * a;
}

double CubicSplineWeight::shapeDerivative(double q) const {
    if (q <= 0.5) return -12.0 * q + 18.0 * q * q;
    const double a = 1.0 - q;
    return -6.0 * a * a;
}

MFDYN_REGISTER(FitWeight, CubicSplineWeight, "cubicSpline",
               "cubic B-spline (M4) on q = |x - y|/h in [0, 1], W(0) = 1");

}  // namespace mfdyn
