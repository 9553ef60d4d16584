#pragma once
// Particles binned into a uniform grid of cells, in cell-sorted order: the one cell grid of the
// code. The neighbour search builds its lists on it, Interpolation finds the particles around a
// sample point with it, and a background-grid method (MPM's gather-form particle-to-grid
// transfer: each node sums over the particles within its shape function's support) is meant to
// query it the same way, node by node, from as many threads as it likes (queries are const).
//
// bin(positions, cellWidth) lays cells at least cellWidth wide over the domain's box (given, or
// the particles' bounding box) and sorts the particles by cell with a stable counting sort:
// order()[k] is the particle at place k, and a cell's particles are the contiguous places
// [cellBegin(c), cellEnd(c)), by increasing particle index. Cells are numbered with x fastest, so
// a row of cells along x is one contiguous run of places. In an open direction the edge cells
// reach to infinity (a particle or point outside a given box belongs to the edge cell); in a
// periodic direction [lo, hi) points are wrapped first, and the direction holds a whole number of
// cells, each at least cellWidth wide.
//
// The grid is limited to maxCellsPerParticle cells per particle: a few particles in a huge box
// coarsen the cells instead of allocating an empty grid. So cells may be wider than asked
// (width(d) says how wide they are), never narrower; queries are exact at any width.
//
// Point queries: forEachWithin(x, r, visit) visits every particle j with |separation(x, x_j)| < r
// (compared as squares), at any point, inside the box or not; forEachCandidate visits a superset
// (whole chords of cell rows through the ball) for a caller with its own test. Both visit in
// place order, which does not depend on the number of threads.
#include "core/Error.hpp"
#include "core/Tensor.hpp"
#include "particles/NeighbourDomain.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace mfdyn {

template <int Dim>
class CellBins {
public:
    using Index = std::uint32_t;
    // A run [first, second) of places in the cell order.
    using Run = std::array<Index, 2>;

    explicit CellBins(NeighbourDomain<Dim> domain = {}, double maxCellsPerParticle = 32.0);

    // Bins the particles; cellWidth 0 gives one cell as wide as the box in each open direction.
    // Throws Error for a non-finite position, a negative or non-finite width, or more particles
    // than a 32-bit index can number.
    void bin(const std::vector<Vector<Dim>>& positions, double cellWidth);

    const NeighbourDomain<Dim>& domain() const { return domain_; }
    std::size_t size() const { return order_.size(); }
    // Cells along each direction, their width, and the low corner of cell (0, ..., 0).
    const std::array<std::int64_t, Dim>& shape() const { return cells_; }
    double width(int direction) const { return width_[direction]; }
    const Vector<Dim>& origin() const { return origin_; }
    std::size_t cellCount() const { return cellStart_.empty() ? 0 : cellStart_.size() - 1; }

    // The cell holding x: its coordinates (clamped to the edge cells in open directions, wrapped
    // in periodic ones) and its number. x must be finite.
    std::array<std::int64_t, Dim> cellCoordinates(const Vector<Dim>& x) const;
    std::size_t cellOf(const Vector<Dim>& x) const;

    // The particles of cell c: places [cellBegin(c), cellEnd(c)), or their indices.
    Index cellBegin(std::size_t c) const { return cellStart_[c]; }
    Index cellEnd(std::size_t c) const { return cellStart_[c + 1]; }
    std::span<const Index> particlesOf(std::size_t c) const {
        return {order_.data() + cellStart_[c], order_.data() + cellStart_[c + 1]};
    }
    // order()[k] is the index of the particle at place k; sortedPositions()[k] its position as
    // given to bin() (not wrapped).
    const std::vector<Index>& order() const { return order_; }
    const std::vector<Vector<Dim>>& sortedPositions() const { return sortedPosition_; }

    // Appends to `out` (cleared first) runs of places holding every particle within `reach` of
    // x: each row of cells through the ball cut to the ball's chord (one run, two where a
    // periodic range wraps). `Periodic` must be domain().anyPeriodic(); x must be finite.
    template <bool Periodic>
    void runs(const Vector<Dim>& x, double reach, std::vector<Run>& out) const {
        out.clear();
        visitRuns<Periodic>(x, reach, [&](Index begin, Index end) { out.push_back({begin, end}); });
    }
    // The same runs handed to visit(begin, end) one by one, in the same order: the caller keeps
    // them as it likes (the neighbour search in scratch that is only grown; a vector cleared and
    // pushed to per query cost a tenth of its build).
    // With fromRow > 0 (open domains only) the rows of cells whose first cell is numbered below
    // fromRow are skipped: a half stencil (each pair once) passes the row of the particle's own
    // cell (rowOf) and cuts that row at the particle's place.
    template <bool Periodic, class Visit>
    void visitRuns(const Vector<Dim>& x, double reach, Visit&& visit, std::int64_t fromRow = 0) const;
    // The number of the first cell of the row of cells holding x.
    std::int64_t rowOf(const Vector<Dim>& x) const { return std::int64_t(cellOf(x)) - cellCoordinates(x)[0]; }

