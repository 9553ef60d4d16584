#include "particles/NeighbourSearch.hpp"

#include <omp.h>
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

// The pair test of a criterion on the squared distance and the two squared support radii: one
// expression for the full and the half stencil, so a pair passes from either side alike.
template <PairCriterion C>
inline bool withinSupport(double d2, double ri2, double rj2) {
    if constexpr (C == PairCriterion::either)
        return d2 < std::max(ri2, rj2);
    else if constexpr (C == PairCriterion::both)
        return d2 < std::min(ri2, rj2);
    else
        return d2 < ri2;
}

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
std::size_t NeighbourSearch<Dim>::gatherRow(std::size_t k, std::vector<Index>& buffer, std::size_t used,
                                            std::vector<std::array<Index, 2>>& runs) const {
    const Vector<Dim>* const sortedPosition = bins_.sortedPositions().data();
    const Index* const order = bins_.order().data();
    const double* const radius2 = sortedRadius2_.data();
    const Vector<Dim> xi = sortedPosition[k];
    const double ri2 = radius2[k];
    // Any j with d < max(r_i, r_j) is within maxRadius; the other criteria stay within r_i.
    const double reach = C == PairCriterion::either ? maxRadius_ : std::sqrt(ri2);
    const bool includeSelf = options_.includeSelf;

    // The runs into scratch that is only grown (a vector cleared and pushed to per query cost a
    // tenth of the build), then their candidates tested in one loop.
    std::size_t runCount = 0, candidates = 0;
    bins_.template visitRuns<Periodic>(xi, reach, [&](Index begin, Index end) {
        if (runCount == runs.size()) runs.resize(std::max<std::size_t>(64, 2 * runCount));
        runs[runCount++] = {begin, end};
        candidates += end - begin;
    });
    // Room for every candidate first, so that the test below can store each one and advance
    // only past those that pass: no branch on the outcome, which is close to a coin toss. The
    // buffer only grows (kept between builds), so no element is initialised twice.
    if (buffer.size() < used + candidates) buffer.resize(std::max(2 * buffer.size(), used + candidates));
    Index* const row = buffer.data() + used;
    std::size_t found = 0;
    for (std::size_t r = 0; r < runCount; ++r) {
        const std::size_t begin = runs[r][0], end = runs[r][1];
        for (std::size_t l = begin; l < end; ++l) {
            Vector<Dim> dx;
            if constexpr (Periodic)
                dx = domain_.separation(xi, sortedPosition[l]);
            else
                dx = xi - sortedPosition[l];
            const double d2 = dx.squaredNorm();
            bool in = withinSupport<C>(d2, ri2, radius2[l]);
            in = l == k ? includeSelf : in;
            row[found] = order[l];
            found += in;
        }
    }
    return used + found;
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
        std::size_t used = 0;
        std::vector<std::array<Index, 2>> runs;
        const std::size_t end = std::min(n, std::size_t(b + 1) * rowBlock);
        for (std::size_t k = std::size_t(b) * rowBlock; k < end; ++k) {
            const std::size_t start = used;
            used = gatherRow<C, Periodic>(k, buffer, used, runs);
            if (options_.sortRows && !std::is_sorted(buffer.begin() + start, buffer.begin() + used))
                std::sort(buffer.begin() + start, buffer.begin() + used);
            rowLength_[k] = Index(used - start);
        }
    }
}

