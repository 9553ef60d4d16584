// CellBuckets (CellBuckets.hpp): a counting sort of the fluid particles by (cell, material).
// O(particles + cells x materials) per call; the per-particle key is computed in parallel, the
// count and fill are single ordered passes (a few ns a particle, beside the stress update's
// equation-of-state call per particle), which is what makes the order deterministic.
#include "mpm/pressureSmoothing/CellBuckets.hpp"

#include "core/Error.hpp"
#include "core/Parallel.hpp"

#include <algorithm>
#include <limits>

namespace mfdyn {

template <int Dim>
void CellBuckets<Dim>::build(const CartesianGrid<Dim>& grid, const PressureSmoothingFields<Dim>& f) {
    constexpr std::size_t none = std::numeric_limits<std::size_t>::max();
    const std::size_t n = f.position.size();
    if (n > std::numeric_limits<std::uint32_t>::max())
        throw Error("pressureSmoothing: more than 2^32 particles on one process");
    std::int64_t largest = -1;
    for (std::size_t p = 0; p < n; ++p) largest = std::max(largest, f.material[p]);
    const std::size_t materials = std::size_t(largest + 1);
    // The callback once per material, not per particle.
    fluid_.assign(materials, 0);
    for (std::size_t k = 0; k < materials; ++k) fluid_[k] = f.smoothed(std::int64_t(k)) ? 1 : 0;
    const auto& cells = grid.cells();
    const std::size_t keys = grid.cellCount() * materials;
    key_.resize(n);
    parallelFor(n, [&](std::size_t p) {
        const std::int64_t k = f.material[p];
        if (!fluid_[std::size_t(k)]) {
            key_[p] = none;
            return;
        }
        const auto ijk = grid.cellOf(f.position[p]);
        std::size_t cell = 0;
        for (int d = Dim - 1; d >= 0; --d) cell = cell * std::size_t(cells[d]) + std::size_t(ijk[d]);
        key_[p] = cell * materials + std::size_t(k);
    });
    start_.assign(keys + 1, 0);
    for (std::size_t p = 0; p < n; ++p)
        if (key_[p] != none) ++start_[key_[p] + 1];
    nonEmpty_.clear();
    for (std::size_t k = 0; k < keys; ++k) {
        if (start_[k + 1] > 0) nonEmpty_.push_back(k);
        start_[k + 1] += start_[k];
    }
    order_.resize(start_[keys]);
    // Fill in increasing particle index: next[key] walks from start_[key] (the start_ array is
    // restored after by shifting back one key).
    for (std::size_t p = 0; p < n; ++p)
        if (key_[p] != none) order_[start_[key_[p]]++] = std::uint32_t(p);
    for (std::size_t k = keys; k > 0; --k) start_[k] = start_[k - 1];
    start_[0] = 0;
    // In global-id order when the ids are given (already so where the indices follow the ids).
    if (f.globalId.size() >= n) {
        auto byId = [&](std::uint32_t a, std::uint32_t b) { return f.globalId[a] < f.globalId[b]; };
        parallelFor(nonEmpty_.size(), [&](std::size_t b) {
            const auto first = order_.begin() + std::ptrdiff_t(start_[nonEmpty_[b]]);
            const auto last = order_.begin() + std::ptrdiff_t(start_[nonEmpty_[b] + 1]);
            if (!std::is_sorted(first, last, byId)) std::sort(first, last, byId);
        });
    }
}

template class CellBuckets<1>;
template class CellBuckets<2>;
template class CellBuckets<3>;

}  // namespace mfdyn
