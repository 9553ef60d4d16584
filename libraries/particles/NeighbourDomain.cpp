#include "particles/NeighbourDomain.hpp"

#include "core/Error.hpp"
#include "core/KeywordSchema.hpp"  // formatKeywordNumber: 1e-320 shows as 9.99989e-321, not 0.000000

#include <string>

namespace mfdyn {

template <int Dim>
NeighbourDomain<Dim>::NeighbourDomain(const Vector<Dim>& lo, const Vector<Dim>& hi,
                                      const std::array<bool, Dim>& periodic)
    : bounded_(true), lo_(lo), hi_(hi), periodic_(periodic) {
    for (int k = 0; k < Dim; ++k) {
        if (!(std::isfinite(lo[k]) && std::isfinite(hi[k]) && hi[k] > lo[k]))
            throw Error("neighbour search domain: direction " + std::to_string(k) +
                        " needs lo < hi, found [" + formatKeywordNumber(lo[k]) + ", " +
                        formatKeywordNumber(hi[k]) + "]");
        period_[k] = periodic[k] ? hi[k] - lo[k] : 0.0;
        anyPeriodic_ = anyPeriodic_ || periodic[k];
    }
}

template <int Dim>
Vector<Dim> NeighbourDomain<Dim>::wrap(const Vector<Dim>& x) const {
    Vector<Dim> w = x;
    for (int k = 0; k < Dim; ++k) {
        if (!periodic_[k]) continue;
        w[k] -= period_[k] * std::floor((x[k] - lo_[k]) / period_[k]);
        // Rounding can land a point a hair outside [lo, hi) (just below lo maps onto hi).
        if (w[k] >= hi_[k] || w[k] < lo_[k]) w[k] = lo_[k];
    }
    return w;
}

template class NeighbourDomain<1>;
template class NeighbourDomain<2>;
template class NeighbourDomain<3>;

}  // namespace mfdyn
