#pragma once
// Boundary conditions: the family `boundaryCondition`, shared by the particle solvers. A case
// lists them in constant/boundaryConditions (read by BoundaryConditionList):
//
//     boundaryConditions
//     {
//         chamber   { type fixed;              regions (wall); }
//         punch     { type prescribedVelocity; shape { type box; min (0.25 1 0.25); max (0.75 1.1 0.75); }
//                     velocity (0 -100 0); releaseTime 0.007; }
//         xSymmetry { type symmetryPlane;      point (0 0 0); normal (1 0 0); }
//         floor     { type rigidPlanarWall;    point (0 0 0); normal (0 1 0); }
//         tubeEnd   { type mirrorPlane;        point (0 0 0); normal (1 0 0); noSlip no; }
//     }
//
// Every condition acts on a Selection (Selection.hpp: `regions (...)`, `shape { ... }`, `all yes`)
// and holds until `releaseTime` [s] (default: for ever; from then on it does nothing).
//
// Hooks, all per-particle updates on the selection (no neighbours). In one time step a solver
// calls them in this order (BoundaryConditionList forwards each to every condition in turn):
//
//   0. updateSelection(particles)            after the solver reorders particles or changes
//                                            their number (cell sorting, erosion), before 1-4.
//   1. ghosts(particles, v, hMax)            before the neighbour search: ghost particles of the
//                                            mirror planes (GhostBlock.hpp), appended to the
//                                            search as neighbours; other fields by block.source.
//  2a. addBoundaryForce(particles, f, t)    before constrainAcceleration: adds the boundary
//                                            forces [N] per particle (prescribedTraction:
//                                            A_a t_a of doc/methods/tl-jst-sph.md 2.7) to `f`; a
//                                            total-Lagrangian solver adds f/V to dp/dt, an
//                                            updated-Lagrangian one f/m to dv/dt.
//   2. constrainAcceleration(particles, a, t)  after the rates are computed, before they are
//                                            integrated: constrained components of dv/dt = 0.
//   3. constrainVelocity(particles, v, t)    after every velocity update (each kick of a leapfrog,
//                                            for every velocity array that is updated, e.g. the
//                                            half-step one), with t the time v belongs to.
//   4. constrainPosition(particles, t)       after the position update (drift).
//
// 2 and 3 together keep a constraint exact: zeroing only v lets the integrator reintroduce
// motion within a step through the rate, zeroing only the rate lets round-off drift v.
// The arrays passed are the solver's own (velocity or, in a total-Lagrangian solver, linear
// momentum p = rho0 v: fixed, symmetryPlane and the plane conditions act on any such vector;
// prescribedVelocity writes velocities, see prescribedVelocity(t)).
//
// A condition that acts on particles picked once by their initial positions (skewSymmetricPlane,
// prescribedTraction) keeps them by globalId and re-finds them in selectionUpdated().
#include "boundaryConditions/GhostBlock.hpp"
#include "boundaryConditions/Plane.hpp"
#include "boundaryConditions/Selection.hpp"
#include "core/Registry.hpp"
#include "particles/ParticleSet.hpp"

#include <cstdint>
#include <limits>
#include <memory>
#include <string>
#include <vector>

namespace mfdyn {

// The keywords of every condition: the selection's (Selection.hpp) and releaseTime. A type's
// schema declares its own keywords and appends these:
//
//     KeywordSchema MirrorPlane<Dim>::keywords() {
//         return KeywordSchema("boundaryCondition", "mirrorPlane")
//             .append(planeKeywords())
//             .flag("noSlip", "...").orDefault(false)
//             .append(commonBoundaryConditionKeywords());
//     }
KeywordSchema commonBoundaryConditionKeywords();

template <int Dim>
class BoundaryCondition {
public:
    static constexpr const char* familyName = "boundaryCondition";
    using Selector = Registry<BoundaryCondition, const Dictionary&, const ParticleSet<Dim>&>;
    using VectorType = Vector<Dim>;
    static std::unique_ptr<BoundaryCondition> New(const Dictionary& dict, const ParticleSet<Dim>& particles) {
        return Selector::New(dict, particles);
    }

    virtual ~BoundaryCondition();
    BoundaryCondition(const BoundaryCondition&) = delete;
    BoundaryCondition& operator=(const BoundaryCondition&) = delete;