template <int Dim>
template <PairCriterion C>
std::size_t NeighbourSearch<Dim>::gatherForward(std::size_t k, std::vector<Index>& buffer, std::size_t used,
                                                std::vector<std::array<Index, 2>>& runs) const {
    const Vector<Dim>* const sortedPosition = bins_.sortedPositions().data();
    const double* const radius2 = sortedRadius2_.data();
    const Vector<Dim> xi = sortedPosition[k];
    const double ri2 = radius2[k];
    const double reach = C == PairCriterion::either ? maxRadius_ : std::sqrt(ri2);
    // The runs of the full stencil from place k + 1 on: rows of cells below the particle's own
    // row skipped, its own row cut after k.
    std::size_t runCount = 0, candidates = 0;
    bins_.template visitRuns<false>(
        xi, reach,
        [&](Index begin, Index end) {
            begin = std::max(begin, Index(k + 1));
            if (begin >= end) return;
            if (runCount == runs.size()) runs.resize(std::max<std::size_t>(64, 2 * runCount));
            runs[runCount++] = {begin, end};
            candidates += end - begin;
        },
        bins_.rowOf(xi));
    if (buffer.size() < used + candidates) buffer.resize(std::max(2 * buffer.size(), used + candidates));
    Index* const row = buffer.data() + used;
    std::size_t found = 0;
    for (std::size_t r = 0; r < runCount; ++r) {
        const std::size_t begin = runs[r][0], end = runs[r][1];
        for (std::size_t l = begin; l < end; ++l) {
            // The same expression as gatherRow's: x_k - x_l and x_l - x_k have the same squared
            // norm bit for bit, so the pair passes here exactly when it passes from either side.
            const Vector<Dim> dx = xi - sortedPosition[l];
            const double d2 = dx.squaredNorm();
            const bool in = withinSupport<C>(d2, ri2, radius2[l]);
            row[found] = Index(l);  // a place: the rows are assembled from places in list()
            found += in;
        }
    }
    return used + found;
}

template <int Dim>
template <PairCriterion C>
void NeighbourSearch<Dim>::fillBlocksHalf() {
    const std::size_t n = bins_.size();
    const std::int64_t blocks = std::int64_t((n + rowBlock - 1) / rowBlock);
    blockIndices_.resize(std::size_t(blocks));
    blockMaxTarget_.resize(std::size_t(blocks));
    rowLength_.resize(n);
#pragma omp parallel for schedule(dynamic) if (blocks > 1)
    for (std::int64_t b = 0; b < blocks; ++b) {
        std::vector<Index>& buffer = blockIndices_[std::size_t(b)];
        std::size_t used = 0;
        std::vector<std::array<Index, 2>> runs;
        const std::size_t end = std::min(n, std::size_t(b + 1) * rowBlock);
        for (std::size_t k = std::size_t(b) * rowBlock; k < end; ++k) {
            const std::size_t start = used;
            used = gatherForward<C>(k, buffer, used, runs);
            rowLength_[k] = Index(used - start);
        }
        // The farthest place this block's forward halves reach (0 for none): assembleHalf's
        // chunks skip the blocks that cannot reach them.
        blockMaxTarget_[std::size_t(b)] =
            used > 0 ? *std::max_element(buffer.begin(), buffer.begin() + used) : 0;
    }
}

