#pragma once
// Cell-linked-list neighbour search over particles sorted by cell.
//
// bin() puts the particles on a grid of cells no narrower than maxRadius / cellsPerRadius and
// sorts them by cell with a stable counting sort (a CellBins, bins()); order() is that
// permutation. A caller that applies it to its own fields (applyOrder) gets particles that are
// close in space close in memory, which is what makes the gather loops over the list
// cache-friendly; binning the reordered particles again then gives the identity order. list() builds the compressed-row
// neighbour list in the caller's indexing.
//
// Pairs: with r_i the support radius of particle i and d = |separation(x_i, x_j)|, j is in row i
// when (compared as squares, d^2 < r^2)
//   either:  d < r_i or d < r_j       symmetric; what SPH needs when h varies (gather-scatter)
//   both:    d < min(r_i, r_j)        symmetric
//   gather:  d < r_i                  asymmetric
// Self is in its own row only when asked for.
//
// Results do not depend on the number of threads: a row is computed by one thread from data that
// does not depend on the schedule. A row lists its neighbours in cell order (by increasing cell,
// within a cell by increasing index) or, with sortRows, by increasing index; on particles already
// in cell order the two coincide outside periodic wrap-around and the sort costs only its check.
//
// The grid is limited to maxCellsPerParticle cells per particle: a few particles in a huge box
// coarsen the cells instead of allocating an empty grid. Periodic directions need
// maxRadius <= period / 2, so that only the minimum image can be a neighbour.
//
// Everything here is rank-local (LocalReduce): the search sees this process's particles (owned
// and ghost) and never waits for another rank.
#include "core/Error.hpp"
#include "core/Parallel.hpp"
#include "core/Tensor.hpp"
#include "particles/CellBins.hpp"
#include "particles/NeighbourDomain.hpp"
#include "particles/NeighbourList.hpp"

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace mfdyn {

enum class PairCriterion { either, both, gather };

struct NeighbourSearchOptions {
    PairCriterion criterion = PairCriterion::either;
    bool includeSelf = false;
    // Off by default: on particles kept in cell order (see order()) rows come out sorted anyway,
    // and on others sorting costs more than the search itself.
    bool sortRows = false;
    // With each row of cells cut to the query sphere's chord, cells of width maxRadius / 2 scan
    // 2.5 times the sphere's volume in 3D, width maxRadius 4.9, width maxRadius / 3 1.9 but
    // with twice the rows per particle; at SPH neighbour counts 2 measured fastest.
    int cellsPerRadius = 2;
    // An impact's debris spreads over a box hundreds of particle spacings wide while most of it
    // stays empty: with too few cells the cells grow past the support radius and every query
    // scans many times its neighbours (a 2D impact ran 3x slower at 2 cells per particle).
    // 32 cells cost 128 bytes per particle of cell starts.
    double maxCellsPerParticle = 32.0;
    // Symmetric criteria in open domains test each pair once (from the lower of its two places)
    // and write it into both rows: the same list, bit for bit and in the same order, for about
    // two thirds of the time. Off only to compare against the full stencil.
    bool halfStencil = true;
};

template <int Dim>
class NeighbourSearch {
public:
    using Index = NeighbourList::Index;

    explicit NeighbourSearch(NeighbourDomain<Dim> domain = {}, NeighbourSearchOptions options = {});

    // Sorts the particles into cells. supportRadius[i] is r_i (kappa h_i); the constant-radius
    // form skips the per-pair radius look-up.
    void bin(const std::vector<Vector<Dim>>& positions, const std::vector<double>& supportRadius);
    void bin(const std::vector<Vector<Dim>>& positions, double supportRadius);

    // The neighbour list of the particles last binned, written into the storage of `reuse` (a
    // previous list, moved in) where it is large enough.
    NeighbourList list(NeighbourList reuse = {});

    NeighbourList build(const std::vector<Vector<Dim>>& positions, const std::vector<double>& supportRadius) {
        bin(positions, supportRadius);
        return list();
    }
    NeighbourList build(const std::vector<Vector<Dim>>& positions, double supportRadius) {
        bin(positions, supportRadius);
        return list();
    }

    // order()[k] is the index of the particle at place k of the cell order.
    const std::vector<Index>& order() const { return bins_.order(); }
    // The cells of the last bin(), for point queries among the same particles.
    const CellBins<Dim>& bins() const { return bins_; }

    // field[k] <- field[order()[k]], for a field of `width` contiguous values per particle.
    template <class T>
    void applyOrder(std::span<T> field, std::size_t width = 1) const;
    template <class T>
    void applyOrder(std::vector<T>& field, std::size_t width = 1) const {
        applyOrder(std::span<T>(field), width);
    }

    const NeighbourDomain<Dim>& domain() const { return domain_; }
    const NeighbourSearchOptions& options() const { return options_; }
    Vector<Dim> separation(const Vector<Dim>& xi, const Vector<Dim>& xj) const {
        return domain_.separation(xi, xj);
    }

    std::size_t size() const { return bins_.size(); }
    double maxRadius() const { return maxRadius_; }
    const std::array<std::int64_t, Dim>& cellShape() const { return bins_.shape(); }
    std::size_t cellCount() const { return bins_.cellCount(); }

private:
    void binSorted(const std::vector<Vector<Dim>>& positions, const double* radius, bool constantRadius);
    // Writes row k (place k of the cell order) into buffer from position `used` on, growing the
    // buffer when it must; returns the position after the row. runs is scratch space.
    template <PairCriterion C, bool Periodic>
    std::size_t gatherRow(std::size_t k, std::vector<Index>& buffer, std::size_t used,
                          std::vector<std::array<Index, 2>>& runs) const;
    template <PairCriterion C, bool Periodic>
    void fillBlocks();
    // The half stencil (open domains, symmetric criteria): each pair tested once, from its
    // lower place, and the rows assembled from the forward halves (see list()).
    template <PairCriterion C>
    std::size_t gatherForward(std::size_t k, std::vector<Index>& buffer, std::size_t used,
                              std::vector<std::array<Index, 2>>& runs) const;
    template <PairCriterion C>
    void fillBlocksHalf();
    void assembleHalf(std::vector<std::size_t>& offsets, std::vector<Index>& indices);

    NeighbourDomain<Dim> domain_;
    NeighbourSearchOptions options_;
    bool constantRadius_ = false;
    double maxRadius_ = 0.0;

    CellBins<Dim> bins_;
    std::vector<double> sortedRadius2_;

    // Per block of rows: the rows' neighbours in place order (the first rowLength_ sum of each
    // buffer; a buffer is only grown, never cleared), and each row's length. Kept between builds
    // so that a rebuild reuses the memory.
    std::vector<std::vector<Index>> blockIndices_;
    std::vector<Index> rowLength_;
    // The half stencil's backward lengths and the rows' write positions.
    std::vector<Index> backLength_, blockMaxTarget_;
    std::vector<std::size_t> rowStart_;
};

template <int Dim>
template <class T>
void NeighbourSearch<Dim>::applyOrder(std::span<T> field, std::size_t width) const {
    const std::vector<Index>& order = bins_.order();
    if (field.size() != order.size() * width)
        throw Error("NeighbourSearch::applyOrder: field of " + std::to_string(field.size()) + " values for " +
                    std::to_string(order.size()) + " particles of width " + std::to_string(width));
    const std::vector<T> old(field.begin(), field.end());
    parallelFor(order.size(), [&](std::size_t k) {
        for (std::size_t c = 0; c < width; ++c) field[k * width + c] = old[std::size_t(order[k]) * width + c];
    });
}

}  // namespace mfdyn
