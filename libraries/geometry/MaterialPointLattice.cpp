// materialPoints: material points for the material point method, as the generators of the thesis
// (doc/methods/mpm.md section 3, "Containers"; section 8 item 4): the bounding box [min, max] of
// the shape is cut into n_d sub-cells per direction, of size h_d = L_d / n_d, and
//   - pattern centre (pattern 1): one point at each sub-cell centre, x = min + (i + 1/2) h;
//   - pattern gauss  (pattern 2): the 2 x 2 (x 2) Gauss points of each sub-cell,
//                                 x = min + (i + 1/2) h -+ h / (2 sqrt 3);
// points inside the shape are kept. particleGen then gives every kept point of the region the
// volume V_p = (the shape's exact volume) / N (Lattice::volumeFromShape()), so that the body's
// mass is rho x its exact volume whatever the count; a shape without a closed-form volume (a CSG
// combination, an STL surface) keeps the sub-cell volume per point, with a log line saying so.
// The counts of the note: a disc of radius 0.2, pattern gauss, cells (10 10): 316 points
// (cells (31 31): 3016); the equilateral triangle of side 0.2, apex up, cells (10 10): 200; the
// spring's box 0.02 x 0.2 from (x0 0.8), pattern centre, cells (1 10): y = 0.81 ... 0.99.
// A k x k (x k) set of points per grid cell is `pattern centre` with k times the grid's cells.
//   - `cells (n1 n2 n3);` the sub-cells per direction (whole numbers from 1);
//   - `spacing h;` the nominal sub-cell size: n_d = round(L_d / h), at least 1, h_d = L_d / n_d
//     (adjusted to fit the box; the adjusted sizes are logged).
// Points are ordered x fastest, then y, then z (row by row of points, not sub-cell by sub-cell).
// `jitter` moves each coordinate by up to jitter x the distance between neighbouring points of
// that direction (h_d for centre, h_d / sqrt 3 between the two Gauss points of a sub-cell).
#include "geometry/MaterialPointLattice.hpp"

#include "core/Log.hpp"

#include <cmath>
#include <random>
#include <sstream>

