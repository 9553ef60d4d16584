#pragma once
// The fluid particles of PressureSmoothingFields grouped by grid cell and material, for the cell
// averages of cellPressure and cellJacobian: a counting sort of the particles by the key
// cell * materials + material. Deterministic: each bucket lists its particles in increasing index
// (the fill is one ordered pass), or in increasing global id when the fields give the ids, so the
// sums over a bucket are the same for any thread count (and any number of ranks).
// The buffers are kept between steps (no allocation once the sizes are reached).
#include "grid/CartesianGrid.hpp"
#include "mpm/PressureSmoothing.hpp"

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace mfdyn {

template <int Dim>
class CellBuckets {
public:
    // Sorts the particles of fluid materials (fields.smoothed) by cell and material.
    void build(const CartesianGrid<Dim>& grid, const PressureSmoothingFields<Dim>& fields);
    // Non-empty buckets, each a run of particle indices.
    std::size_t count() const { return nonEmpty_.size(); }
    std::span<const std::uint32_t> members(std::size_t b) const {
        const std::size_t key = nonEmpty_[b];
        return {order_.data() + start_[key], order_.data() + start_[key + 1]};
    }

private:
    std::vector<std::size_t> key_;        // per particle; npos for a particle not smoothed
    std::vector<std::size_t> start_;      // per key + 1: the start of its run in order_
    std::vector<std::uint32_t> order_;    // particle indices sorted by key, then index
    std::vector<std::size_t> nonEmpty_;   // keys with at least one particle, increasing
    std::vector<char> fluid_;             // per material: smoothed
};

extern template class CellBuckets<1>;
extern template class CellBuckets<2>;
extern template class CellBuckets<3>;

}  // namespace mfdyn
