// hcp: the 3D hexagonal close-packed lattice of nearest-neighbour distance Δx = spacing (e.g.
// Kittel, Introduction to Solid State Physics, ch. 1: ABAB stacking of triangular layers).
// Each layer is the 2D hexagonal lattice (rows Δy = Δx·√3/2 apart, odd rows shifted Δx/2);
// layers are Δz = Δx·√(2/3) apart, and every odd (B) layer is shifted by (Δx/2, Δy/3) so that its
// points sit over the centroids of the A layer's triangles. Each point has 12 neighbours at Δx
// and stands for the volume Δx·Δy·Δz = Δx³/√2 (packing density π/(3√2) for spheres of diameter Δx).
// 3D only.
#include "geometry/HcpLattice.hpp"

#include <cmath>

namespace mfdyn {

KeywordSchema HcpLattice::keywords() {
    return commonKeywords("hcp");
}

HcpLattice::HcpLattice(const Dictionary& dict, int dimension) : Lattice(keywords().read(dict), dimension) {
    if (dimension != 3) throw dict.error("type", "the hcp lattice is 3D; use hexagonal in 2D or cubic in 1D");
}

std::array<double, 3> HcpLattice::siteCounts(const BoundingBox& box) const {
    const double dx = spacing();
    const double dy = dx * std::sqrt(3.0) / 2;
    const double dz = dx * std::sqrt(2.0 / 3.0);
    return {rowCount(box.max[0] - box.min[0], dx), rowCount(box.max[1] - box.min[1], dy),
            rowCount(box.max[2] - box.min[2], dz)};
}

std::vector<double> HcpLattice::sites(const BoundingBox& box) const {
    const double dx = spacing();
    const double dy = dx * std::sqrt(3.0) / 2;
    const double dz = dx * std::sqrt(2.0 / 3.0);
    const auto [nx, ny, nz] = checkedSiteCounts(box);
    std::vector<double> out;
    out.reserve(std::size_t(nx * ny * nz) * 3);
    for (long k = 0; k < nz; ++k) {
        const double layerX = (k % 2) * 0.5 * dx, layerY = (k % 2) * dy / 3;
        for (long j = 0; j < ny; ++j)
            for (long i = 0; i < nx; ++i) {
                out.push_back(box.min[0] + (double(i) + 0.5 + 0.5 * double(j % 2)) * dx + layerX);
                out.push_back(box.min[1] + (double(j) + 0.5) * dy + layerY);
                out.push_back(box.min[2] + (double(k) + 0.5) * dz);
            }
    }
    return out;
}

double HcpLattice::pointVolume() const {
    return std::pow(spacing(), 3) / std::sqrt(2.0);
}

MFDYN_REGISTER(Lattice, HcpLattice, "hcp",
               "3D hexagonal close-packed lattice (ABAB layers), volume spacing³/√2 per point");

}  // namespace mfdyn
