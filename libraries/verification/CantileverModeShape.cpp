// The oscillating plate of Gray, Monaghan & Swift 2001 ("SPH elastic dynamics", Comput. Methods
// Appl. Mech. Engrg. 190:6641, section 6.2), as PySPH's oscillating_plate example sets it up: a
// plate clamped at s = 0 and free at s = L starts with the velocity of the first bending mode of an
// Euler-Bernoulli cantilever,
//
//     v_y(s) = V_f f(s)/f(L),   f(s) = M (cos ks - cosh ks) - N (sin ks - sinh ks),
//     M = sin kL + sinh kL,  N = cos kL + cosh kL,  f(L) = 2 (cos kL sinh kL - sin kL cosh kL),
//
// k = kL/L with kL = 1.875 (the first root of 1 + cos kL cosh kL = 0), so that v_y(L) = V_f at the
// free end and v_y = v_y' = 0 at the clamp; v_y = 0 for s <= 0 (inside the clamp). Thin plates only:
// the shape ignores shear. PySPH's Vf is a fraction of the sound speed; here V_f is in m/s. The
// slope f'(s) = k [-M (sin ks + sinh ks) - N (cos ks - cosh ks)] gives the rotation rate of the
// cross-sections, v_x = -(Y - Y0) v_y'(s) in the beam's own kinematics (CantileverMode `sections`).
#include "verification/CantileverModeShape.hpp"

#include "core/Error.hpp"

#include <cmath>

namespace mfdyn {

CantileverModeShape::CantileverModeShape(double length, double tipVelocity, double kL)
    : length_(length), velocity_(tipVelocity), kL_(kL) {
    if (!(length_ > 0)) throw Error("cantilever mode: expected a positive length [m]");
    if (!(kL_ > 0)) throw Error("cantilever mode: expected a positive mode number kL");
    if (!std::isfinite(velocity_)) throw Error("cantilever mode: expected a finite tip velocity [m/s]");
}

double CantileverModeShape::shape(double s) const {
    const double k = kL_ / length_, kL = kL_;
    const double M = std::sin(kL) + std::sinh(kL), N = std::cos(kL) + std::cosh(kL);
    return M * (std::cos(k * s) - std::cosh(k * s)) - N * (std::sin(k * s) - std::sinh(k * s));
}

double CantileverModeShape::shapeSlope(double s) const {
    const double k = kL_ / length_, kL = kL_;
    const double M = std::sin(kL) + std::sinh(kL), N = std::cos(kL) + std::cosh(kL);
    return k * (-M * (std::sin(k * s) + std::sinh(k * s)) - N * (std::cos(k * s) - std::cosh(k * s)));
}

double CantileverModeShape::transverseVelocitySlope(double s) const {
    if (s <= 0) return 0.0;
    return velocity_ * shapeSlope(s) / shape(length_);
}

double CantileverModeShape::transverseVelocity(double s) const {
    if (s <= 0) return 0.0;
    return velocity_ * shape(s) / shape(length_);
}

}  // namespace mfdyn
