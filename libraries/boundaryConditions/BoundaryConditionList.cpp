#include "boundaryConditions/BoundaryConditionList.hpp"

namespace mfdyn {

template <int Dim>
BoundaryConditionList<Dim>::BoundaryConditionList(const Dictionary& dict, const ParticleSet<Dim>& particles) {
    const Dictionary& list = dict.isDict("boundaryConditions") ? dict.subDict("boundaryConditions") : dict;
    for (const auto& entry : list.entries()) {
        if (!entry->isDict())
            throw list.error(entry->key, "expected a boundary condition `" + entry->key +
                                             " { type ...; }`, found a plain entry");
        entry->read = true;
        conditions_.push_back(BoundaryCondition<Dim>::New(*entry->dict, particles));
    }
}

template <int Dim>
const BoundaryCondition<Dim>* BoundaryConditionList<Dim>::find(const std::string& name) const {
    for (const auto& c : conditions_)
        if (c->name() == name) return c.get();
    return nullptr;
}

template <int Dim>
bool BoundaryConditionList<Dim>::makesGhosts() const {
    for (const auto& c : conditions_)
        if (c->makesGhosts()) return true;
    return false;
}

template <int Dim>
void BoundaryConditionList<Dim>::requireHooks(const Dictionary& dict, const Hooks& hooks,
                                              const std::string& solver) const {
    const Dictionary& list = dict.isDict("boundaryConditions") ? dict.subDict("boundaryConditions") : dict;
    for (const auto& c : conditions_) {
        std::string needs;
        if (c->makesGhosts() && !hooks.ghosts)
            needs = "a layer of mirror ghost particles, which " + solver + " does not build";
        if (c->appliesForces() && !hooks.boundaryForces)
            needs = "boundary forces, which " + solver + " does not apply";
        if (needs.empty()) continue;
        std::string alternatives =
            "the conditions that act on velocities and positions (fixed, prescribedVelocity, "
            "symmetryPlane, skewSymmetricPlane, rigidPlanarWall)";
        if (hooks.ghosts) alternatives += ", mirrorPlane";
        if (hooks.boundaryForces) alternatives += ", prescribedTraction";
        throw list.error(c->name(), "boundary condition `" + c->name() + "` (" + c->type() +
                                        ") acts through " + needs + ": it would have no effect. " + solver +
                                        " applies " + alternatives);
    }
}

template <int Dim>
std::string BoundaryConditionList<Dim>::summary() const {
    std::string s;
    for (const auto& c : conditions_) s += c->describe() + "\n";
    return s;
}

template <int Dim>
void BoundaryConditionList<Dim>::updateSelections(const ParticleSet<Dim>& particles) {
    for (auto& c : conditions_) c->updateSelection(particles);
}

template <int Dim>
GhostBlock<Dim> BoundaryConditionList<Dim>::ghosts(const ParticleSet<Dim>& particles,
                                                   const std::vector<VectorType>& velocity, double hMax,
                                                   double t) const {
    GhostBlock<Dim> block;
    for (const auto& c : conditions_) c->appendGhosts(particles, velocity, hMax, t, block);
    return block;
}

template <int Dim>
std::vector<typename BoundaryConditionList<Dim>::ReferenceMirror>
BoundaryConditionList<Dim>::referenceMirrors() const {
    std::vector<ReferenceMirror> mirrors;
    for (const auto& c : conditions_) {
        double parity = 1.0;
        if (const Plane<Dim>* plane = c->referenceMirror(parity)) mirrors.push_back({plane, parity});
    }
    return mirrors;
}

template <int Dim>
GhostBlock<Dim> BoundaryConditionList<Dim>::referenceImages(const std::vector<VectorType>& X,
                                                            double depth) const {
    GhostBlock<Dim> block;
    for (const auto& mirror : referenceMirrors())
        block.referenceImagesAcross(X, *mirror.plane, mirror.parity, depth);
    return block;
}

template <int Dim>
void BoundaryConditionList<Dim>::addBoundaryForces(const ParticleSet<Dim>& particles,
                                                   std::vector<VectorType>& force, double t) const {
    for (const auto& c : conditions_) c->addBoundaryForce(particles, force, t);
}

template <int Dim>
void BoundaryConditionList<Dim>::constrainAcceleration(ParticleSet<Dim>& particles,
                                                       std::vector<VectorType>& acceleration, double t) {
    for (auto& c : conditions_) c->constrainAcceleration(particles, acceleration, t);
}

template <int Dim>
void BoundaryConditionList<Dim>::constrainVelocity(ParticleSet<Dim>& particles,
                                                   std::vector<VectorType>& velocity, double t) {
    for (auto& c : conditions_) c->constrainVelocity(particles, velocity, t);
}

template <int Dim>
void BoundaryConditionList<Dim>::constrainVelocity(ParticleSet<Dim>& particles, double t) {
    if (conditions_.empty()) return;
    constrainVelocity(particles, particles.template requireField<VectorType>("velocity"), t);
}

template <int Dim>
void BoundaryConditionList<Dim>::constrainPosition(ParticleSet<Dim>& particles, double t) {
    for (auto& c : conditions_) c->constrainPosition(particles, t);
}

template class BoundaryConditionList<1>;
template class BoundaryConditionList<2>;
template class BoundaryConditionList<3>;

}  // namespace mfdyn
