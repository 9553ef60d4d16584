// M6 quintic B-spline (Schoenberg 1946; Morris, Fox & Zhu 1997, J. Comput. Phys. 136:214;
// Monaghan 2005, Rep. Prog. Phys. 68:1703), in the unit-support form of Zisis 2017 Eq. 2.8
// (doc/methods/sph-impact.md 1.1):
//
//     w(u) = (1 - u)_+^5 - 6 (2/3 - u)_+^5 + 15 (1/3 - u)_+^5,   u = r/H,  H = 3h,
//     c_d  = 3^5/40, 7 3^7/(478 pi), 3^7/(40 pi)                  (d = 1, 2, 3).
//
// C4, knots at u = 1/3 and 2/3. Like M4 its transform is positive in 1D (sinc^6) but not in 2D and
// 3D (Dehnen & Aly 2012).
#include "kernels/QuinticSpline.hpp"

namespace mfdyn {

QuinticSpline::QuinticSpline(const Dictionary& dict) : Kernel(dict, keywords().read(dict), 3.0) {
    initialise();
}

namespace {
double pow4(double x) {
    return (x * x) * (x * x);
}
}  // namespace

double QuinticSpline::shape(double u, int) const {
    const double a = 1.0 - u;
    const double b = u < 2.0 / 3.0 ? 2.0 / 3.0 - u : 0.0;
    const double c = u < 1.0 / 3.0 ? 1.0 / 3.0 - u : 0.0;
    return pow4(a) * a - 6.0 * pow4(b) * b + 15.0 * pow4(c) * c;
}

double QuinticSpline::shapeDerivative(double u, int) const {
    const double a = 1.0 - u;
    const double b = u < 2.0 / 3.0 ? 2.0 / 3.0 - u : 0.0;
    const double c = u < 1.0 / 3.0 ? 1.0 / 3.0 - u : 0.0;
    return -5.0 * pow4(a) + 30.0 * pow4(b) - 75.0 * pow4(c);
}

MFDYN_REGISTER(Kernel, QuinticSpline, "quinticSpline",
               "M6 quintic B-spline (Morris et al. 1997), support 3h");

}  // namespace mfdyn
