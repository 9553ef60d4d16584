// cylinder: the points whose projection t = (x − p₁)·a onto the axis a = (p₂ − p₁)/L, L = |p₂ − p₁|,
// lies in 0 <= t < L and whose distance from the axis |x − p₁ − t a| is below R.
// 3D: a right circular cylinder, volume πR²L. 2D: the same test is the rectangle of length L and
// width 2R centred on the segment p₁p₂ (a cylinder seen side-on), area 2RL. Half-open in t, as
// box is, so two cylinders placed end to end do not both claim the particles on the shared face.
// Not defined in 1D, where a box already is the segment.
//     shape { type cylinder; point1 (0 0 0); point2 (0 0 0.1); radius 0.02; }
#include "geometry/Cylinder.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace mfdyn {

Cylinder::Cylinder(const Dictionary& dict, int dimension)
    : Shape(dict, dimension),
      point1_(readPoint(dict, "point1")),
      point2_(readPoint(dict, "point2")),
      radius_(readLength(dict, "radius")) {
    if (dimension < 2) throw dict.error("type", "a cylinder needs a 2D or 3D case; use a box in 1D");
    for (int d = 0; d < 3; ++d) length_ += (point2_[d] - point1_[d]) * (point2_[d] - point1_[d]);
    length_ = std::sqrt(length_);
    if (!(length_ > 0)) throw dict.error("point2", "point1 and point2 coincide: the cylinder has no axis");
    for (int d = 0; d < 3; ++d) axis_[d] = (point2_[d] - point1_[d]) / length_;
    checkBounds(dict, "radius");
}

bool Cylinder::inside(const double* x) const {
    double t = 0;
    for (int d = 0; d < dimension(); ++d) t += (x[d] - point1_[d]) * axis_[d];
    if (t < 0 || t >= length_) return false;
    double r2 = 0;
    for (int d = 0; d < dimension(); ++d) {
        const double e = x[d] - point1_[d] - t * axis_[d];
        r2 += e * e;
    }
    return r2 < radius_ * radius_;
}

// The end discs' extent in direction d is R·sqrt(1 − a_d²) (R in 2D, the end being a segment
// perpendicular to the axis, whose half-extent is R·|a_other| = R·sqrt(1 − a_d²) as well).
BoundingBox Cylinder::bounds() const {
    BoundingBox b;
    for (int d = 0; d < dimension(); ++d) {
        const double half = radius_ * std::sqrt(std::max(0.0, 1 - axis_[d] * axis_[d]));
        b.min[d] = std::min(point1_[d], point2_[d]) - half;
        b.max[d] = std::max(point1_[d], point2_[d]) + half;
    }
    return b;
}

std::optional<double> Cylinder::volume() const {
    if (dimension() == 2) return 2 * radius_ * length_;
    return std::numbers::pi * radius_ * radius_ * length_;
}

MFDYN_REGISTER(Shape, Cylinder, "cylinder",
               "circular cylinder from point1 to point2 (3D); rectangle of width 2 radius (2D)");

}  // namespace mfdyn
