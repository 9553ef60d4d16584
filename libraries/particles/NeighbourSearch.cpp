#include "particles/NeighbourSearch.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace mfdyn {

namespace {

// Rows are produced in blocks of fixed size, each into its own buffer: the blocks, not the
// threads, define where a row's data goes, so the list is the same for any thread count.
constexpr std::size_t rowBlock = 1024;

// A query box is widened by this many cell widths so that rounding in the cell coordinates can
// never drop a cell holding a neighbour; an extra cell only costs distance checks.
constexpr double cellPadding = 1e-6;

}  // namespace

template <int Dim>
NeighbourSearch<Dim>::NeighbourSearch(NeighbourDomain<Dim> domain, NeighbourSearchOptions options)
    : domain_(std::move(domain)), options_(options) {
    if (options_.cellsPerRadius < 1)
        throw Error("NeighbourSearch: cellsPerRadius must be at least 1, found " +
                    std::to_string(options_.cellsPerRadius));
    if (!(options_.maxCellsPerParticle > 0))
        throw Error("NeighbourSearch: maxCellsPerParticle must be positive");
}

template <int Dim>
void NeighbourSearch<Dim>::bin(const std::vector<Vector<Dim>>& positions, const std::vector<double>& supportRadius) {
    if (supportRadius.size() != positions.size())
        throw Error("NeighbourSearch: " + std::to_string(supportRadius.size()) + " support radii for " +
                    std::to_string(positions.size()) + " particles");
    binSorted(positions, supportRadius.data(), false);
}

template <int Dim>
void NeighbourSearch<Dim>::bin(const std::vector<Vector<Dim>>& positions, double supportRadius) {
    binSorted(positions, &supportRadius, true);
}

template <int Dim>
void NeighbourSearch<Dim>::binSorted(const std::vector<Vector<Dim>>& positions, const double* radius,
                                     bool constantRadius) {
    const std::size_t n = positions.size();
    if (n >= std::size_t(std::numeric_limits<Index>::max()))
        throw Error("NeighbourSearch: " + std::to_string(n) + " particles exceed the 32-bit index range");
    constantRadius_ = constantRadius;
    auto r = [&](std::size_t i) { return constantRadius ? radius[0] : radius[i]; };

    const std::size_t badRadii =
        constantRadius ? std::size_t(!(std::isfinite(radius[0]) && radius[0] >= 0))
                       : Reduce::sum<std::size_t>(n, [&](std::size_t i) { return !(std::isfinite(r(i)) && r(i) >= 0); });
    if (badRadii > 0) throw Error("NeighbourSearch: support radii must be finite and non-negative");
    const std::size_t badPositions =
        Reduce::sum<std::size_t>(n, [&](std::size_t i) { return std::size_t(!positions[i].allFinite()); });
    if (badPositions > 0)
        throw Error("NeighbourSearch: " + std::to_string(badPositions) + " particle positions are not finite");

    order_.resize(n);
    sortedPosition_.resize(n);
    sortedRadius2_.resize(n);
    if (n == 0) {
        maxRadius_ = 0;
        cellStart_.assign(1, 0);
        cells_.fill(1);
        return;
    }
    maxRadius_ = constantRadius ? radius[0] : Reduce::max(n, r);

    // The box: given, or the particles' extent.
    Vector<Dim> extent;
    for (int d = 0; d < Dim; ++d) {
        if (domain_.bounded()) {
            origin_[d] = domain_.lo()[d];
            extent[d] = domain_.hi()[d] - domain_.lo()[d];
        } else {
            origin_[d] = Reduce::min(n, [&](std::size_t i) { return positions[i][d]; });
            extent[d] = Reduce::max(n, [&](std::size_t i) { return positions[i][d]; }) - origin_[d];
        }
        if (domain_.periodic(d) && maxRadius_ > 0.5 * domain_.period(d))
            throw Error("NeighbourSearch: support radius " + std::to_string(maxRadius_) +
                        " exceeds half the period " + std::to_string(domain_.period(d)) + " of direction " +
                        std::to_string(d) + "; the minimum image would not be the only neighbour");
    }

    // Cell width: maxRadius / cellsPerRadius, widened until the grid has at most
    // maxCellsPerParticle cells per particle. Counted in double so that a huge box cannot
    // overflow before it is coarsened.
    double width = maxRadius_ / options_.cellsPerRadius;
    if (!(width > 0)) width = std::max(extent.maxCoeff(), 1.0);
    const double cellLimit =
        std::min(std::max(1.0, options_.maxCellsPerParticle * double(n)), double(std::numeric_limits<Index>::max() - 2));
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
    std::vector<Index> cellOf(n);
    parallelFor(n, [&](std::size_t i) {
        const Vector<Dim> x = domain_.anyPeriodic() ? domain_.wrap(positions[i]) : positions[i];
        std::int64_t c = 0;
        for (int d = Dim - 1; d >= 0; --d) {
            const double t = std::floor((x[d] - origin_[d]) / width_[d]);
            c = c * cells_[d] + std::int64_t(std::clamp(t, 0.0, double(cells_[d] - 1)));
        }
        cellOf[i] = Index(c);
    });
    cellStart_.assign(std::size_t(cellTotal) + 1, 0);
    for (std::size_t i = 0; i < n; ++i) ++cellStart_[cellOf[i] + 1];
    for (std::size_t c = 0; c < std::size_t(cellTotal); ++c) cellStart_[c + 1] += cellStart_[c];
    {
        std::vector<Index> next(cellStart_.begin(), cellStart_.end() - 1);
        for (std::size_t i = 0; i < n; ++i) order_[next[cellOf[i]]++] = Index(i);
    }
    parallelFor(n, [&](std::size_t k) {
        sortedPosition_[k] = positions[order_[k]];
        const double rk = r(order_[k]);
        sortedRadius2_[k] = rk * rk;
    });
}

