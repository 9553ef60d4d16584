#include "particles/ParticleSetBase.hpp"

namespace mfdyn {

ParticleSetBase::~ParticleSetBase() = default;

std::vector<std::size_t> ParticleSetBase::regionCounts() const {
    const auto& region = requireField<std::int64_t>("region");
    std::vector<std::size_t> counts(regionNames.size(), 0);
    for (std::int64_t r : region) {
        if (r < 0) throw Error("particle region id " + std::to_string(r) + " is negative");
        if (std::size_t(r) >= counts.size()) counts.resize(std::size_t(r) + 1, 0);
        ++counts[std::size_t(r)];
    }
    return counts;
}

}  // namespace mfdyn
