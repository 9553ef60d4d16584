// hexagonal: the 2D triangular (hexagonal close-packed) lattice of nearest-neighbour distance
// Δx = spacing. Rows are Δy = Δx·√3/2 apart, y_j = min + (j + ½)Δy, and every odd row is shifted by
// Δx/2: x_ij = min + (i + ½ + ½·(j mod 2))Δx. Each point stands for the area of its Voronoi cell,
// the regular hexagon of area Δx·Δy = Δx²·√3/2. Every particle then has six neighbours at equal
// distance, which makes SPH sums more isotropic than on a square lattice (doc/methods/sph-impact.md §4: a
// hexagonal lattice is an alternative to the Cartesian one in the uniform-spacing scheme).
// 2D only.
#include "geometry/HexagonalLattice.hpp"

#include <cmath>

namespace mfdyn {

KeywordSchema HexagonalLattice::keywords() {
    return commonKeywords("hexagonal");
}

HexagonalLattice::HexagonalLattice(const Dictionary& dict, int dimension)
    : Lattice(keywords().read(dict), dimension) {
    if (dimension != 2) throw dict.error("type", "the hexagonal lattice is 2D; use hcp in 3D or cubic in 1D");
}

std::array<double, 3> HexagonalLattice::siteCounts(const BoundingBox& box) const {
    const double dy = spacing() * std::sqrt(3.0) / 2;
    return {rowCount(box.max[0] - box.min[0], spacing()), rowCount(box.max[1] - box.min[1], dy), 1};
}

std::vector<double> HexagonalLattice::sites(const BoundingBox& box) const {
    const double dx = spacing();
    const double dy = dx * std::sqrt(3.0) / 2;
    const auto count = checkedSiteCounts(box);
    const long columns = count[0], rows = count[1];
    std::vector<double> out;
    out.reserve(std::size_t(rows * columns) * 2);
    for (long j = 0; j < rows; ++j)
        for (long i = 0; i < columns; ++i) {
            out.push_back(box.min[0] + (double(i) + 0.5 + 0.5 * double(j % 2)) * dx);
            out.push_back(box.min[1] + (double(j) + 0.5) * dy);
        }
    return out;
}

double HexagonalLattice::pointVolume() const {
    return spacing() * spacing() * std::sqrt(3.0) / 2;
}

MFDYN_REGISTER(Lattice, HexagonalLattice, "hexagonal",
               "2D triangular lattice, rows √3/2 spacing apart, odd rows offset");

}  // namespace mfdyn
