#pragma once
// The initial motion of the twisting column of Lee et al. 2016 section 8.9 (doc/methods/tl-jst-sph.md
// 8.9): a rigid-body-like twist whose angular velocity grows along the column. Formula and sources
// in TwistingColumnMotion.cpp; the initialState twistingColumn (libraries/solver) applies it.
#include "core/Tensor.hpp"

namespace mfdyn {

class TwistingColumnMotion {
public:
    // Omega [rad/s] at the free end s = L, length L [m] (> 0), axis 0/1/2 (X/Y/Z), centre c [m] a
    // point of the axis at the base. Throws Error for a non-positive length or an axis outside 0-2.
    TwistingColumnMotion(double Omega, double length, int axis, const Vector<3>& centre);

    // v(X) = omega(X) x (X - c), omega = Omega sin(pi s/(2L)) e_axis, s = (X - c).e_axis.
    Vector<3> velocity(const Vector<3>& X) const;

private:
    double Omega_, length_;
    int axis_;
    Vector<3> centre_;
};

}  // namespace mfdyn
