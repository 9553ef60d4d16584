// The twisting column (Lee, Gil, Greto, Kulasegaram & Bonet 2016, CMAME 311:71, section 8.9,
// Figs 24-28; doc/methods/tl-jst-sph.md 8.9): the 1 x 6 x 1 m column along Y, clamped at its base,
// starts with
//
//     v(X) = omega(X) x (X - c),   omega = Omega sin(pi s/(2L)) e_axis,   s = (X - c).e_axis,
//
// zero twist rate at the base s = 0 and Omega at the free end s = L; u = 0. The paper: Omega = 105
// rad/s, L = 6 m, axis Y, about the origin (the Fig 26 caption's Z is a typo). Not an exact solution
// of the motion that follows, only its initial state; kept with the references so that every test
// problem's analytic data live in one library.
#include "verification/TwistingColumnMotion.hpp"

#include "core/Error.hpp"

#include <Eigen/Geometry>

#include <cmath>
#include <numbers>
#include <string>

namespace mfdyn {

TwistingColumnMotion::TwistingColumnMotion(double Omega, double length, int axis, const Vector<3>& centre)
    : Omega_(Omega), length_(length), axis_(axis), centre_(centre) {
    if (!(length_ > 0)) throw Error("twisting column: expected a positive length [m]");
    if (axis_ < 0 || axis_ > 2)
        throw Error("twisting column: axis " + std::to_string(axis) + " is not 0, 1 or 2");
}

Vector<3> TwistingColumnMotion::velocity(const Vector<3>& X) const {
    const Eigen::Vector3d r = X - centre_;
    Eigen::Vector3d omega = Eigen::Vector3d::Zero();
    omega(axis_) = Omega_ * std::sin(std::numbers::pi * r(axis_) / (2 * length_));
    return omega.cross(r);
}

}  // namespace mfdyn
