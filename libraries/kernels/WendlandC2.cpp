// Wendland C2 (Wendland 1995, Adv. Comput. Math. 4:389, Table 1: psi_{1,1} and psi_{3,1}; Dehnen &
// Aly 2012, MNRAS 425:1068, Table 1; Zisis 2017 Eq. 2.9 with tau = 3, 4, 4):
//
//     d = 1:     w(u) = (1 - u)^3 (1 + 3u),  w'(u) = -12 u (1 - u)^2,  c_1 = 5/4
//     d = 2, 3:  w(u) = (1 - u)^4 (1 + 4u),  w'(u) = -20 u (1 - u)^3,  c_2 = 7/pi, c_3 = 21/(2 pi)
//
// u = r/H with H = 2h by default. Positive definite in the dimension it is built for (Wendland
// 1995, Thm. 9.13 of Wendland's 2005 book), hence free of the pairing instability (Dehnen & Aly).
#include "kernels/WendlandC2.hpp"

namespace mfdyn {

WendlandC2::WendlandC2(const Dictionary& dict) : Kernel(dict, keywords().read(dict), 2.0) {
    initialise();
}

double WendlandC2::shape(double u, int dim) const {
    const double a = 1.0 - u, a3 = a * a * a;
    return dim == 1 ? a3 * (1.0 + 3.0 * u) : a3 * a * (1.0 + 4.0 * u);
}

double WendlandC2::shapeDerivative(double u, int dim) const {
    const double a = 1.0 - u;
    return dim == 1 ? -12.0 * u * a * a : -20.0 * u * a * a * a;
}

MFDYN_REGISTER(Kernel, WendlandC2, "wendlandC2",
               "Wendland C2 (Wendland 1995), support 2h, positive definite");

}  // namespace mfdyn
