// Tile bucketing and colouring of the particle-to-grid sums: see ParticleColouring.hpp.
#include "mpm/ParticleColouring.hpp"

#include <algorithm>
#include <cmath>

namespace mfdyn {

template <int Dim>
void ParticleColouring<Dim>::build(const CartesianGrid<Dim>& grid, std::span<const Vector<Dim>> x,
                                   const ParticleNodeList<Dim>& list, std::span<const std::int64_t> globalId) {
    const std::size_t n = x.size();
    const auto& cells = grid.cells();
    stride_ = std::max<std::size_t>(1, list.stride);
    // Node layers per axis of one particle (the list is a tensor-product block), plus one for the
    // cell's width: the tile must be at least that wide.
    const int layers = int(std::lround(std::pow(double(stride_), 1.0 / Dim)));
    const int width = std::max(8, layers + 1);
    std::array<std::size_t, Dim> tiles;
    std::size_t tileCount = 1;
    for (int d = 0; d < Dim; ++d) {
        period_[d] = width;
        tiles[d] = (std::size_t(cells[d]) + std::size_t(width) - 1) / std::size_t(width);
        tileCount *= tiles[d];
    }
    tileOfParticle_.resize(n);
    tileStart_.assign(tileCount + 1, 0);
    for (std::size_t p = 0; p < n; ++p) {
        const auto cell = grid.cellOf(x[p]);
        std::size_t index = 0, stride = 1;
        for (int d = 0; d < Dim; ++d) {
            index += std::size_t(cell[d]) / std::size_t(width) * stride;
            stride *= tiles[d];
        }
        tileOfParticle_[p] = index;
        ++tileStart_[index + 1];
    }
    // Stable counting sort by tile.
    for (std::size_t t = 0; t < tileCount; ++t) tileStart_[t + 1] += tileStart_[t];
    order_.resize(n);
    {
        std::vector<std::size_t> next(tileStart_.begin(), tileStart_.end() - 1);
        for (std::size_t p = 0; p < n; ++p) order_[next[tileOfParticle_[p]]++] = p;
    }
    // Each tile's particles in global-id order (already so when the indices follow the ids).
    if (globalId.size() >= n) {
        auto byId = [&](std::size_t a, std::size_t b) { return globalId[a] < globalId[b]; };
        parallelFor(tileCount, [&](std::size_t t) {
            const auto first = order_.begin() + std::ptrdiff_t(tileStart_[t]);
            const auto last = order_.begin() + std::ptrdiff_t(tileStart_[t + 1]);
            if (!std::is_sorted(first, last, byId)) std::sort(first, last, byId);
        });
    }
    colourTiles_.assign(std::size_t(1) << Dim, {});
    for (std::size_t t = 0; t < tileCount; ++t) {
        if (tileStart_[t] == tileStart_[t + 1]) continue;
        std::size_t rest = t, colour = 0;
        for (int d = 0; d < Dim; ++d) {
            colour |= ((rest % tiles[d]) & 1u) << d;
            rest /= tiles[d];
        }
        colourTiles_[colour].push_back(t);
    }
}

template class ParticleColouring<1>;
template class ParticleColouring<2>;
template class ParticleColouring<3>;

}  // namespace mfdyn
