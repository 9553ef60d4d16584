// Wendland C2 fit weight (Wendland 1995, Adv. Comput. Math. 4:389, Table 1, psi_{3,1}), unnormalised
// so that W(0) = 1, on q = |x - y| / h (support radius h):
//
//     W(q)  = (1 - q)^4 (1 + 4q)     for q <= 1, else 0
//     dW/dq = -20 q (1 - q)^3
//
// The d = 2, 3 form is used in every dimension: a fit weight needs positivity and smoothness, not
// the positive definiteness the kernel family (kernels/WendlandC2.cpp) keeps per dimension. C2 at
// q = 1, so the fit's coefficients and the full derivative are continuous as neighbours enter and
// leave the support.
#include "meshfreeOperators/fitWeights/WendlandC2Weight.hpp"

namespace mfdyn {

WendlandC2Weight::WendlandC2Weight(const Dictionary& dict) : FitWeight(dict, keywords().read(dict)) {}

double WendlandC2Weight::shape(double q) const {
    const double a = 1.0 - q, a2 = a * a;
    return a2 * a2 * (1.0 + 4.0 * q);
}

double WendlandC2Weight::shapeDerivative(double q) const {
    const double a = 1.0 - q;
    return -20.0 * q * a * a * a;
}

MFDYN_REGISTER(FitWeight, WendlandC2Weight, "wendlandC2",
               "Wendland C2 (1 - q)^4 (1 + 4q), q = |x - y|/h, C2 at the support radius");

}  // namespace mfdyn