template <int Dim>
template <PairCriterion C, bool Periodic>
void NeighbourSearch<Dim>::gatherRow(std::size_t k, std::vector<Index>& out) const {
    const Vector<Dim>& xi = sortedPosition_[k];
    const double ri2 = sortedRadius2_[k];
    // Any j with d < max(r_i, r_j) is within maxRadius; the other criteria stay within r_i.
    const double reach = C == PairCriterion::either ? maxRadius_ : std::sqrt(ri2);
    const bool includeSelf = options_.includeSelf;

    // Cell range of the query box [x - reach, x + reach] in each direction. In a periodic
    // direction the range is left unwrapped (it may start below 0 or end past the last cell) and
    // folded when visited; one that would cover a cell twice is cut to the whole period.
    const Vector<Dim> x = Periodic ? domain_.wrap(xi) : xi;
    std::array<std::int64_t, Dim> first{}, last{};
    for (int d = 0; d < Dim; ++d) {
        const double t = (x[d] - origin_[d]) / width_[d];
        const double s = reach / width_[d] + cellPadding;
        const double top = double(cells_[d] - 1);
        if (Periodic && domain_.periodic(d)) {
            first[d] = std::int64_t(std::floor(std::clamp(t - s, -top - 1, 2 * top + 1)));
            last[d] = std::int64_t(std::floor(std::clamp(t + s, -top - 1, 2 * top + 1)));
            if (last[d] - first[d] + 1 >= cells_[d]) {
                first[d] = 0;
                last[d] = cells_[d] - 1;
            }
        } else {
            first[d] = std::int64_t(std::clamp(std::floor(t - s), 0.0, top));
            last[d] = std::int64_t(std::clamp(std::floor(t + s), 0.0, top));
        }
    }
    auto fold = [](std::int64_t c, std::int64_t n) { return c < 0 ? c + n : (c >= n ? c - n : c); };

    auto visit = [&](std::size_t begin, std::size_t end) {
        for (std::size_t l = begin; l < end; ++l) {
            Vector<Dim> dx;
            if constexpr (Periodic)
                dx = domain_.separation(xi, sortedPosition_[l]);
            else
                dx = xi - sortedPosition_[l];
            const double d2 = dx.squaredNorm();
            bool in;
            if constexpr (C == PairCriterion::either)
                in = d2 < std::max(ri2, sortedRadius2_[l]);
            else if constexpr (C == PairCriterion::both)
                in = d2 < std::min(ri2, sortedRadius2_[l]);
            else
                in = d2 < ri2;
            if (l == k) in = includeSelf;
            if (in) out.push_back(order_[l]);
        }
    };
    // Cells along x are contiguous in the cell order, so a row of cells is one run of particles
    // (two where a periodic range wraps).
    auto visitCellRow = [&](std::int64_t base) {
        const std::int64_t n = cells_[0];
        if (first[0] >= 0 && last[0] < n) {
            visit(cellStart_[base + first[0]], cellStart_[base + last[0] + 1]);
        } else {
            visit(cellStart_[base + fold(first[0], n)], cellStart_[base + n]);
            visit(cellStart_[base], cellStart_[base + fold(last[0], n) + 1]);
        }
    };
    if constexpr (Dim == 1) {
        visitCellRow(0);
    } else if constexpr (Dim == 2) {
        for (std::int64_t cy = first[1]; cy <= last[1]; ++cy) visitCellRow(fold(cy, cells_[1]) * cells_[0]);
    } else {
        for (std::int64_t cz = first[2]; cz <= last[2]; ++cz)
            for (std::int64_t cy = first[1]; cy <= last[1]; ++cy)
                visitCellRow((fold(cz, cells_[2]) * cells_[1] + fold(cy, cells_[1])) * cells_[0]);
    }
}

