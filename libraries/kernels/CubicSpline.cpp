// M4 cubic B-spline (Schoenberg 1946; Monaghan & Lattanzio 1985; Monaghan 1992, Annu. Rev. Astron.
// Astrophys. 30:543 Eq. 2.6), in the unit-support form of Zisis 2017 Eq. 2.7 (doc/methods/sph-impact.md 1.1):
//
//     w(u) = (1 - u)_+^3 - 4 (1/2 - u)_+^3,   u = r/H,  H = 2h (Monaghan's h),
//     c_d  = 8/3, 80/(7 pi), 16/pi            (d = 1, 2, 3).
//
// C2, knot at u = 1/2. Its Fourier transform is sinc^4(kH/4) >= 0 in 1D but has negative lobes in
// 2D and 3D (Dehnen & Aly 2012, MNRAS 425:1068, Fig. 2), and it is prone to pairing instability
// with many neighbours; use a Wendland kernel where that matters.
#include "kernels/CubicSpline.hpp"

namespace mfdyn {

CubicSpline::CubicSpline(const Dictionary& dict) : Kernel(dict, keywords().read(dict), 2.0) {
    initialise();
}

double CubicSpline::shape(double u, int) const {
    const double a = 1.0 - u, b = u < 0.5 ? 0.5 - u : 0.0;
    return a * a * a - 4.0 * b * b * b;
}

double CubicSpline::shapeDerivative(double u, int) const {
    const double a = 1.0 - u, b = u < 0.5 ? 0.5 - u : 0.0;
    return -3.0 * a * a + 12.0 * b * b;
}

MFDYN_REGISTER(Kernel, CubicSpline, "cubicSpline", "M4 cubic B-spline (Monaghan 1992), support 2h");

}  // namespace mfdyn
