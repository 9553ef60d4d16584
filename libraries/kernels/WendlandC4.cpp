// Wendland C4 (Wendland 1995, Adv. Comput. Math. 4:389, Table 1: psi_{2,2} and psi_{4,2}; Dehnen &
// Aly 2012, MNRAS 425:1068, Table 1). Zisis 2017 prints it as Eq. 2.10 and calls it "C6"; the note
// (doc/methods/sph-impact.md 1.1) identifies it as C4:
//
//     d = 1:     w(u) = (1 - u)^5 (1 + 5u + 8u^2),        w'(u) = -14 u (1 + 4u) (1 - u)^4,     c_1 = 3/2
//     d = 2, 3:  w(u) = (1 - u)^6 (1 + 6u + 35/3 u^2),    w'(u) = -56/3 u (1 + 5u) (1 - u)^5,
//                c_2 = 9/pi, c_3 = 495/(32 pi)
//
// u = r/H with H = 2h by default. Positive definite in the dimension it is built for.
#include "kernels/WendlandC4.hpp"

namespace mfdyn {

WendlandC4::WendlandC4(const Dictionary& dict) : Kernel(dict, keywords().read(dict), 2.0) {
    initialise();
}

double WendlandC4::shape(double u, int dim) const {
    const double a = 1.0 - u, a2 = a * a, a5 = a2 * a2 * a;
    return dim == 1 ? a5 * (1.0 + u * (5.0 + 8.0 * u)) : a5 * a * (1.0 + u * (6.0 + 35.0 / 3.0 * u));
}

double WendlandC4::shapeDerivative(double u, int dim) const {
    const double a = 1.0 - u, a4 = (a * a) * (a * a);
    return dim == 1 ? -14.0 * u * (1.0 + 4.0 * u) * a4 : -56.0 / 3.0 * u * (1.0 + 5.0 * u) * a4 * a;
}

MFDYN_REGISTER(Kernel, WendlandC4, "wendlandC4",
               "Wendland C4 (Wendland 1995), support 2h, positive definite");

}  // namespace mfdyn
