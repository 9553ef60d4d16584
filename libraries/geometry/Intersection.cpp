// intersection: x is inside when it is inside every listed shape, A ∩ B ∩ .... Its bounds are the
// overlap of the shapes' bounds (possibly empty, which leaves the region without particles and is
// reported as such by particleGen). No closed-form volume in general.
#include "geometry/Intersection.hpp"

#include <algorithm>

namespace mfdyn {

bool Intersection::inside(const double* x) const {
    return std::ranges::all_of(shapes(), [x](const auto& s) { return s->inside(x); });
}

BoundingBox Intersection::bounds() const {
    BoundingBox b = shapes().front()->bounds();
    for (const auto& s : shapes()) {
        const BoundingBox o = s->bounds();
        for (int d = 0; d < dimension(); ++d) {
            b.min[d] = std::max(b.min[d], o.min[d]);
            b.max[d] = std::min(b.max[d], o.max[d]);
        }
    }
    for (int d = 0; d < dimension(); ++d) b.max[d] = std::max(b.max[d], b.min[d]);
    return b;
}

MFDYN_REGISTER(Shape, Intersection, "intersection", "points inside all of the listed shapes");

}  // namespace mfdyn
