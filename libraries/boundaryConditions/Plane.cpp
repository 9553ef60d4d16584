#include "boundaryConditions/Plane.hpp"

#include <cmath>

namespace mfdyn {

template <int Dim>
Plane<Dim>::Plane(const Dictionary& dict, const std::vector<Vector<Dim>>& positions)
    : point_(dict.get<Vector<Dim>>("point")), normal_(dict.get<Vector<Dim>>("normal")) {
    const double length = normal_.norm();
    if (!(length > 0.0) || !std::isfinite(length))
        throw dict.error("normal", "the normal must be a non-zero vector (it is normalised)");
    normal_ /= length;
    if (auto tolerance = dict.getOptional<double>("tolerance")) {
        if (!(*tolerance >= 0.0)) throw dict.error("tolerance", "expected a distance >= 0 [m]");
        tolerance_ = *tolerance;
    } else if (!positions.empty()) {
        Vector<Dim> lo = positions.front(), hi = positions.front();
        for (const auto& x : positions) {
            lo = lo.cwiseMin(x);
            hi = hi.cwiseMax(x);
        }
        tolerance_ = 1e-9 * (hi - lo).norm();
    }
}

template <int Dim>
Plane<Dim>::Plane(const Vector<Dim>& point, const Vector<Dim>& normal, double tolerance)
    : point_(point), normal_(normal.normalized()), tolerance_(tolerance) {}

template class Plane<1>;
template class Plane<2>;
template class Plane<3>;

}  // namespace mfdyn
