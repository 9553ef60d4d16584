// union: x is inside when it is inside any of the listed shapes, A ∪ B ∪ .... Its bounds are the
// box around all the shapes' bounds. No closed-form volume: the shapes may overlap.
#include "geometry/Union.hpp"

#include <algorithm>

namespace mfdyn {

bool Union::inside(const double* x) const {
    return std::ranges::any_of(shapes(), [x](const auto& s) { return s->inside(x); });
}

BoundingBox Union::bounds() const {
    BoundingBox b = shapes().front()->bounds();
    for (const auto& s : shapes()) {
        const BoundingBox o = s->bounds();
        for (int d = 0; d < dimension(); ++d) {
            b.min[d] = std::min(b.min[d], o.min[d]);
            b.max[d] = std::max(b.max[d], o.max[d]);
        }
    }
    return b;
}

MFDYN_REGISTER(Shape, Union, "union", "points inside any of the listed shapes");

}  // namespace mfdyn