    // visit(index) for every particle in the runs around x (a superset of those within reach).
    template <class Visit>
    void forEachCandidate(const Vector<Dim>& x, double reach, Visit&& visit) const;
    // visit(index, separation(x, x_j)) for every particle with |separation|^2 < r^2. A point that
    // is not finite is within no distance of any particle: nothing is visited.
    template <class Visit>
    void forEachWithin(const Vector<Dim>& x, double r, Visit&& visit) const;
    // The indices forEachWithin visits, in its order.
    std::vector<Index> within(const Vector<Dim>& x, double r) const;

private:
    template <class Visit>
    void forEachRun(const Vector<Dim>& x, double reach, Visit&& visit) const;

    NeighbourDomain<Dim> domain_;
    double maxCellsPerParticle_;
    Vector<Dim> origin_ = Vector<Dim>::Zero();
    std::array<double, Dim> width_{};
    std::array<std::int64_t, Dim> cells_{};
    std::vector<Index> order_;
    std::vector<Index> cellStart_;
    std::vector<Vector<Dim>> sortedPosition_;
};

namespace cellBinsDetail {

// A query box is widened by this many cell widths so that rounding in the cell coordinates can
// never drop a cell holding a neighbour; an extra cell only costs distance checks.
inline constexpr double cellPadding = 1e-6;

// floor() of a value well inside the int64 range. Without SSE4.1 std::floor is a library call,
// and a query computes a few dozen of them. Of a non-negative value the conversion alone is the
// floor.
inline std::int64_t floorToInt(double v) {
    const auto i = std::int64_t(v);
    return i - std::int64_t(double(i) > v);
}

}  // namespace cellBinsDetail

template <int Dim>
template <bool Periodic, class Visit>
void CellBins<Dim>::visitRuns(const Vector<Dim>& xi, double reach, Visit&& visit,
                              std::int64_t fromRow) const {
    using cellBinsDetail::cellPadding;
    using cellBinsDetail::floorToInt;
    if (order_.empty()) return;
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
    auto cellRow = [&](std::int64_t base, double gap2) {
        if (gap2 > reach2) return;  // not >=: with reach 0 the own cell still holds self
        std::int64_t lo, hi;
        range(0, std::sqrt(reach2 - gap2), lo, hi);
        const std::int64_t n = cells_[0];
        if (lo >= 0 && hi < n) {
            visit(cellStart_[base + lo], cellStart_[base + hi + 1]);
        } else {
            visit(cellStart_[base + fold(lo, n)], cellStart_[base + n]);
            visit(cellStart_[base], cellStart_[base + fold(hi, n) + 1]);
        }
    };
    // The first row not skipped (fromRow): rows are numbered z-major, so the skipped ones are
    // those of lower z, and of the same z and lower y.
    // Periodic ranges start below 0 unwrapped: fromRow 0 must leave them alone.
    const std::int64_t fromY =
        Dim > 1 && fromRow > 0 ? fromRow / cells_[0] % cells_[1] : first[Dim > 1 ? 1 : 0];
    const std::int64_t fromZ =
        Dim > 2 && fromRow > 0 ? fromRow / (cells_[0] * cells_[1]) : first[Dim > 2 ? 2 : 0];
    if constexpr (Dim == 1) {
        cellRow(0, 0.0);
    } else if constexpr (Dim == 2) {
        for (std::int64_t cy = std::max(first[1], fromY); cy <= last[1]; ++cy) {
            const double gy = gap(1, cy);
            cellRow(fold(cy, cells_[1]) * cells_[0], gy * gy);
        }
    } else {
        for (std::int64_t cz = std::max(first[2], fromZ); cz <= last[2]; ++cz) {
            const double gz = gap(2, cz);
            for (std::int64_t cy = cz == fromZ ? std::max(first[1], fromY) : first[1]; cy <= last[1]; ++cy) {
                const double gy = gap(1, cy);
                cellRow((fold(cz, cells_[2]) * cells_[1] + fold(cy, cells_[1])) * cells_[0],
                        gy * gy + gz * gz);
            }
        }
    }
}

template <int Dim>
template <class Visit>
void CellBins<Dim>::forEachRun(const Vector<Dim>& x, double reach, Visit&& visit) const {
    if (order_.empty() || !x.allFinite() || !(reach >= 0)) return;
    // A point far outside the box: the ranges clamp to the edge cells, which is still exact.
    // No scratch: the runs are visited as they are found (a visitor may itself query these bins).
    auto each = [&](Index begin, Index end) {
        for (Index l = begin; l < end; ++l) visit(l);
    };
    if (domain_.anyPeriodic())
        visitRuns<true>(x, reach, each);
    else
        visitRuns<false>(x, reach, each);
}

template <int Dim>
template <class Visit>
void CellBins<Dim>::forEachCandidate(const Vector<Dim>& x, double reach, Visit&& visit) const {
    forEachRun(x, reach, [&](Index l) { visit(order_[l]); });
}

template <int Dim>
template <class Visit>
void CellBins<Dim>::forEachWithin(const Vector<Dim>& x, double r, Visit&& visit) const {
    if (!(r > 0)) return;  // nothing is at a distance below 0; NaN r finds nothing either
    const double r2 = r * r;
    forEachRun(x, r, [&](Index l) {
        const Vector<Dim> dx = domain_.separation(x, sortedPosition_[l]);
        if (dx.squaredNorm() < r2) visit(order_[l], dx);
    });
}

}  // namespace mfdyn
