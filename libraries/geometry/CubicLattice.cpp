// cubic: cell-centred points x = min + (i + ½) Δx in each direction, Δx = spacing; each point
// stands for the volume Δx^d of its cell, so a box that is a whole number of cells long is
// filled with exactly its volume.
#include "geometry/CubicLattice.hpp"

#include <cmath>

namespace mfdyn {

KeywordSchema CubicLattice::keywords() {
    return commonKeywords("cubic");
}

CubicLattice::CubicLattice(const Dictionary& dict, int dimension)
    : Lattice(keywords().read(dict), dimension) {}

std::array<double, 3> CubicLattice::siteCounts(const BoundingBox& box) const {
    std::array<double, 3> count{1, 1, 1};
    for (int d = 0; d < dimension(); ++d) count[d] = rowCount(box.max[d] - box.min[d], spacing());
    return count;
}

std::vector<double> CubicLattice::sites(const BoundingBox& box) const {
    const int dim = dimension();
    const double dx = spacing();
    const std::array<long, 3> count = checkedSiteCounts(box);
    std::vector<double> out;
    out.reserve(std::size_t(count[0] * count[1] * count[2]) * dim);
    for (long k = 0; k < count[2]; ++k)
        for (long j = 0; j < count[1]; ++j)
            for (long i = 0; i < count[0]; ++i) {
                const long index[3] = {i, j, k};
                for (int d = 0; d < dim; ++d) out.push_back(box.min[d] + (double(index[d]) + 0.5) * dx);
            }
    return out;
}

double CubicLattice::pointVolume() const {
    return std::pow(spacing(), dimension());
}

MFDYN_REGISTER(Lattice, CubicLattice, "cubic", "cell-centred square/cubic lattice of the given spacing");

}  // namespace mfdyn