namespace mfdyn {

KeywordSchema MaterialPointLattice::keywords() {
    // The lattice family's spacing, jitter and seed (Lattice reads them by these names), with the
    // meanings they have here: spacing is the sub-cell size, jitter a fraction of the distance
    // between neighbouring points.
    return KeywordSchema(familyName, "materialPoints")
        .scalar("spacing", "m",
                "the sub-cell size (instead of cells), adjusted to a whole number of sub-cells of the "
                "bounding box")
        .greaterThan(0)
        .optional()
        .scalar("jitter", "-",
                "random displacement of each coordinate, a fraction of the distance between points")
        .atLeast(0)
        .lessThan(0.5)
        .orDefault(0.0)
        .integer("seed", "-", "seed of the jitter's random numbers (std::mt19937_64)")
        .atLeast(0)
        .orDefault(1)
        .vector("cells", "-", "sub-cells per direction over the shape's bounding box (instead of spacing)")
        .optional()
        .example("(10 10)")
        .word(
            "pattern", {"centre", "gauss"},
            "points per sub-cell: its centre (the thesis's pattern 1) or its 2^dim Gauss points (pattern 2)")
        .orDefault("centre");
}

MaterialPointLattice::MaterialPointLattice(const Dictionary& dict, int dimension)
    : MaterialPointLattice(dict, keywords().read(dict), dimension) {}

MaterialPointLattice::MaterialPointLattice(const Dictionary& dict, const KeywordValues& v, int dimension)
    : Lattice(v, dimension), gauss_(v.word("pattern") == "gauss"), where_(dict.scope()) {
    if (v.given("spacing") == v.given("cells"))
        throw InputError(dict.where(), dict.scope(),
                         "the materialPoints lattice needs exactly one of `cells (n1 n2 n3);` (sub-cells per "
                         "direction over the shape's bounding box) and `spacing h;` [m] (the sub-cell size)");
    if (v.given("cells")) {
        const auto& n = v.vector("cells");
        if (int(n.size()) < dimension)
            throw dict.error("cells",
                             "expected " + std::to_string(dimension) + " sub-cell counts, one per direction");
        for (std::size_t d = 0; d < n.size(); ++d) {
            const bool used = int(d) < dimension;
            // At most 2^31 per direction: beyond it nothing could be allocated, below it the
            // conversion to long is exact.
            if (used && !(n[d] >= 1 && n[d] == std::floor(n[d]) && n[d] <= 2147483648.0))
                throw dict.error("cells", "sub-cell counts are whole numbers from 1 to 2^31, found " +
                                              std::to_string(n[d]) + " in direction " +
                                              std::to_string(d + 1));
            if (!used && n[d] != 1 && n[d] != 0)
                throw dict.error("cells", "direction " + std::to_string(d + 1) + " is not used in a " +
                                              std::to_string(dimension) + "D case: give 1 or leave it out");
            if (used) cells_[d] = long(n[d]);
        }
    }
}

std::array<double, 3> MaterialPointLattice::siteCounts(const BoundingBox& box) const {
    std::array<double, 3> n{1, 1, 1};
    for (int d = 0; d < dimension(); ++d) {
        const double c = cells_[d] > 0 ? double(cells_[d])
                                       : std::max(1.0, std::round((box.max[d] - box.min[d]) / spacing()));
        n[d] = gauss_ ? 2 * c : c;
    }
    return n;
}

std::array<long, 3> MaterialPointLattice::cells(const BoundingBox& box) const {
    auto n = checkedSiteCounts(box);
    if (gauss_)
        for (int d = 0; d < dimension(); ++d) n[d] /= 2;
    return n;
}

std::array<double, 3> MaterialPointLattice::cellSizes(const BoundingBox& box) const {
    const auto n = cells(box);
    std::array<double, 3> h{0, 0, 0};
    for (int d = 0; d < dimension(); ++d) h[d] = (box.max[d] - box.min[d]) / double(n[d]);
    return h;
}

std::vector<double> MaterialPointLattice::sites(const BoundingBox& box) const {
    const int dim = dimension();
    const auto n = cells(box);
    const auto h = cellSizes(box);
    std::ostringstream message;
    message.precision(10);
    message << (where_.empty() ? "" : where_ + ": ") << "materialPoints lattice of";
    for (int d = 0; d < dim; ++d) message << (d ? " x " : " ") << n[d];
    message << " sub-cells of (";
    for (int d = 0; d < dim; ++d) message << (d ? " " : "") << h[d];
    message << ") m, " << (gauss_ ? "2^" + std::to_string(dim) + " Gauss points" : std::string("1 point"))
            << " each";
    Log::info(message.str());

    // The coordinates along each direction, ascending: sub-cell centres, or the two Gauss points
    // of each sub-cell at -+ h / (2 sqrt 3) of its centre.
    const double offset = 0.5 / std::sqrt(3.0);
    std::array<std::vector<double>, 3> axis;
    for (int d = 0; d < 3; ++d) {
        if (d >= dim) {
            axis[d] = {0.0};
            continue;
        }
        for (long i = 0; i < n[d]; ++i) {
            const double centre = box.min[d] + (double(i) + 0.5) * h[d];
            if (gauss_) {
                axis[d].push_back(centre - offset * h[d]);
                axis[d].push_back(centre + offset * h[d]);
            } else {
                axis[d].push_back(centre);
            }
        }
    }
    std::vector<double> out;
    out.reserve(axis[0].size() * axis[1].size() * axis[2].size() * std::size_t(dim));
    for (double z : axis[2])
        for (double y : axis[1])
            for (double x : axis[0]) {
                const double p[3] = {x, y, z};
                for (int d = 0; d < dim; ++d) out.push_back(p[d]);
            }
    return out;
}

std::vector<double> MaterialPointLattice::points(const BoundingBox& box) const {
    std::vector<double> p = sites(box);
    if (jitter() > 0) {
        const int dim = dimension();
        const auto h = cellSizes(box);
        // As Lattice::points: one engine per call, one draw per coordinate in lattice order.
        std::mt19937_64 engine(seed());
        std::uniform_real_distribution<double> uniform(-jitter(), jitter());
        for (std::size_t c = 0; c < p.size(); ++c) {
            const int d = int(c % std::size_t(dim));
            p[c] += uniform(engine) * (gauss_ ? h[d] / std::sqrt(3.0) : h[d]);
        }
    }
    return p;
}

double MaterialPointLattice::pointVolume() const {
    // Only `mass equalMass` asks for it before the box is known; it would scale the spacing to a
    // mass per point that the exact-volume share then replaces.
    throw InputError(where_ +
                     ": `mass equalMass` does not apply to the materialPoints lattice: each point's volume "
                     "is the shape's exact volume / N (mass = density x that); use `mass uniformSpacing`");
}

std::vector<double> MaterialPointLattice::pointVolumes(const BoundingBox& box,
                                                       const std::vector<double>& points) const {
    const int dim = dimension();
    const auto h = cellSizes(box);
    double cell = 1;
    for (int d = 0; d < dim; ++d) cell *= h[d];
    if (gauss_) cell /= double(1 << dim);
    return std::vector<double>(points.size() / std::size_t(dim), cell);
}

MFDYN_REGISTER(
    Lattice, MaterialPointLattice, "materialPoints",
    "MPM material points: sub-cell centres or 2^dim Gauss points, volume = exact shape volume / N");

}  // namespace mfdyn