    // The dictionary key (`chamber`) and the type name (`fixed`).
    const std::string& name() const { return name_; }
    const std::string& type() const { return type_; }
    const Selection<Dim>& selection() const { return selection_; }
    double releaseTime() const { return releaseTime_; }
    // True while the condition holds: t < releaseTime.
    bool active(double t) const { return t < releaseTime_; }
    // For the log: "chamber: fixed on regions (wall), 120 particles". Collective on several ranks
    // (the counts are over every rank).
    virtual std::string describe() const;

    void updateSelection(const ParticleSet<Dim>& particles) {
        selection_.update(particles);
        selectionUpdated(particles);
    }

    void constrainVelocity(ParticleSet<Dim>& particles, std::vector<VectorType>& velocity, double t) {
        if (active(t)) velocityConstraint(particles, velocity, t);
    }
    // On the particle field `velocity`.
    void constrainVelocity(ParticleSet<Dim>& particles, double t) {
        constrainVelocity(particles, particles.template requireField<VectorType>("velocity"), t);
    }
    // Adds this condition's boundary forces [N] to `force` (one entry per particle).
    void addBoundaryForce(const ParticleSet<Dim>& particles, std::vector<VectorType>& force, double t) const {
        if (active(t)) boundaryForce(particles, force, t);
    }
    void constrainAcceleration(ParticleSet<Dim>& particles, std::vector<VectorType>& acceleration, double t) {
        if (active(t)) accelerationConstraint(particles, acceleration, t);
    }
    void constrainPosition(ParticleSet<Dim>& particles, double t) {
        if (active(t)) positionConstraint(particles, t);
    }
    // Ghosts of this condition appended to `block`; `hMax` is the largest smoothing length.
    void appendGhosts(const ParticleSet<Dim>& particles, const std::vector<VectorType>& velocity, double hMax,
                      double t, GhostBlock<Dim>& block) const {
        if (active(t)) ghostLayer(particles, velocity, hMax, block);
    }
    virtual bool makesGhosts() const { return false; }
    // True for a condition whose whole effect is boundary forces (the addBoundaryForce hook): a
    // solver that does not call that hook must refuse it (BoundaryConditionList::requireHooks).
    virtual bool appliesForces() const { return false; }
    // The plane across which a total-Lagrangian method mirrors its reference configuration once
    // (BoundaryConditionList::referenceImages), with the images' parity: symmetryPlane +1,
    // skewSymmetricPlane -1 (GhostBlock.hpp). Null for every other condition.
    virtual const Plane<Dim>* referenceMirror(double& parity) const {
        parity = 1.0;
        return nullptr;
    }

protected:
    // `allByDefault`: without `regions`/`shape`/`all` the selection is every particle (planes,
    // which select by side) rather than an input error (fixed, prescribedVelocity).
    // From the values of the type's schema, which appends commonBoundaryConditionKeywords().
    BoundaryCondition(const KeywordValues& values, const ParticleSet<Dim>& particles, bool allByDefault);
    // For a type without a schema of its own (a user's library): reads the common keywords only.
    BoundaryCondition(const Dictionary& dict, const ParticleSet<Dim>& particles, bool allByDefault);

    virtual void velocityConstraint(ParticleSet<Dim>&, std::vector<VectorType>&, double) {}
    virtual void accelerationConstraint(ParticleSet<Dim>&, std::vector<VectorType>&, double) {}
    virtual void positionConstraint(ParticleSet<Dim>&, double) {}
    virtual void boundaryForce(const ParticleSet<Dim>&, std::vector<VectorType>&, double) const {}
    // After selection_ has been updated for a reorder or a change in particle count.
    virtual void selectionUpdated(const ParticleSet<Dim>&) {}
    virtual void ghostLayer(const ParticleSet<Dim>&, const std::vector<VectorType>&, double,
                            GhostBlock<Dim>&) const {}

    // Sets every selected entry of `values` to `value`.
    void assignOnSelection(std::vector<VectorType>& values, const VectorType& value) const;
    // The current index of each particle of `ids` (globalId), or npos for one no longer present.
    static constexpr std::size_t npos = std::size_t(-1);
    static std::vector<std::size_t> indicesOf(const ParticleSet<Dim>& particles,
                                              const std::vector<std::int64_t>& ids);

    Selection<Dim> selection_;

private:
    std::string name_;
    std::string type_;
    double releaseTime_ = std::numeric_limits<double>::infinity();
};

extern template class BoundaryCondition<1>;
extern template class BoundaryCondition<2>;
extern template class BoundaryCondition<3>;

}  // namespace mfdyn
