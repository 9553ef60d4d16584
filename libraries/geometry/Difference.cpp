// difference: x is inside when it is inside the first listed shape and in none of the others,
// A \ (B ∪ C ∪ ...): a plate with a hole is a box less a sphere (a disc in 2D). Bounded by the
// first shape. No closed-form volume: the removed shapes may overlap each other or stick out.
#include "geometry/Difference.hpp"

#include <algorithm>

namespace mfdyn {

bool Difference::inside(const double* x) const {
    if (!shapes().front()->inside(x)) return false;
    return std::none_of(shapes().begin() + 1, shapes().end(), [x](const auto& s) { return s->inside(x); });
}

BoundingBox Difference::bounds() const {
    return shapes().front()->bounds();
}

MFDYN_REGISTER(Shape, Difference, "difference",
               "points inside the first listed shape and none of the others");

}  // namespace mfdyn
