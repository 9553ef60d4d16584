// nodal: the Cartesian lattice that includes the boundary faces, used by total-Lagrangian SPH
// (Lee, Gil, Greto, Karim & Bonet 2016, doc/methods/tl-jst-sph.md 2.1 "Layout"): along each direction d of
// the bounding box [min, max] there are n_d nodes
//     x_i = min_d + i Δx_d,  i = 0 … n_d − 1,  Δx_d = L_d / (n_d − 1),  L_d = max_d − min_d,
// the last one placed at max_d exactly (no round-off outside the box). The paper's examples:
// 31×11×6 nodes on 0.03×0.01×0.005 (Δx = 1 mm), 21×11×3 on 1×0.5×0.1 (Δx = 0.05).
//   - `spacing s;`   n_d = round(L_d/s) + 1 (at least 2), so Δx_d is s adjusted to fit L_d;
//   - `points (n1 n2 n3);`  n_d given (at least 2 each), Δx_d = L_d/(n_d − 1).
// The adjusted spacings are logged.
//
// Volumes (doc/methods/tl-jst-sph.md 2.1 "Particle volume", recommendation [R]; not stated in the paper):
// the tributary (dual-cell) volume V = Π_d Δx_d, halved once for each face of the box the node
// lies on (an edge node in 3D gets Δx³/4, a corner node Δx³/8), so that Σ V = |box| exactly up
// to round-off.
//
// Restrictions:
//  - Meant for a box shape, or a union of boxes that fills its bounding box. For any other shape
//    the volumes are still those of the lattice over the bounding box (a node near a curved
//    surface keeps the full Δx^d), and a node on the shape's surface is kept only if the
//    shape's inside test accepts it (box: faces included).
//  - `jitter` moves only the coordinates of a node that are not on a face (a face node moves
//    along its face, an interior node in every direction), so boundary nodes stay on their faces.
//  - `mass equalMass` needs `spacing` (with `points` the volume per point depends on the box).
#include "geometry/NodalLattice.hpp"

#include "core/Log.hpp"

#include <cmath>
#include <random>
#include <sstream>

