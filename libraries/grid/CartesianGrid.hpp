#pragma once
// A structured Cartesian background grid in 1, 2 or 3 dimensions: the grid of grid methods (MPM
// first; FPM and the MPI decomposition may use it). It knows nothing of any method: it is the
// geometry (origin, cell size per axis, cell counts), the node numbering, and the node fields,
// stored as arrays and created on demand exactly as ParticleSet's particle fields are (a
// FieldStore of nodeCount() entries).
//
// Numbering: node (i, j, k), 0 <= i <= cells[0], ..., has index i + (cells[0]+1) (j + (cells[1]+1) k),
// x fastest; its position is origin + (i dx, j dy, k dz). Cell (i, j, k) spans [x_i, x_i+1) x ...;
// a point on the upper face of the grid belongs to the last cell (cellOf clamps), so every point
// of the closed box has a cell.
//
// Dictionary (constant/mpmProperties' `grid`, or any method's):
//     grid { origin (0 0 0); cellSize (0.05 0.05 0.05); cells (20 20 20); }
//     grid { box { min (0 0 0); max (1 1 1); } cellSize 0.05; }  // cells = round(length / size),
//                                                                 // size then adjusted to fit the box
#include "core/Dictionary.hpp"
#include "core/KeywordSchema.hpp"
#include "core/Tensor.hpp"
#include "particles/FieldStore.hpp"

#include <array>
#include <cstddef>
#include <cstdint>

namespace mfdyn {

template <int Dim>
class CartesianGrid {
public:
    using Index = std::int64_t;
    using Ijk = std::array<Index, Dim>;

    // Throws Error for a non-positive or non-finite cell size or a cell count below 1.
    CartesianGrid(const Vector<Dim>& origin, const Vector<Dim>& cellSize, const Ijk& cells);
    // From a dictionary of either form above; InputError at the entry's line for bad input.
    static CartesianGrid fromDictionary(const Dictionary& dict);
    // The keywords of both forms (origin, cellSize, cells, box), for a method's schema
    // (`.dictionary("grid", ...).nested(&CartesianGrid<Dim>::keywords)`) and mfDoc; which
    // combinations go together is checked by fromDictionary.
    static KeywordSchema keywords();

    const Vector<Dim>& origin() const { return origin_; }
    const Vector<Dim>& cellSize() const { return cellSize_; }
    double cellSize(int d) const { return cellSize_[d]; }
    double smallestCellSize() const;
    const Ijk& cells() const { return cells_; }
    Ijk nodesPerAxis() const;
    Vector<Dim> upperCorner() const;  // origin + cells * cellSize
    std::size_t nodeCount() const { return nodeCount_; }
    std::size_t cellCount() const;

    Index nodeIndex(const Ijk& ijk) const;
    Ijk nodeIjk(Index node) const;
    Vector<Dim> nodePosition(Index node) const;
    Vector<Dim> nodePosition(const Ijk& ijk) const;

    // Inside the closed box [origin, upperCorner] (with a tolerance of 1e-12 of a cell).
    bool contains(const Vector<Dim>& x) const;
    // The cell holding x, clamped to the grid (callers check contains() first where it matters).
    Ijk cellOf(const Vector<Dim>& x) const;
    // (x - origin) / cellSize per axis: the position in cell units, for the shape functions.
    Vector<Dim> cellCoordinates(const Vector<Dim>& x) const;

    // The node fields ("mass", "momentum", "velocity", ...), nodeCount() entries each.
    FieldStore& nodes() { return nodes_; }
    const FieldStore& nodes() const { return nodes_; }

    // One line for the log: "grid: 20 x 20 cells of 0.05 x 0.05 m from (0 0), 441 nodes".
    std::string describe() const;

private:
    Vector<Dim> origin_;
    Vector<Dim> cellSize_;
    Ijk cells_;
    std::size_t nodeCount_;
    FieldStore nodes_;
};

extern template class CartesianGrid<1>;
extern template class CartesianGrid<2>;
extern template class CartesianGrid<3>;

}  // namespace mfdyn
