#include "particles/CellBins.hpp"

#include "core/Parallel.hpp"

#include <limits>
#include <string>

namespace mfdyn {

template <int Dim>
CellBins<Dim>::CellBins(NeighbourDomain<Dim> domain, double maxCellsPerParticle)
    : domain_(std::move(domain)), maxCellsPerParticle_(maxCellsPerParticle) {
    if (!(maxCellsPerParticle_ > 0)) throw Error("CellBins: maxCellsPerParticle must be positive");
}

template <int Dim>
void CellBins<Dim>::bin(const std::vector<Vector<Dim>>& positions, double cellWidth) {
    const std::size_t n = positions.size();
    if (n >= std::size_t(std::numeric_limits<Index>::max()))
        throw Error("cell binning: " + std::to_string(n) + " particles exceed the 32-bit index range");
    if (!(std::isfinite(cellWidth) && cellWidth >= 0))
        throw Error("cell binning: the cell width must be finite and non-negative, found " +
                    std::to_string(cellWidth));
    // Rank-local: these are this process's particles, and the throw below is taken alone.
    const std::size_t badPositions = LocalReduce::sum<std::size_t>(
        n, [&](std::size_t i) { return std::size_t(!positions[i].allFinite()); });
    if (badPositions > 0)
        throw Error("cell binning: " + std::to_string(badPositions) + " particle positions are not finite");

    order_.resize(n);
    sortedPosition_.resize(n);
    if (n == 0) {
        cellStart_.assign(1, 0);
        cells_.fill(1);
        width_.fill(1.0);
        origin_.setZero();
        return;
    }

    // The box: given, or the particles' extent (of this rank's particles: the grid is local).
    Vector<Dim> extent;
    for (int d = 0; d < Dim; ++d) {
        if (domain_.bounded()) {
            origin_[d] = domain_.lo()[d];
            extent[d] = domain_.hi()[d] - domain_.lo()[d];
        } else {
            origin_[d] = LocalReduce::min(n, [&](std::size_t i) { return positions[i][d]; });
            extent[d] = LocalReduce::max(n, [&](std::size_t i) { return positions[i][d]; }) - origin_[d];
        }
    }

    // Cell width: as asked, widened until the grid has at most maxCellsPerParticle cells per
    // particle. Counted in double so that a huge box cannot overflow before it is coarsened.
    double width = cellWidth;
    if (!(width > 0)) width = std::max(extent.maxCoeff(), 1.0);
    const double cellLimit = std::min(std::max(1.0, maxCellsPerParticle_ * double(n)),
                                      double(std::numeric_limits<Index>::max() - 2));
    std::array<double, Dim> cellsAlong{};
    for (;;) {
        double total = 1;
        for (int d = 0; d < Dim; ++d) {
            cellsAlong[d] = domain_.periodic(d) ? std::max(1.0, std::floor(extent[d] / width))
                                                : std::max(1.0, std::ceil(extent[d] / width));
            total *= cellsAlong[d];
        }
        if (total <= cellLimit) break;
        width *= std::max(1.01, std::pow(total / cellLimit, 1.0 / Dim));
    }
    std::int64_t cellTotal = 1;
    for (int d = 0; d < Dim; ++d) {
        cells_[d] = std::int64_t(cellsAlong[d]);
        // A periodic direction holds a whole number of cells, each at least `width` wide.
        width_[d] = domain_.periodic(d) ? extent[d] / double(cells_[d]) : width;
        cellTotal *= cells_[d];
    }

    // Counting sort by cell; stable, so a cell lists its particles by increasing index.
    std::vector<Index> cell(n);
    parallelFor(n, [&](std::size_t i) { cell[i] = Index(cellOf(positions[i])); });
    cellStart_.assign(std::size_t(cellTotal) + 1, 0);
    for (std::size_t i = 0; i < n; ++i) ++cellStart_[cell[i] + 1];
    for (std::size_t c = 0; c < std::size_t(cellTotal); ++c) cellStart_[c + 1] += cellStart_[c];
    {
        std::vector<Index> next(cellStart_.begin(), cellStart_.end() - 1);
        for (std::size_t i = 0; i < n; ++i) order_[next[cell[i]]++] = Index(i);
    }
    parallelFor(n, [&](std::size_t k) { sortedPosition_[k] = positions[order_[k]]; });
}

template <int Dim>
std::array<std::int64_t, Dim> CellBins<Dim>::cellCoordinates(const Vector<Dim>& position) const {
    const Vector<Dim> x = domain_.anyPeriodic() ? domain_.wrap(position) : position;
    std::array<std::int64_t, Dim> c{};
    for (int d = 0; d < Dim; ++d) {
        const double t = (x[d] - origin_[d]) / width_[d];
        c[d] = std::int64_t(std::clamp(t, 0.0, double(cells_[d] - 1)));
    }
    return c;
}

template <int Dim>
std::size_t CellBins<Dim>::cellOf(const Vector<Dim>& x) const {
    const std::array<std::int64_t, Dim> c = cellCoordinates(x);
    std::int64_t k = 0;
    for (int d = Dim - 1; d >= 0; --d) k = k * cells_[d] + c[d];
    return std::size_t(k);
}

template <int Dim>
std::vector<typename CellBins<Dim>::Index> CellBins<Dim>::within(const Vector<Dim>& x, double r) const {
    std::vector<Index> out;
    forEachWithin(x, r, [&](Index j, const Vector<Dim>&) { out.push_back(j); });
    return out;
}

template class CellBins<1>;
template class CellBins<2>;
template class CellBins<3>;

}  // namespace mfdyn
