#include "boundaryConditions/Selection.hpp"

#include "core/Parallel.hpp"

#include <algorithm>
#include <unordered_set>

namespace mfdyn {

KeywordSchema selectionKeywords() {
    return KeywordSchema("boundaryCondition", "selection")
        .words("regions", "the particles of these named regions (with shape: those of them inside it)")
        .optional()
        .dictionary("shape", "the particles inside this shape (geometry/Shape.hpp)")
        .optional()
        .flag("all", "every particle (instead of regions and shape)")
        .optional()
        .flag("reselect",
              "yes: after a reorder, apply the criteria again to the current positions; not "
              "given or no: keep the same particles (by global id)")
        .optional();
}

template <int Dim>
Selection<Dim>::Selection(const Dictionary& dict, const ParticleSet<Dim>& particles, bool allByDefault)
    : Selection(selectionKeywords().read(dict), particles, allByDefault) {}

template <int Dim>
Selection<Dim>::Selection(const KeywordValues& values, const ParticleSet<Dim>& particles, bool allByDefault) {
    const bool hasRegions = values.given("regions");
    const bool hasShape = values.given("shape");
    const bool allGiven = values.given("all");
    all_ = allGiven && values.flag("all");
    if (all_ && (hasRegions || hasShape))
        throw values.error("all", "`all yes` selects every particle; remove `regions` and `shape` or `all`");
    if (allGiven && !all_ && !hasRegions && !hasShape)
        throw values.error("all", "`all no` needs `regions (...)` or `shape { ... }`");
    if (!allGiven && !hasRegions && !hasShape) {
        if (!allByDefault)
            throw InputError(values.dict().where(), values.dict().scope(),
                             "no particles selected: give `regions (name ...);`, `shape { type ...; }` or "
                             "`all yes;`");
        all_ = true;
    }
    reselect_ = values.flag("reselect");

    if (hasRegions) {
        regionNames_ = values.words("regions");
        for (const auto& name : regionNames_) {
            const auto& known = particles.regionNames;
            const auto it = std::find(known.begin(), known.end(), name);
            if (it == known.end()) {
                std::string list;
                for (const auto& k : known) list += (list.empty() ? "" : ", ") + k;
                std::string message = "unknown region '" + name + "'";
                const std::string guess = closestMatch(name, known);
                if (!guess.empty()) message += "; did you mean '" + guess + "'?";
                message += " Regions in the particle file: " + (list.empty() ? std::string("(none)") : list);
                throw values.error("regions", message);
            }
            regionIds_.push_back(std::int64_t(it - known.begin()));
        }
    }
    if (hasShape) {
        const Dictionary& shapeDict = values.dictionary("shape");
        shape_ = Shape::New(shapeDict, Dim);
        shapeType_ = shapeDict.get<std::string>("type");
    }
    resolve(particles);
    if (!all_ && !reselect_) {
        wantedIds_ = globalConcatenation(globalIds_);
        std::sort(wantedIds_.begin(), wantedIds_.end());
    }
}

template <int Dim>
Selection<Dim>::~Selection() = default;

template <int Dim>
std::vector<std::size_t> Selection<Dim>::haloIndices(const ParticleSet<Dim>& particles) const {
    std::vector<std::size_t> halo;
    const auto& ids = particles.globalId();
    for (std::size_t i = particles.haloBegin(), end = i + particles.haloCount(); i < end; ++i) {
        const bool selected =
            all_ || (reselect_ ? matches(particles, i)
                               : std::binary_search(wantedIds_.begin(), wantedIds_.end(), ids[i]) ||
                                     (ids[i] >= newIdsFrom_ && matches(particles, i)));
        if (selected) halo.push_back(i);
    }
    return halo;
}

template <int Dim>
bool Selection<Dim>::matches(const ParticleSet<Dim>& particles, std::size_t i) const {
    if (all_) return true;
    if (!regionIds_.empty() &&
        std::find(regionIds_.begin(), regionIds_.end(), particles.region()[i]) == regionIds_.end())
        return false;
    return !shape_ || shape_->inside(particles.position()[i].data());
}

template <int Dim>
void Selection<Dim>::record(const ParticleSet<Dim>& particles) {
    newIdsFrom_ = particles.nextGlobalId();
    topologyVersion_ = particles.topologyVersion();
}

template <int Dim>
void Selection<Dim>::resolve(const ParticleSet<Dim>& particles) {
    const std::size_t n = particles.ownedCount();
    indices_.clear();
    for (std::size_t i = 0; i < n; ++i)
        if (matches(particles, i)) indices_.push_back(i);
    const auto& ids = particles.globalId();
    globalIds_.resize(indices_.size());
    for (std::size_t k = 0; k < indices_.size(); ++k) globalIds_[k] = ids[indices_[k]];
    record(particles);
}

template <int Dim>
void Selection<Dim>::update(const ParticleSet<Dim>& particles) {
    if (all_ || reselect_) return resolve(particles);
    // Same particles, new places: the selected ones found again by globalId (on any rank: a
    // particle arrived from another rank is found too).
    const auto& ids = particles.globalId();
    indices_.clear();
    std::vector<std::int64_t> kept, joined;
    // Particles removed by the solver (eroded, left the domain) drop out of the selection; those
    // appended since the last update, and only they, are judged by the criteria.
    for (std::size_t i = 0, n = particles.ownedCount(); i < n; ++i) {
        const bool wanted = std::binary_search(wantedIds_.begin(), wantedIds_.end(), ids[i]);
        if (wanted || (ids[i] >= newIdsFrom_ && matches(particles, i))) {
            indices_.push_back(i);
            kept.push_back(ids[i]);
            if (!wanted) joined.push_back(ids[i]);
        }
    }
    globalIds_ = std::move(kept);
    if (!joined.empty()) {
        wantedIds_.insert(wantedIds_.end(), joined.begin(), joined.end());
        std::sort(wantedIds_.begin(), wantedIds_.end());
    }
    record(particles);
}

template <int Dim>
bool Selection<Dim>::refresh(const ParticleSet<Dim>& particles) {
    if (particles.topologyVersion() == topologyVersion_) return false;
    update(particles);
    return true;
}

template <int Dim>
std::string Selection<Dim>::describe() const {
    if (all_) return "all particles";
    std::string s;
    if (!regionNames_.empty()) {
        s = "regions (";
        for (std::size_t k = 0; k < regionNames_.size(); ++k) s += (k ? " " : "") + regionNames_[k];
        s += ")";
    }
    if (shape_) s += (s.empty() ? "" : " inside ") + std::string("shape ") + shapeType_;
    return s;
}

template class Selection<1>;
template class Selection<2>;
template class Selection<3>;

}  // namespace mfdyn
