#pragma once
// Deterministic particle-to-grid sums without floating-point atomics (issue 17 item 3).
//
// Every step the particles are bucketed by tile, a block of T x T (x T) cells (T = 8, or more
// for a shape function reaching more node layers), with a stable counting sort, so that inside
// a tile they keep their index order; the tiles are coloured by the parity of their tile index
// along each axis (2^Dim colours). Two tiles of one colour are a whole tile apart along some
// axis, T + 1 cells between their nearest cells, while the particles of one cell reach at most
// nodesPerAxis() + 1 <= T node layers: their particles touch disjoint nodes. The tiles of a colour
// are scattered in parallel, the colours one after another. Each node then receives its terms
// colour by colour, and within a colour from one tile, its particles in index order: the same
// order, hence the same bits, for any thread count and with no locks. Given the particles' global
// ids, a tile's particles are in id order instead (the index order of a serial run, whose file is
// in id order; a no-op check there): on several ranks, whose owned particles and halo are numbered
// differently, every node then receives the same terms in the same order as serially (issue 21).
//
// Measured (P2G of mass and momentum, 102400 particles on a 160 x 160 grid, linear hats, one
// thread of a loaded machine; /tmp bench in the commit message): serial scatter in index order
// 1.55 ms; colouring cell by cell ((i mod P) per axis, 4 colours; the first version) 5.5 ms, of
// which the bucketing 2.2 ms, its scatter 3.3 ms streaming the grid once per colour; fixed
// per-block grids summed in block order (8 blocks) 1.96 ms but 8 copies of the node fields (a
// 10^6-node 3D grid: 450 MB); a gather per node over the particles of its cells 5.9 ms. Tiles
// keep the serial scatter's locality (a tile's particles in order) and bucket by tile, not cell.
#include "core/Parallel.hpp"
#include "core/Tensor.hpp"
#include "grid/CartesianGrid.hpp"
#include "grid/shapeFunctions/ShapeFunction.hpp"

#include <array>
#include <cstdint>
#include <cstddef>
#include <span>
#include <vector>

namespace mfdyn {

template <int Dim>
class ParticleColouring {
public:
    // Buckets the particles at `x` (inside the grid) by tile, for the node list `list` evaluated
    // at the same positions (its stride gives the node layers a particle reaches).
    void build(const CartesianGrid<Dim>& grid, std::span<const Vector<Dim>> x,
               const ParticleNodeList<Dim>& list, std::span<const std::int64_t> globalId = {});

    // body(p) for every particle, in colour batches: body may add into the arrays of p's nodes
    // without synchronisation. The order within a node is fixed (see the header comment).
    template <class Body>
    void forEachParticle(Body&& body) const {
        // The work of a colour: its share of the particles times the nodes each one touches.
        const std::size_t work = (order_.size() / colours() + 1) * stride_;
        for (const auto& tiles : colourTiles_) {
            parallelForWork(tiles.size(), work, [&](std::size_t t) {
                for (std::size_t k = tileStart_[tiles[t]]; k < tileStart_[tiles[t] + 1]; ++k) body(order_[k]);
            });
        }
    }

    std::size_t colours() const { return colourTiles_.size(); }
    // The tile's width in cells along each axis (T above).
    const std::array<int, Dim>& period() const { return period_; }

private:
    std::vector<std::size_t> tileOfParticle_;
    std::vector<std::size_t> tileStart_;                 // tileCount + 1 offsets into order_
    std::vector<std::size_t> order_;                     // particles sorted by tile, stable
    std::vector<std::vector<std::size_t>> colourTiles_;  // per colour: its non-empty tiles, ascending
    std::array<int, Dim> period_{};
    std::size_t stride_ = 1;
};

extern template class ParticleColouring<1>;
extern template class ParticleColouring<2>;
extern template class ParticleColouring<3>;

}  // namespace mfdyn
