#pragma once
// All boundary conditions of a case, from constant/boundaryConditions:
//
//     boundaryConditions
//     {
//         chamber { type fixed; regions (wall); }
//         tubeEnd { type mirrorPlane; point (0 0 0); normal (1 0 0); }
//     }
//
// built in the order written, and applied in that order by each hook (a later condition wins
// where two act on one particle, so write the overriding one last). The hooks and the order a
// solver calls them in within a step are those of BoundaryCondition.hpp:
//
//     bcs.updateSelections(particles);                 // only after a reorder / resize
//     GhostBlock<Dim> ghosts = bcs.ghosts(particles, v, hMax, t);   // -> neighbour search
//     ... compute rates a ...
//     bcs.addBoundaryForces(particles, f, t);          // f [N]; a += f/m (or dp/dt += f/V)
//     bcs.constrainAcceleration(particles, a, t);
//     ... v += a dt (each kick) ...;   bcs.constrainVelocity(particles, v, t);
//     ... x += v dt ...;               bcs.constrainPosition(particles, t);
//
// A case without the file, or with an empty list, has no boundary conditions (free surfaces).
#include "boundaryConditions/BoundaryCondition.hpp"

#include <memory>
#include <string>
#include <vector>

namespace mfdyn {

template <int Dim>
class BoundaryConditionList {
public:
    using VectorType = Vector<Dim>;

    BoundaryConditionList() = default;
    // `dict` holds the `boundaryConditions` sub-dictionary (the file), or is that sub-dictionary.
    BoundaryConditionList(const Dictionary& dict, const ParticleSet<Dim>& particles);

    std::size_t size() const { return conditions_.size(); }
    bool empty() const { return conditions_.empty(); }
    BoundaryCondition<Dim>& operator[](std::size_t k) { return *conditions_[k]; }
    const BoundaryCondition<Dim>& operator[](std::size_t k) const { return *conditions_[k]; }
    // Null when no condition has that name.
    const BoundaryCondition<Dim>* find(const std::string& name) const;
    bool makesGhosts() const;
    // The hooks beyond the constraints (constrainAcceleration, constrainVelocity, constrainPosition)
    // that a solver calls. A condition that acts only through a hook the solver does not call
    // would be silently without effect: requireHooks refuses it at its entry of `dict` (the file
    // the list was read from), naming the condition, what it needs and the solver.
    struct Hooks {
        bool ghosts = false;          // ghosts(): mirrorPlane's layer
        bool boundaryForces = false;  // addBoundaryForces(): prescribedTraction
    };
    void requireHooks(const Dictionary& dict, const Hooks& hooks, const std::string& solver) const;
    // One line per condition, for the log.
    std::string summary() const;

    void updateSelections(const ParticleSet<Dim>& particles);
    GhostBlock<Dim> ghosts(const ParticleSet<Dim>& particles, const std::vector<VectorType>& velocity,
                           double hMax, double t) const;
    // The conditions that mirror a total-Lagrangian reference configuration, in the order written
    // (BoundaryCondition::referenceMirror), with their parities.
    struct ReferenceMirror {
        const Plane<Dim>* plane;
        double parity;
    };
    std::vector<ReferenceMirror> referenceMirrors() const;
    // The images of the reference positions X across those planes, made once: each plane in the
    // order written mirrors X and the images already made (GhostBlock::referenceImagesAcross),
    // for points with tolerance < d < depth. Every condition mirrors whatever its selection or
    // release time: the images extend the body, they do not constrain it. No velocity.
    GhostBlock<Dim> referenceImages(const std::vector<VectorType>& X, double depth) const;
    // Adds every condition's boundary forces [N] to `force` (sized to the particles by the caller).
    void addBoundaryForces(const ParticleSet<Dim>& particles, std::vector<VectorType>& force, double t) const;
    void constrainAcceleration(ParticleSet<Dim>& particles, std::vector<VectorType>& acceleration, double t);
    void constrainVelocity(ParticleSet<Dim>& particles, std::vector<VectorType>& velocity, double t);
    void constrainVelocity(ParticleSet<Dim>& particles, double t);
    void constrainPosition(ParticleSet<Dim>& particles, double t);

private:
    std::vector<std::unique_ptr<BoundaryCondition<Dim>>> conditions_;
};

extern template class BoundaryConditionList<1>;
extern template class BoundaryConditionList<2>;
extern template class BoundaryConditionList<3>;

}  // namespace mfdyn