namespace mfdyn {

KeywordSchema NodalLattice::keywords() {
    return commonKeywords("nodal", true)
        .append(KeywordSchema(familyName, "nodal")
                    .vector("points", "-", "nodes per direction, both faces included (instead of spacing)")
                    .optional());
}

NodalLattice::NodalLattice(const Dictionary& dict, int dimension)
    : NodalLattice(dict, keywords().read(dict), dimension) {}

NodalLattice::NodalLattice(const Dictionary& dict, const KeywordValues& v, int dimension)
    : Lattice(v, dimension), where_(dict.scope()) {
    if (v.given("spacing") == v.given("points"))
        throw InputError(dict.where(), dict.scope(),
                         "the nodal lattice needs exactly one of `spacing s;` [m] and `points (n1 n2 n3);` "
                         "(nodes per direction, faces included)");
    if (v.given("points")) {
        const auto& n = v.vector("points");
        if (int(n.size()) < dimension)
            throw dict.error("points",
                             "expected " + std::to_string(dimension) + " node counts, one per direction");
        for (std::size_t d = 0; d < n.size(); ++d) {
            const bool used = int(d) < dimension;
            // At most 2^31 per direction: a count beyond that could not be allocated anyway, and
            // below it the conversion to long is exact.
            if (used && !(n[d] >= 2 && n[d] == std::floor(n[d]) && n[d] <= 2147483648.0))
                throw dict.error("points",
                                 "node counts are whole numbers from 2 (both faces) to 2^31, found " +
                                     std::to_string(n[d]) + " in direction " + std::to_string(d + 1));
            if (!used && n[d] != 1 && n[d] != 0)
                throw dict.error("points", "direction " + std::to_string(d + 1) + " is not used in a " +
                                               std::to_string(dimension) + "D case: give 1 or leave it out");
            if (used) points_[d] = long(n[d]);
        }
    }
}

std::array<double, 3> NodalLattice::siteCounts(const BoundingBox& box) const {
    std::array<double, 3> n{1, 1, 1};
    for (int d = 0; d < dimension(); ++d)
        n[d] = points_[d] > 0 ? double(points_[d])
                              : std::max(2.0, std::round((box.max[d] - box.min[d]) / spacing()) + 1);
    return n;
}

std::array<long, 3> NodalLattice::counts(const BoundingBox& box) const {
    return checkedSiteCounts(box);
}

std::array<double, 3> NodalLattice::spacings(const BoundingBox& box) const {
    const auto n = counts(box);
    std::array<double, 3> dx{0, 0, 0};
    for (int d = 0; d < dimension(); ++d) dx[d] = (box.max[d] - box.min[d]) / double(n[d] - 1);
    return dx;
}

std::vector<double> NodalLattice::sites(const BoundingBox& box) const {
    const int dim = dimension();
    const auto n = counts(box);
    const auto dx = spacings(box);
    std::ostringstream message;
    message.precision(10);
    message << (where_.empty() ? "" : where_ + ": ") << "nodal lattice of";
    for (int d = 0; d < dim; ++d) message << (d ? " x " : " ") << n[d];
    message << " nodes, spacing (";
    for (int d = 0; d < dim; ++d) message << (d ? " " : "") << dx[d];
    message << ") m";
    Log::info(message.str());

    const auto coordinate = [&](int d, long i) {
        return i == n[d] - 1 ? box.max[d] : box.min[d] + double(i) * dx[d];
    };
    std::vector<double> out;
    out.reserve(std::size_t(n[0] * n[1] * n[2]) * std::size_t(dim));
    for (long k = 0; k < n[2]; ++k)
        for (long j = 0; j < n[1]; ++j)
            for (long i = 0; i < n[0]; ++i) {
                const long index[3] = {i, j, k};
                for (int d = 0; d < dim; ++d) out.push_back(coordinate(d, index[d]));
            }
    return out;
}

std::vector<double> NodalLattice::points(const BoundingBox& box) const {
    std::vector<double> p = sites(box);
    if (jitter() > 0) {
        const int dim = dimension();
        const auto dx = spacings(box);
        // As Lattice::points: one engine per call, one draw per coordinate in lattice order (also
        // for the coordinates left in place), so the points do not depend on anything but the box.
        std::mt19937_64 engine(seed());
        std::uniform_real_distribution<double> uniform(-jitter(), jitter());
        for (std::size_t c = 0; c < p.size(); ++c) {
            const int d = int(c % std::size_t(dim));
            const double shift = uniform(engine) * dx[d];
            if (p[c] != box.min[d] && p[c] != box.max[d]) p[c] += shift;
        }
    }
    return p;
}

double NodalLattice::pointVolume() const {
    if (!(spacing() > 0))
        throw InputError(where_ +
                         ": a nodal lattice given by `points` has no volume per point until the box "
                         "is known; give `spacing` instead (needed by `mass equalMass`)");
    return std::pow(spacing(), dimension());
}

std::vector<double> NodalLattice::pointVolumes(const BoundingBox& box,
                                               const std::vector<double>& points) const {
    const int dim = dimension();
    const auto dx = spacings(box);
    double cell = 1;
    for (int d = 0; d < dim; ++d) cell *= dx[d];
    std::vector<double> v(points.size() / std::size_t(dim), cell);
    for (std::size_t p = 0; p < v.size(); ++p)
        for (int d = 0; d < dim; ++d) {
            const double x = points[p * std::size_t(dim) + std::size_t(d)];
            if (x == box.min[d] || x == box.max[d]) v[p] *= 0.5;
        }
    return v;
}

MFDYN_REGISTER(Lattice, NodalLattice, "nodal",
               "Cartesian lattice with nodes on the box faces, tributary volumes (total-Lagrangian SPH)");

}  // namespace mfdyn
