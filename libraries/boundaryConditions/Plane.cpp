#include "boundaryConditions/Plane.hpp"

#include "core/Parallel.hpp"

#include <cmath>

namespace mfdyn {

KeywordSchema planeKeywords() {
    return KeywordSchema("boundaryCondition", "plane")
        .vector("point", "m", "a point of the plane")
        .vector("normal", "-", "the plane's normal, pointing into the material (normalised when read)")
        .example("(1 0 0)")
        .scalar("tolerance", "m",
                "how far inside a particle still counts as on the plane (default 1e-9 "
                "times the extent of the particle set)")
        .atLeast(0)
        .optional();
}

template <int Dim>
Plane<Dim>::Plane(const KeywordValues& values, const std::vector<Vector<Dim>>& positions)
    : point_(keywordVector<Dim>(values, "point")), normal_(keywordVector<Dim>(values, "normal")) {
    const double length = normal_.norm();
    if (!(length > 0.0))
        throw values.error("normal", "the normal must be a non-zero vector (it is normalised)");
    normal_ /= length;
    if (auto tolerance = values.optionalScalar("tolerance")) {
        tolerance_ = *tolerance;
    } else {
        // The box of the whole body: every rank's part of it (global reductions: the same
        // tolerance on every rank; none with no particle anywhere).
        Vector<Dim> lo, hi;
        for (int d = 0; d < Dim; ++d) {
            lo[d] = GlobalReduce::min(positions.size(), [&](std::size_t i) { return positions[i][d]; });
            hi[d] = GlobalReduce::max(positions.size(), [&](std::size_t i) { return positions[i][d]; });
        }
        if (lo.allFinite() && hi.allFinite()) tolerance_ = 1e-9 * (hi - lo).norm();
    }
}

template <int Dim>
Plane<Dim>::Plane(const Vector<Dim>& point, const Vector<Dim>& normal, double tolerance)
    : point_(point), normal_(normal.normalized()), tolerance_(tolerance) {}

template class Plane<1>;
template class Plane<2>;
template class Plane<3>;

}  // namespace mfdyn
