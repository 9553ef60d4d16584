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

// floor() of a value well inside the int64 range. Without SSE4.1 std::floor is a library call,
// and the query computes a few dozen of them per particle. Of a non-negative value the
// conversion alone is the floor.
inline std::int64_t floorToInt(double v) {
    const auto i = std::int64_t(v);
    return i - std::int64_t(double(i) > v);
}

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

    const std::size_t badRadii =
        constantRadius
            ? std::size_t(!(std::isfinite(radius[0]) && radius[0] >= 0))
            : Reduce::sum<std::size_t>(n, [&](std::size_t i) { return !(std::isfinite(r(i)) && r(i) >= 0); });
    if (badRadii > 0) throw Error("NeighbourSearch: support radii must be finite and non-negative");
    const std::size_t badPositions =
        Reduce::sum<std::size_t>(n, [&](std::size_t i) { return std::size_t(!positions[i].allFinite()); });
    if (badPositions > 0)
        throw Error("NeighbourSearch: " + std::to_string(badPositions) +
                    " particle positions are not finite");

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
    const double cellLimit = std::min(std::max(1.0, options_.maxCellsPerParticle * double(n)),
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
    std::vector<Index> cellOf(n);
    parallelFor(n, [&](std::size_t i) {
        const Vector<Dim> x = domain_.anyPeriodic() ? domain_.wrap(positions[i]) : positions[i];
        std::int64_t c = 0;
        for (int d = Dim - 1; d >= 0; --d) {
            const double t = (x[d] - origin_[d]) / width_[d];
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
void NeighbourSearch<Dim>::gatherRow(std::size_t k, std::vector<Index>& out,
                                     std::vector<std::array<Index, 2>>& runs) const {
    const Vector<Dim>& xi = sortedPosition_[k];
    const double ri2 = sortedRadius2_[k];
    // Any j with d < max(r_i, r_j) is within maxRadius; the other criteria stay within r_i.
    const double reach = C == PairCriterion::either ? maxRadius_ : std::sqrt(ri2);
    const bool includeSelf = options_.includeSelf;

    // Cell range [first, last] of the query interval [x - half, x + half] along direction d. In a
    // periodic direction the range is left unwrapped (it may start below 0 or end past the last
    // cell) and folded when visited; one that would cover a cell twice is cut to the whole period.
    const Vector<Dim> x = Periodic ? domain_.wrap(xi) : xi;
    std::array<double, Dim> t{};
    for (int d = 0; d < Dim; ++d) t[d] = (x[d] - origin_[d]) / width_[d];
    auto range = [&](int d, double half, std::int64_t& first, std::int64_t& last) {
        const double s = half / width_[d] + cellPadding;
        const double top = double(cells_[d] - 1);
        if (Periodic && domain_.periodic(d)) {
            first = floorToInt(std::clamp(t[d] - s, -top - 1, 2 * top + 1));
            last = floorToInt(std::clamp(t[d] + s, -top - 1, 2 * top + 1));
            if (last - first + 1 >= cells_[d]) {
                first = 0;
                last = cells_[d] - 1;
                return true;
            }
        } else {
            first = std::int64_t(std::clamp(t[d] - s, 0.0, top));
            last = std::int64_t(std::clamp(t[d] + s, 0.0, top));
        }
        return false;
    };
    std::array<std::int64_t, Dim> first{}, last{};
    std::array<bool, Dim> wholePeriod{};
    for (int d = 1; d < Dim; ++d) wholePeriod[d] = range(d, reach, first[d], last[d]);
    auto fold = [](std::int64_t c, std::int64_t n) { return c < 0 ? c + n : (c >= n ? c - n : c); };
    // Distance from x to the slab of (unwrapped) cell c along d, shrunk by the padding. Zero when
    // the range covers the whole period, where c is not the nearest image. In an open direction
    // the edge cells reach to infinity: they hold the particles outside a given box.
    auto gap = [&](int d, std::int64_t c) {
        if (wholePeriod[d]) return 0.0;
        const bool open = !(Periodic && domain_.periodic(d));
        const double below = open && c == 0 ? 0.0 : double(c) - t[d];
        const double above = open && c == cells_[d] - 1 ? 0.0 : t[d] - double(c + 1);
        const double g = std::max(below, above) - cellPadding;
        return g > 0 ? g * width_[d] : 0.0;
    };

    // Cells along x are contiguous in the cell order, so a row of cells is one run of particles
    // (two where a periodic range wraps). Each row is cut to the chord of the query sphere through
    // it, which leaves in 3D about two thirds of the particles of the full box of cells to check.
    const double reach2 = reach * reach;
    runs.clear();
    auto run = [&](Index begin, Index end) { runs.push_back({begin, end}); };
    {
        auto cellRow = [&](std::int64_t base, double gap2) {
            if (gap2 > reach2) return;  // not >=: with reach 0 the own cell still holds self
            std::int64_t lo, hi;
            range(0, std::sqrt(reach2 - gap2), lo, hi);
            const std::int64_t n = cells_[0];
            if (lo >= 0 && hi < n) {
                run(cellStart_[base + lo], cellStart_[base + hi + 1]);
            } else {
                run(cellStart_[base + fold(lo, n)], cellStart_[base + n]);
                run(cellStart_[base], cellStart_[base + fold(hi, n) + 1]);
            }
        };
        if constexpr (Dim == 1) {
            cellRow(0, 0.0);
        } else if constexpr (Dim == 2) {
            for (std::int64_t cy = first[1]; cy <= last[1]; ++cy) {
                const double gy = gap(1, cy);
                cellRow(fold(cy, cells_[1]) * cells_[0], gy * gy);
            }
        } else {
            for (std::int64_t cz = first[2]; cz <= last[2]; ++cz) {
                const double gz = gap(2, cz);
                for (std::int64_t cy = first[1]; cy <= last[1]; ++cy) {
                    const double gy = gap(1, cy);
                    cellRow((fold(cz, cells_[2]) * cells_[1] + fold(cy, cells_[1])) * cells_[0],
                            gy * gy + gz * gz);
                }
            }
        }
    }

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
            in = l == k ? includeSelf : in;
            row[found] = order_[l];
            found += in;
        }
    }
    out.resize(start + found);
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
#pragma omp parallel for schedule(static) if (blocks > 1)
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
