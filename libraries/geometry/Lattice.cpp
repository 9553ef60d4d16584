#include "geometry/Lattice.hpp"

#include <random>

namespace mfdyn {

Lattice::Lattice(const Dictionary& dict, int dimension)
    : Lattice(dict, dimension, dict.get<double>("spacing")) {
    if (!(spacing() > 0)) throw dict.error("spacing", "spacing must be positive");
}

Lattice::Lattice(const Dictionary& dict, int dimension, double spacing)
    : dimension_(dimension),
      spacing_(spacing),
      jitter_(dict.getOrDefault<double>("jitter", 0.0)),
      seed_(dict.getOrDefault<unsigned long>("seed", 1UL)) {
    if (!(jitter_ >= 0 && jitter_ < 0.5))
        throw dict.error("jitter",
                         "jitter is a fraction of the spacing in [0, 0.5), found " + std::to_string(jitter_));
}

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

std::vector<double> Lattice::pointVolumes(const BoundingBox&, const std::vector<double>& points) const {
    return std::vector<double>(points.size() / std::size_t(dimension_), pointVolume());
}

}  // namespace mfdyn
