#pragma once
// What the upwinded parts of fpmSolid (fpm/EulerPart, fpm/ShearPart) share about their fits at the
// shifted points x_i -+ l d (doc/methods/fpm.md §2, "Upwinding in a direction"): the fit's options
// there, and the rows of those points.
#include "meshfreeOperators/LeastSquaresOperators.hpp"
#include "particles/NeighbourList.hpp"

#include <algorithm>
#include <cstddef>
#include <vector>

namespace mfdyn::fpm {

// The central fit's options as the shifted fits take them: the value form (evaluated away from the
// particle), no fallback, a failure flagged (the part then shortens the shift or goes central), and
// at least minReciprocalCondition (a point beyond a free surface sees one plane of particles).
template <int Dim>
typename LeastSquaresOperators<Dim>::Options shiftedFitOptions(typename LeastSquaresOperators<Dim>::Options o,
                                                               double minReciprocalCondition) {
    o.form = LeastSquaresOperators<Dim>::Form::value;
    o.fallback = LeastSquaresOperators<Dim>::Fallback::none;
    o.onFailure = LeastSquaresOperators<Dim>::OnFailure::flag;
    o.minReciprocalCondition = std::max(o.minReciprocalCondition, minReciprocalCondition);
    return o;
}

// The rows of copies x m shifted points, point q m + j taking the row of particle active[j] (its
// neighbours within (1 + maxShift) h hold those of each of its shifted points within h).
inline NeighbourList shiftedRows(const std::vector<std::size_t>& active, const NeighbourList& rows,
                                 std::size_t copies) {
    const std::size_t m = active.size();
    std::vector<std::size_t> offsets(copies * m + 1, 0);
    std::vector<NeighbourList::Index> indices;
    for (std::size_t q = 0; q < copies; ++q)
        for (std::size_t j = 0; j < m; ++j) {
            const std::size_t i = active[j];
            indices.insert(indices.end(), rows.indices().begin() + std::ptrdiff_t(rows.offsets()[i]),
                           rows.indices().begin() + std::ptrdiff_t(rows.offsets()[i + 1]));
            offsets[q * m + j + 1] = indices.size();
        }
    return NeighbourList(std::move(offsets), std::move(indices));
}

}  // namespace mfdyn::fpm
