#include "boundaryConditions/BoundaryCondition.hpp"

#include "core/Parallel.hpp"

#include <sstream>
#include <unordered_map>

namespace mfdyn {

namespace {

// The last component of "boundaryConditions/chamber".
std::string lastScope(const std::string& scope) {
    const auto slash = scope.find_last_of('/');
    return slash == std::string::npos ? scope : scope.substr(slash + 1);
}

}  // namespace

KeywordSchema commonBoundaryConditionKeywords() {
    return KeywordSchema("boundaryCondition", "common")
        .append(selectionKeywords())
        .scalar("releaseTime", "s", "the condition holds while t < releaseTime (default: for ever)")
        .atLeast(0)
        .optional();
}

template <int Dim>
BoundaryCondition<Dim>::BoundaryCondition(const KeywordValues& values, const ParticleSet<Dim>& particles,
                                          bool allByDefault)
    : selection_(values, particles, allByDefault),
      name_(lastScope(values.dict().scope())),
      type_(values.dict().get<std::string>("type")) {
    if (auto release = values.optionalScalar("releaseTime")) releaseTime_ = *release;
}

template <int Dim>
BoundaryCondition<Dim>::BoundaryCondition(const Dictionary& dict, const ParticleSet<Dim>& particles,
                                          bool allByDefault)
    : BoundaryCondition(commonBoundaryConditionKeywords().read(dict), particles, allByDefault) {}

template <int Dim>
BoundaryCondition<Dim>::~BoundaryCondition() = default;

template <int Dim>
std::string BoundaryCondition<Dim>::describe() const {
    // The count over every rank (a rank selects among its own particles).
    std::string s = name_ + ": " + type_ + " on " + selection_.describe() + ", " +
                    std::to_string(globalSum(std::size_t(selection_.size()))) + " particles";
    if (releaseTime_ < std::numeric_limits<double>::infinity()) {
        std::ostringstream release;
        release << ", released at t = " << releaseTime_ << " s";  // 0.007, not 0.007000
        s += release.str();
    }
    return s;
}

template <int Dim>
void BoundaryCondition<Dim>::assignOnSelection(std::vector<VectorType>& values,
                                               const VectorType& value) const {
    const auto& idx = selection_.indices();
    parallelFor(idx.size(), [&](std::size_t k) { values[idx[k]] = value; });
}

template <int Dim>
std::vector<std::size_t> BoundaryCondition<Dim>::indicesOf(const ParticleSet<Dim>& particles,
                                                           const std::vector<std::int64_t>& ids) {
    std::unordered_map<std::int64_t, std::size_t> where;
    where.reserve(ids.size());
    for (std::size_t k = 0; k < ids.size(); ++k) where.emplace(ids[k], k);
    std::vector<std::size_t> index(ids.size(), npos);
    const auto& globalId = particles.globalId();
    for (std::size_t i = 0; i < globalId.size(); ++i)
        if (const auto it = where.find(globalId[i]); it != where.end()) index[it->second] = i;
    return index;
}

template class BoundaryCondition<1>;
template class BoundaryCondition<2>;
template class BoundaryCondition<3>;

}  // namespace mfdyn
