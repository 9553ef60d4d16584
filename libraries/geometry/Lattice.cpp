#include "geometry/Lattice.hpp"

#include <algorithm>
#include <cmath>
#include <random>
#include <sstream>

namespace mfdyn {

KeywordSchema Lattice::commonKeywords(const char* type, bool spacingOptional) {
    KeywordSchema schema(familyName, type);
    schema.scalar("spacing", "m", "distance between neighbouring lattice points").greaterThan(0);
    if (spacingOptional) schema.optional();
    return schema.scalar("jitter", "-", "random displacement of each coordinate, a fraction of the spacing")
        .atLeast(0)
        .lessThan(0.5)
        .orDefault(0.0)
        .integer("seed", "-", "seed of the jitter's random numbers (std::mt19937_64)")
        .atLeast(0)
        .orDefault(1);
}

Lattice::Lattice(const KeywordValues& v, int dimension)
    : dimension_(dimension),
      spacing_(v.optionalScalar("spacing").value_or(0.0)),
      jitter_(v.scalar("jitter")),
      seed_(std::uint64_t(v.integer("seed"))) {}

Lattice::~Lattice() = default;

std::vector<double> Lattice::points(const BoundingBox& box) const {
    std::vector<double> p = sites(box);
    if (jitter_ > 0) {
        // One engine per call, seeded afresh, so the same box gives the same points every time.
        std::mt19937_64 engine(seed_);
        std::uniform_real_distribution<double> uniform(-jitter_ * spacing_, jitter_ * spacing_);
        for (double& x : p) x += uniform(engine);
    }
    return p;
}

double Lattice::rowCount(double length, double step) {
    return std::max(1.0, std::ceil(length / step - 1e-9));
}

double Lattice::pointCount(const BoundingBox& box) const {
    const auto n = siteCounts(box);
    return n[0] * n[1] * n[2];
}

std::array<long, 3> Lattice::checkedSiteCounts(const BoundingBox& box) const {
    const auto n = siteCounts(box);
    const double total = n[0] * n[1] * n[2];
    if (!(total <= 9007199254740992.0)) {  // 2^53; also catches inf and NaN
        std::ostringstream message;
        message << "a lattice of spacing " << spacing_ << " m over the box from (";
        for (int d = 0; d < dimension_; ++d) message << (d ? " " : "") << box.min[d];
        message << ") to (";
        for (int d = 0; d < dimension_; ++d) message << (d ? " " : "") << box.max[d];
        message << ") would have " << total << " points; give a larger spacing";
        throw InputError(message.str());
    }
    return {long(n[0]), long(n[1]), long(n[2])};
}

std::vector<double> Lattice::pointVolumes(const BoundingBox&, const std::vector<double>& points) const {
    return std::vector<double>(points.size() / std::size_t(dimension_), pointVolume());
}

}  // namespace mfdyn
