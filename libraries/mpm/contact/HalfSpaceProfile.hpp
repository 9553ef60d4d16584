#pragma once
// Where a body's surface lies near a node, read from the body's nodal centre of mass: the 1D
// profile of a shape function over a half-space (the multiField contact's surface-gap check,
// MultiFieldContact.cpp; the equations are in HalfSpaceProfile.cpp).
#include "grid/shapeFunctions/ShapeFunction.hpp"

#include <vector>

namespace mfdyn {

class HalfSpaceProfile {
public:
    // Tabulates N(r) of one axis of `shape` (an interior node, r in cells) and the centre of the
    // half-space r < s weighted by N, for s across the support.
    template <int Dim>
    explicit HalfSpaceProfile(const ShapeFunction<Dim>& shape);
    double supportHalfWidth() const { return reach_; }
    // c(s) = int_{-R}^{s} r N dr / int_{-R}^{s} N dr (cells): the nodal centre of mass, relative to
    // the node, of a body filling r < s; increasing from -R to 0 as s runs from -R to R.
    double centre(double s) const;
    // The inverse: the surface s of a body r < s whose centre is c, clamped to [-R, R].
    double surface(double c) const;

private:
    double reach_ = 0;
    double step_ = 0;
    std::vector<double> centre_;  // c at s_k = -R + k step
};

}  // namespace mfdyn
