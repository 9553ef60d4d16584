#include "particles/NeighbourSearch.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <type_traits>

namespace mfdyn {

namespace {

// Rows are produced in blocks of fixed size, each into its own buffer: the blocks, not the
// threads, define where a row's data goes, so the list is the same for any thread count.
constexpr std::size_t rowBlock = 1024;

static_assert(std::is_same_v<NeighbourList::Index, CellBins<3>::Index>);

}  // namespace

template <int Dim>
NeighbourSearch<Dim>::NeighbourSearch(NeighbourDomain<Dim> domain, NeighbourSearchOptions options)
    : domain_(std::move(domain)), options_(options), bins_(domain_, options.maxCellsPerParticle) {
    if (options_.cellsPerRadius < 1)
        throw Error("NeighbourSearch: cellsPerRadius must be at least 1, found " +
                    std::to_string(options_.cellsPerRadius));
    if (!(options_.maxCellsPerParticle > 0))
        throw Error("NeighbourSearch: maxCellsPerParticle must be positive");
}

template <int Dim>
void NeighbourSearch<Dim>::bin(const std::vector<Vector<Dim>>& positions,
                               const std::vector<double>& supportRadius) {
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

    // Local reductions throughout: these are this rank's particles, the checks throw on their
    // own, and the box is the rank's own (a global reduction here would be collective behind
    // the early returns and throws of a rank-local build).
    const std::size_t badRadii = constantRadius ? std::size_t(!(std::isfinite(radius[0]) && radius[0] >= 0))
                                                : LocalReduce::sum<std::size_t>(n, [&](std::size_t i) {
                                                      return !(std::isfinite(r(i)) && r(i) >= 0);
                                                  });
    if (badRadii > 0) throw Error("NeighbourSearch: support radii must be finite and non-negative");
    const std::size_t badPositions = LocalReduce::sum<std::size_t>(
        n, [&](std::size_t i) { return std::size_t(!positions[i].allFinite()); });
    if (badPositions > 0)
        throw Error("NeighbourSearch: " + std::to_string(badPositions) +
                    " particle positions are not finite");

    maxRadius_ = n == 0 ? 0.0 : constantRadius ? radius[0] : LocalReduce::max(n, r);
    for (int d = 0; d < Dim; ++d)
        if (domain_.periodic(d) && maxRadius_ > 0.5 * domain_.period(d))
            throw Error("NeighbourSearch: support radius " + std::to_string(maxRadius_) +
                        " exceeds half the period " + std::to_string(domain_.period(d)) + " of direction " +
                        std::to_string(d) + "; the minimum image would not be the only neighbour");

    // Cells maxRadius / cellsPerRadius wide (CellBins widens them past maxCellsPerParticle).
    bins_.bin(positions, maxRadius_ / options_.cellsPerRadius);
    const std::vector<Index>& order = bins_.order();
    sortedRadius2_.resize(n);
    parallelFor(n, [&](std::size_t k) {
        const double rk = r(order[k]);
        sortedRadius2_[k] = rk * rk;
    });
}

template <int Dim>
template <PairCriterion C, bool Periodic>
void NeighbourSearch<Dim>::gatherRow(std::size_t k, std::vector<Index>& out,
                                     std::vector<std::array<Index, 2>>& runs) const {
    const std::vector<Vector<Dim>>& sortedPosition = bins_.sortedPositions();
    const std::vector<Index>& order = bins_.order();
    const Vector<Dim>& xi = sortedPosition[k];
    const double ri2 = sortedRadius2_[k];
    // Any j with d < max(r_i, r_j) is within maxRadius; the other criteria stay within r_i.
    const double reach = C == PairCriterion::either ? maxRadius_ : std::sqrt(ri2);
    const bool includeSelf = options_.includeSelf;
    bins_.template runs<Periodic>(xi, reach, runs);

    // Room for every candidate first, so that the test below can store each one and advance
    // only past those that pass: no branch on the outcome, which is close to a coin toss.
    std::size_t candidates = 0;
    for (const auto& [begin, end] : runs) candidates += end - begin;
    const std::size_t start = out.size();
    out.resize(start + candidates);
    Index* const row = out.data() + start;
    std::size_t found = 0;
    for (const auto& [begin, end] : runs) {
        for (std::size_t l = begin; l < end; ++l) {
            Vector<Dim> dx;
            if constexpr (Periodic)
                dx = domain_.separation(xi, sortedPosition[l]);
            else
                dx = xi - sortedPosition[l];
            const double d2 = dx.squaredNorm();
            bool in;
            if constexpr (C == PairCriterion::either)
                in = d2 < std::max(ri2, sortedRadius2_[l]);
            else if constexpr (C == PairCriterion::both)
                in = d2 < std::min(ri2, sortedRadius2_[l]);
            else
                in = d2 < ri2;
            in = l == k ? includeSelf : in;
            row[found] = order[l];
            found += in;
        }
    }
    out.resize(start + found);
}

template <int Dim>
template <PairCriterion C, bool Periodic>
void NeighbourSearch<Dim>::fillBlocks() {
    const std::size_t n = bins_.size();
    const std::int64_t blocks = std::int64_t((n + rowBlock - 1) / rowBlock);
    blockIndices_.resize(std::size_t(blocks));
    rowLength_.resize(n);
    // Dynamic schedule: clustered clouds give blocks of very different cost, and where a block
    // runs does not change what it writes.
#pragma omp parallel for schedule(dynamic) if (blocks > 1)
    for (std::int64_t b = 0; b < blocks; ++b) {
        std::vector<Index>& buffer = blockIndices_[std::size_t(b)];
        buffer.clear();
        std::vector<std::array<Index, 2>> runs;
        const std::size_t end = std::min(n, std::size_t(b + 1) * rowBlock);
        for (std::size_t k = std::size_t(b) * rowBlock; k < end; ++k) {
            const std::size_t start = buffer.size();
            gatherRow<C, Periodic>(k, buffer, runs);
            if (options_.sortRows && !std::is_sorted(buffer.begin() + start, buffer.end()))
                std::sort(buffer.begin() + start, buffer.end());
            rowLength_[k] = Index(buffer.size() - start);
        }
    }
}

template <int Dim>
NeighbourList NeighbourSearch<Dim>::list() {
    const std::vector<Index>& order = bins_.order();
    const std::size_t n = order.size();
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
    for (std::size_t k = 0; k < n; ++k) offsets[std::size_t(order[k]) + 1] = rowLength_[k];
    for (std::size_t i = 0; i < n; ++i) offsets[i + 1] += offsets[i];
    std::vector<Index> indices(offsets[n]);
    const std::int64_t blocks = std::int64_t(blockIndices_.size());
#pragma omp parallel for schedule(static) if (blocks > 1)
    for (std::int64_t b = 0; b < blocks; ++b) {
        const std::vector<Index>& buffer = blockIndices_[std::size_t(b)];
        std::size_t position = 0;
        const std::size_t end = std::min(n, std::size_t(b + 1) * rowBlock);
        for (std::size_t k = std::size_t(b) * rowBlock; k < end; ++k) {
            std::copy_n(buffer.begin() + position, rowLength_[k], indices.begin() + offsets[order[k]]);
            position += rowLength_[k];
        }
    }
    return NeighbourList(std::move(offsets), std::move(indices));
}

template class NeighbourSearch<1>;
template class NeighbourSearch<2>;
template class NeighbourSearch<3>;

}  // namespace mfdyn