template <int Dim>
template <PairCriterion C, bool Periodic>
void NeighbourSearch<Dim>::fillBlocks() {
    const std::size_t n = order_.size();
    const std::int64_t blocks = std::int64_t((n + rowBlock - 1) / rowBlock);
    blockIndices_.resize(std::size_t(blocks));
    rowLength_.resize(n);
    // Dynamic schedule: clustered clouds give blocks of very different cost, and where a block
    // runs does not change what it writes.
#pragma omp parallel for schedule(dynamic)
    for (std::int64_t b = 0; b < blocks; ++b) {
        std::vector<Index>& buffer = blockIndices_[std::size_t(b)];
        buffer.clear();
        const std::size_t end = std::min(n, std::size_t(b + 1) * rowBlock);
        for (std::size_t k = std::size_t(b) * rowBlock; k < end; ++k) {
            const std::size_t start = buffer.size();
            gatherRow<C, Periodic>(k, buffer);
            if (options_.sortRows && !std::is_sorted(buffer.begin() + start, buffer.end()))
                std::sort(buffer.begin() + start, buffer.end());
            rowLength_[k] = Index(buffer.size() - start);
        }
    }
}

template <int Dim>
NeighbourList NeighbourSearch<Dim>::list() {
    const std::size_t n = order_.size();
    // With one radius for all the three criteria coincide; gather skips the look-up of r_j.
    const PairCriterion criterion = constantRadius_ ? PairCriterion::gather : options_.criterion;
    const bool periodic = domain_.anyPeriodic();
    switch (criterion) {
        case PairCriterion::either:
            periodic ? fillBlocks<PairCriterion::either, true>() : fillBlocks<PairCriterion::either, false>();
            break;
        case PairCriterion::both:
            periodic ? fillBlocks<PairCriterion::both, true>() : fillBlocks<PairCriterion::both, false>();
            break;
        case PairCriterion::gather:
            periodic ? fillBlocks<PairCriterion::gather, true>() : fillBlocks<PairCriterion::gather, false>();
            break;
    }

    std::vector<std::size_t> offsets(n + 1, 0);
    for (std::size_t k = 0; k < n; ++k) offsets[std::size_t(order_[k]) + 1] = rowLength_[k];
    for (std::size_t i = 0; i < n; ++i) offsets[i + 1] += offsets[i];
    std::vector<Index> indices(offsets[n]);
    const std::int64_t blocks = std::int64_t(blockIndices_.size());
#pragma omp parallel for schedule(static)
    for (std::int64_t b = 0; b < blocks; ++b) {
        const std::vector<Index>& buffer = blockIndices_[std::size_t(b)];
        std::size_t position = 0;
        const std::size_t end = std::min(n, std::size_t(b + 1) * rowBlock);
        for (std::size_t k = std::size_t(b) * rowBlock; k < end; ++k) {
            std::copy_n(buffer.begin() + position, rowLength_[k], indices.begin() + offsets[order_[k]]);
            position += rowLength_[k];
        }
    }
    return NeighbourList(std::move(offsets), std::move(indices));
}

template class NeighbourSearch<1>;
template class NeighbourSearch<2>;
template class NeighbourSearch<3>;

}  // namespace mfdyn
