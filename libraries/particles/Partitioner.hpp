#pragma once
// Which rank owns which part of space: Zoltan's geometric partitioners over the particles'
// positions, weighted by each particle's cost (issue 21). Two methods, by name in
// system/decomposeParDict (`method`):
//   rcb   recursive coordinate bisection (Berger & Bokhari 1987): axis-aligned boxes, one per
//         rank, cut at the weighted median of the longest extent. Boxes keep halos thin and
//         make "which ranks does this support box touch" exact (Zoltan_LB_Box_Assign).
//   hsfc  Hilbert space-filling curve: the curve cut into equal-weight pieces; faster to
//         recompute, less regular surfaces (more halo per particle).
// Both keep their cuts (KEEP_CUTS) so that any point, and any box, can be assigned to its
// ranks after the partition: the migration of particles that moved, and the halo of each.
// The only translation unit with Zoltan (Partitioner.cpp); a serial build assigns everything
// to rank 0.
#include <array>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace mfdyn {

class Partitioner {
public:
    // `method` one of methods(); InputError otherwise (the caller names the file).
    Partitioner(const std::string& method, int dimension, double imbalanceTolerance);
    ~Partitioner();
    Partitioner(const Partitioner&) = delete;
    Partitioner& operator=(const Partitioner&) = delete;

    static const std::vector<std::string>& methods();
    const std::string& method() const { return method_; }

    // Collective. This rank's particles (positions, dimension() doubles each; weights; global
    // ids), returns each one's new rank. Keeps the cuts for owner() and ranksTouching().
    std::vector<int> partition(const std::vector<double>& coordinates, const std::vector<double>& weights,
                               const std::vector<std::int64_t>& globalIds);
    bool partitioned() const { return partitioned_; }
    // The rank whose part contains x (dimension() values), after partition().
    int owner(const double* x) const;
    // Every rank whose part meets the box [lo, hi], in ascending order.
    std::vector<int> ranksTouching(const double* lo, const double* hi) const;

private:
    std::string method_;
    int dimension_;
    bool partitioned_ = false;
    struct Zoltan;  // the Zoltan_Struct and the callbacks' data, in Partitioner.cpp only
    std::unique_ptr<Zoltan> zoltan_;
};

}  // namespace mfdyn