// The half stencil's rows: row k is, in place order, the places l < k whose forward half holds
// k (in the order of l, as the forward halves are read in place order), k itself when asked
// for, then k's own forward half: exactly the full stencil's row, with half its distance tests.
template <int Dim>
void NeighbourSearch<Dim>::assembleHalf(std::vector<std::size_t>& offsets, std::vector<Index>& indices) {
    const std::vector<Index>& order = bins_.order();
    const std::size_t n = order.size();
    const std::int64_t blocks = std::int64_t(blockIndices_.size());
    // The backward halves are gathered by chunks of target places, one task each: a chunk reads
    // the forward halves of the blocks that reach into it (blockMaxTarget_), in place order, and
    // keeps the pairs whose target is its own. Each row then receives its l < k in the order of
    // l whatever the number of threads; the forward halves reach only a few layers of cells
    // ahead, so a chunk reads little more than its own share.
    const std::int64_t chunks =
        std::max<std::int64_t>(1, std::min<std::int64_t>(blocks, omp_get_max_threads()));
    auto forEachPairInto = [&](std::int64_t chunk, auto&& f) {
        const std::size_t lo = n * std::size_t(chunk) / std::size_t(chunks);
        const std::size_t hi = n * std::size_t(chunk + 1) / std::size_t(chunks);
        for (std::int64_t b = 0; b < blocks && std::size_t(b) * rowBlock < hi; ++b) {
            if (blockMaxTarget_[std::size_t(b)] < lo) continue;
            const std::vector<Index>& buffer = blockIndices_[std::size_t(b)];
            std::size_t position = 0;
            const std::size_t end = std::min(hi, std::min(n, std::size_t(b + 1) * rowBlock));
            for (std::size_t k = std::size_t(b) * rowBlock; k < end; ++k)
                for (const std::size_t stop = position + rowLength_[k]; position < stop; ++position) {
                    const std::size_t l = buffer[position];
                    if (l >= lo && l < hi) f(k, l);
                }
        }
    };
    backLength_.assign(n, 0);
#pragma omp parallel for schedule(static) if (chunks > 1)
    for (std::int64_t c = 0; c < chunks; ++c)
        forEachPairInto(c, [&](std::size_t, std::size_t l) { ++backLength_[l]; });
    const std::size_t self = options_.includeSelf ? 1 : 0;
    offsets.assign(n + 1, 0);
    for (std::size_t k = 0; k < n; ++k)
        offsets[std::size_t(order[k]) + 1] = backLength_[k] + self + rowLength_[k];
    for (std::size_t i = 0; i < n; ++i) offsets[i + 1] += offsets[i];
    indices.resize(offsets[n]);  // every index is written below
    rowStart_.resize(n);
    // Self and the forward halves, block by block (each row's own part: no two blocks write
    // the same place).
#pragma omp parallel for schedule(static) if (blocks > 1)
    for (std::int64_t b = 0; b < blocks; ++b) {
        const std::vector<Index>& buffer = blockIndices_[std::size_t(b)];
        std::size_t position = 0;
        const std::size_t end = std::min(n, std::size_t(b + 1) * rowBlock);
        for (std::size_t k = std::size_t(b) * rowBlock; k < end; ++k) {
            const std::size_t start = offsets[order[k]];
            rowStart_[k] = start;
            Index* out = indices.data() + start + backLength_[k];
            if (self) *out++ = order[k];
            for (const std::size_t stop = position + rowLength_[k]; position < stop; ++position)
                *out++ = order[buffer[position]];
        }
    }
#pragma omp parallel for schedule(static) if (chunks > 1)
    for (std::int64_t c = 0; c < chunks; ++c)
        forEachPairInto(c, [&](std::size_t k, std::size_t l) { indices[rowStart_[l]++] = order[k]; });
}

template <int Dim>
NeighbourList NeighbourSearch<Dim>::list(NeighbourList reuse) {
    const std::vector<Index>& order = bins_.order();
    const std::size_t n = order.size();
    // With one radius for all the three criteria coincide; gather skips the look-up of r_j.
    const PairCriterion criterion = constantRadius_ ? PairCriterion::gather : options_.criterion;
    const bool periodic = domain_.anyPeriodic();
    std::vector<std::size_t> offsets;
    std::vector<Index> indices;
    reuse.releaseStorage(offsets, indices);
    // The half stencil needs a symmetric pair test (gather with variable radii is not) and rows
    // of cells in place order (a periodic range wraps); sorted rows take the full stencil too.
    const bool symmetric = criterion != PairCriterion::gather || constantRadius_;
    if (options_.halfStencil && symmetric && !periodic && !options_.sortRows) {
        switch (criterion) {
            case PairCriterion::either:
                fillBlocksHalf<PairCriterion::either>();
                break;
            case PairCriterion::both:
                fillBlocksHalf<PairCriterion::both>();
                break;
            case PairCriterion::gather:
                fillBlocksHalf<PairCriterion::gather>();
                break;
        }
        assembleHalf(offsets, indices);
        return NeighbourList(std::move(offsets), std::move(indices));
    }
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

    offsets.assign(n + 1, 0);
    for (std::size_t k = 0; k < n; ++k) offsets[std::size_t(order[k]) + 1] = rowLength_[k];
    for (std::size_t i = 0; i < n; ++i) offsets[i + 1] += offsets[i];
    // Every index is written below: only a grown part is initialised by resize.
    indices.resize(offsets[n]);
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
