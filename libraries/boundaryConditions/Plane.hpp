#pragma once
// A plane read from a boundary condition's dictionary, `point (x y z); normal (nx ny nz);`, with
// the normal pointing into the material (the side the particles are on). The signed distance
// d(x) = (x - point)·n is positive inside, zero on the plane, negative behind it. In 1D the
// plane is a point and the normal is +1 or -1.
//
// `tolerance` [m] is how far inside a particle still counts as on the plane (a lattice that
// includes the boundary face puts particles at d = 0 up to round-off); by default 1e-9 times the
// extent of the particle set.
#include "core/KeywordSchema.hpp"
#include "core/Tensor.hpp"

#include <vector>

namespace mfdyn {

// point, normal and tolerance, appended to the schemas of the plane conditions.
KeywordSchema planeKeywords();

template <int Dim>
class Plane {
public:
    // From values read through a schema that includes planeKeywords(); `positions` give the
    // default tolerance.
    Plane(const KeywordValues& values, const std::vector<Vector<Dim>>& positions);
    Plane(const Vector<Dim>& point, const Vector<Dim>& normal, double tolerance = 0.0);

    const Vector<Dim>& point() const { return point_; }
    const Vector<Dim>& normal() const { return normal_; }
    double tolerance() const { return tolerance_; }
    bool onOrBehind(const Vector<Dim>& x) const { return signedDistance(x) <= tolerance_; }
    double signedDistance(const Vector<Dim>& x) const { return (x - point_).dot(normal_); }
    // The foot of the perpendicular from x.
    Vector<Dim> project(const Vector<Dim>& x) const { return x - signedDistance(x) * normal_; }
    // The mirror image of x.
    Vector<Dim> mirror(const Vector<Dim>& x) const { return x - 2.0 * signedDistance(x) * normal_; }

private:
    Vector<Dim> point_;
    Vector<Dim> normal_;
    double tolerance_ = 0.0;
};

extern template class Plane<1>;
extern template class Plane<2>;
extern template class Plane<3>;

}  // namespace mfdyn
