// sphere: the open ball |x − c| < R in the case's dimension: a segment of length 2R in 1D, a disc
// of area πR² in 2D, a ball of volume (4/3)πR³ in 3D (the d-ball volumes, e.g. NIST DLMF 5.19.4
// with d = 1, 2, 3). Strict inequality so that a lattice point exactly on the surface is not
// counted twice by touching spheres.
//     shape { type sphere; centre (0 0 0); radius 0.01; }
#include "geometry/Sphere.hpp"

#include <cmath>
#include <numbers>

namespace mfdyn {

Sphere::Sphere(const Dictionary& dict, int dimension)
    : Shape(dict, dimension), centre_(readPoint(dict, "centre")), radius_(readLength(dict, "radius")) {
    checkBounds(dict, "radius");
}

bool Sphere::inside(const double* x) const {
    double r2 = 0;
    for (int d = 0; d < dimension(); ++d) r2 += (x[d] - centre_[d]) * (x[d] - centre_[d]);
    return r2 < radius_ * radius_;
}

BoundingBox Sphere::bounds() const {
    BoundingBox b;
    for (int d = 0; d < dimension(); ++d) {
        b.min[d] = centre_[d] - radius_;
        b.max[d] = centre_[d] + radius_;
    }
    return b;
}

std::optional<double> Sphere::volume() const {
    switch (dimension()) {
        case 1:
            return 2 * radius_;
        case 2:
            return std::numbers::pi * radius_ * radius_;
        default:
            return 4.0 / 3.0 * std::numbers::pi * radius_ * radius_ * radius_;
    }
}

MFDYN_REGISTER(Shape, Sphere, "sphere", "segment, disc or ball of the given centre and radius");

}  // namespace mfdyn
