// Wendland C6 (Wendland 1995, Adv. Comput. Math. 4:389, Table 1: psi_{3,3} and psi_{5,3}; Dehnen &
// Aly 2012, MNRAS 425:1068, Table 1):
//
//     d = 1:     w(u) = (1 - u)^7 (1 + 7u + 19u^2 + 21u^3),   w'(u) = -6 u (3 + 18u + 35u^2) (1 - u)^6,
//                c_1 = 55/32
//     d = 2, 3:  w(u) = (1 - u)^8 (1 + 8u + 25u^2 + 32u^3),   w'(u) = -22 u (1 + 7u + 16u^2) (1 - u)^7,
//                c_2 = 78/(7 pi), c_3 = 1365/(64 pi)
//
// u = r/H with H = 2h by default. Positive definite in the dimension it is built for; the
// smoothest and widest of the three (Dehnen & Aly recommend it for large neighbour numbers).
#include "kernels/WendlandC6.hpp"

namespace mfdyn {

WendlandC6::WendlandC6(const Dictionary& dict) : Kernel(dict, keywords().read(dict), 2.0) {
    initialise();
}

double WendlandC6::shape(double u, int dim) const {
    const double a = 1.0 - u, a2 = a * a, a4 = a2 * a2, a7 = a4 * a2 * a;
    return dim == 1 ? a7 * (1.0 + u * (7.0 + u * (19.0 + 21.0 * u)))
                    : a7 * a * (1.0 + u * (8.0 + u * (25.0 + 32.0 * u)));
}

double WendlandC6::shapeDerivative(double u, int dim) const {
    const double a = 1.0 - u, a2 = a * a, a6 = a2 * a2 * a2;
    return dim == 1 ? -6.0 * u * (3.0 + u * (18.0 + 35.0 * u)) * a6
                    : -22.0 * u * (1.0 + u * (7.0 + 16.0 * u)) * a6 * a;
}

MFDYN_REGISTER(Kernel, WendlandC6, "wendlandC6",
               "Wendland C6 (Wendland 1995), support 2h, positive definite");

}  // namespace mfdyn
