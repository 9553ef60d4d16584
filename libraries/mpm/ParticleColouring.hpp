#pragma once
// Deterministic particle-to-grid sums without floating-point atomics (issue 17 item 3).
//
// Every step the particles are bucketed by the cell that holds them (a stable counting sort, so
// inside a cell they keep their index order), and the cells are coloured: cell (i, j, k) has
// colour (i mod P_x, j mod P_y, k mod P_z), where P_d is the number of node layers along d that
// the particles of one cell reach (from the node list: linear hats 2, B-splines up to 4). Two
// cells of one colour are P_d or more apart along some axis, so their particles touch disjoint
// nodes: the cells of a colour are scattered in parallel, the colours one after another. Each
// node then receives its terms colour by colour, and within a colour from one cell, its
// particles in index order: the same order, hence the same bits, for any thread count and with
// no locks. Chosen over (b) per-thread grids summed in a fixed order, whose order follows the
// particles' split between threads (bitwise results would change with the thread count unless
// the split is fixed, and a grid copy per block costs memory), and over (a) a gather per node,
// which must find its entry in each neighbouring particle's node list.
#include "core/Parallel.hpp"
#include "core/Tensor.hpp"
#include "grid/CartesianGrid.hpp"
#include "grid/shapeFunctions/ShapeFunction.hpp"

#include <array>
#include <cstddef>
#include <span>
#include <vector>

namespace mfdyn {

template <int Dim>
class ParticleColouring {
public:
    // Buckets the particles at `x` (inside the grid) and colours the cells for the node list
    // `list` evaluated at the same positions.
    void build(const CartesianGrid<Dim>& grid, std::span<const Vector<Dim>> x,
               const ParticleNodeList<Dim>& list);

    // body(p) for every particle, in colour batches: body may add into the arrays of p's nodes
    // without synchronisation. The order within a node is fixed (see the header comment).
    template <class Body>
    void forEachParticle(Body&& body) const {
        // The work of a colour: its share of the particles times the nodes each one touches.
        const std::size_t work = (order_.size() / colours() + 1) * stride_;
        for (const auto& cells : colourCells_) {
            parallelForWork(cells.size(), work, [&](std::size_t c) {
                for (std::size_t k = cellStart_[cells[c]]; k < cellStart_[cells[c] + 1]; ++k) body(order_[k]);
            });
        }
    }

    std::size_t colours() const { return colourCells_.size(); }
    // The node layers per axis a cell's particles reach (P_d above).
    const std::array<int, Dim>& period() const { return period_; }

private:
    std::vector<std::size_t> cellOfParticle_;
    std::vector<std::size_t> cellStart_;                 // cellCount + 1 offsets into order_
    std::vector<std::size_t> order_;                     // particles sorted by cell, stable
    std::vector<std::vector<std::size_t>> colourCells_;  // per colour: its non-empty cells, ascending
    std::array<int, Dim> period_{};
    std::size_t stride_ = 1;
};

extern template class ParticleColouring<1>;
extern template class ParticleColouring<2>;
extern template class ParticleColouring<3>;

}  // namespace mfdyn
