#include "particles/ParticleSetBase.hpp"

#include <algorithm>

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

void ParticleSetBase::refuseWithGhosts(const char* operation) const {
    if (!ghostSource_.empty())
        throw Error(std::string(operation) + ": the particle set holds " +
                    std::to_string(ghostSource_.size()) + " ghosts; clear them first (clearGhosts())");
}

std::int64_t ParticleSetBase::nextGlobalId() const {
    const auto& id = requireField<std::int64_t>("globalId");
    std::int64_t next = nextIdFloor_;
    for (std::size_t i = 0, n = ownedCount(); i < n; ++i) next = std::max(next, id[i] + 1);
    return next;
}

void ParticleSetBase::reserveGlobalIdsBelow(std::int64_t next) {
    nextIdFloor_ = std::max(nextIdFloor_, next);
}

std::size_t ParticleSetBase::append(std::size_t n) {
    refuseWithGhosts("append");
    const std::int64_t next = nextGlobalId();
    const std::size_t first = FieldStore::append(n);
    ++ownedVersion_;
    auto& id = requireField<std::int64_t>("globalId");
    for (std::size_t k = 0; k < n; ++k) id[first + k] = next + std::int64_t(k);
    nextIdFloor_ = next + std::int64_t(n);
    return first;
}

void ParticleSetBase::keep(const std::vector<std::size_t>& indices) {
    refuseWithGhosts("keep");
    // Remember the removed particles' ids as issued: the highest may be among them.
    const std::int64_t next = nextGlobalId();
    FieldStore::keep(indices);
    ++ownedVersion_;
    nextIdFloor_ = next;
}

void ParticleSetBase::resize(std::size_t n) {
    // A resize that drops particles loses their ids too: keep the next id above them. (The sph
    // solver's own ghosts, made by resize before the owned/ghost range existed, are copies of
    // real ids and leave it unchanged.)
    if (n < size()) nextIdFloor_ = nextGlobalId();
    refuseWithGhosts("resize");
    FieldStore::resize(n);
    ++ownedVersion_;
}

void ParticleSetBase::reorder(const std::vector<std::size_t>& order) {
    refuseWithGhosts("reorder");
    FieldStore::reorder(order);
    ++ownedVersion_;
}

void ParticleSetBase::clearGhosts() {
    if (ghostSource_.empty()) return;
    const std::size_t owned = ownedCount();
    ghostSource_.clear();
    halo_ = nullptr, haloBegin_ = 0, haloCount_ = 0;
    FieldStore::resize(owned);
}

std::size_t ParticleSetBase::appendHalo(std::size_t n, const HaloExchange& exchange) {
    if (!ghostSource_.empty())
        throw Error("appendHalo: the halo comes first among the ghosts; " + std::to_string(ghostSource_.size()) +
                    " ghosts are there already");
    const std::size_t first = size();
    FieldStore::resize(first + n);
    for (std::size_t k = 0; k < n; ++k) ghostSource_.push_back(first + k);
    halo_ = &exchange, haloBegin_ = first, haloCount_ = n;
    return first;
}

std::size_t ParticleSetBase::appendMigrated(std::size_t n) {
    refuseWithGhosts("appendMigrated");
    const std::size_t first = FieldStore::append(n);
    ++ownedVersion_;
    return first;
}

std::size_t ParticleSetBase::appendGhostCopies(const std::vector<std::size_t>& source) {
    const std::size_t owned = ownedCount();
    for (std::size_t s : source)
        if (s >= owned && !(s >= haloBegin_ && s < haloBegin_ + haloCount_))
            throw Error("ghost source " + std::to_string(s) + " is not an owned or halo particle (there are " +
                        std::to_string(owned) + ")");
    const std::size_t first = size();
    FieldStore::resize(first + source.size());
    for (const auto& f : fields()) f->copyElements(source, first);
    ghostSource_.insert(ghostSource_.end(), source.begin(), source.end());
    return first;
}

}  // namespace mfdyn
