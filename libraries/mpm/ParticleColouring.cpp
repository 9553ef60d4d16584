// Cell bucketing and colouring of the particle-to-grid sums: see ParticleColouring.hpp.
#include "mpm/ParticleColouring.hpp"

#include "core/Error.hpp"

#include <algorithm>

namespace mfdyn {

template <int Dim>
void ParticleColouring<Dim>::build(const CartesianGrid<Dim>& grid, std::span<const Vector<Dim>> x,
                                   const ParticleNodeList<Dim>& list) {
    const std::size_t n = x.size();
    const auto& cells = grid.cells();
    const std::size_t cellCount = grid.cellCount();
    cellOfParticle_.resize(n);
    stride_ = std::max<std::size_t>(1, list.stride);
    // The node layers a cell's particles reach: from the first and last entry of each particle
    // (a tensor-product block of nodes listed by increasing index: the first is its lowest
    // corner, the last its highest), relative to the particle's cell.
    std::array<long, Dim> lo, hi;
    lo.fill(0), hi.fill(0);
    for (std::size_t p = 0; p < n; ++p) {
        const auto cell = grid.cellOf(x[p]);
        std::size_t index = 0, stride = 1;
        for (int d = 0; d < Dim; ++d) index += std::size_t(cell[d]) * stride, stride *= std::size_t(cells[d]);
        cellOfParticle_[p] = index;
        const std::uint32_t count = list.count[p];
        if (count == 0) continue;
        const auto first = grid.nodeIjk(list.node[p * list.stride]);
        const auto last = grid.nodeIjk(list.node[p * list.stride + count - 1]);
        for (int d = 0; d < Dim; ++d) {
            lo[d] = std::min<long>(lo[d], long(first[d] - cell[d]));
            hi[d] = std::max<long>(hi[d], long(last[d] - cell[d]));
        }
    }
    std::size_t colourCount = 1;
    for (int d = 0; d < Dim; ++d) {
        period_[d] = int(hi[d] - lo[d] + 1);
        colourCount *= std::size_t(period_[d]);
    }
    // Stable counting sort by cell.
    cellStart_.assign(cellCount + 1, 0);
    for (std::size_t p = 0; p < n; ++p) ++cellStart_[cellOfParticle_[p] + 1];
    for (std::size_t c = 0; c < cellCount; ++c) cellStart_[c + 1] += cellStart_[c];
    order_.resize(n);
    {
        std::vector<std::size_t> next(cellStart_.begin(), cellStart_.end() - 1);
        for (std::size_t p = 0; p < n; ++p) order_[next[cellOfParticle_[p]]++] = p;
    }
    colourCells_.assign(colourCount, {});
    for (std::size_t c = 0; c < cellCount; ++c) {
        if (cellStart_[c] == cellStart_[c + 1]) continue;
        std::size_t rest = c, colour = 0, stride = 1;
        for (int d = 0; d < Dim; ++d) {
            const std::size_t i = rest % std::size_t(cells[d]);
            rest /= std::size_t(cells[d]);
            colour += (i % std::size_t(period_[d])) * stride;
            stride *= std::size_t(period_[d]);
        }
        colourCells_[colour].push_back(c);
    }
}

template class ParticleColouring<1>;
template class ParticleColouring<2>;
template class ParticleColouring<3>;

}  // namespace mfdyn
