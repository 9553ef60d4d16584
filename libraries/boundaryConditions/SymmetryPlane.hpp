#pragma once
// `symmetryPlane` (also a roller): no motion through a plane; tangential motion is free.
#include "boundaryConditions/BoundaryCondition.hpp"
#include "boundaryConditions/Plane.hpp"

namespace mfdyn {

template <int Dim>
class SymmetryPlane : public BoundaryCondition<Dim> {
public:
    using typename BoundaryCondition<Dim>::VectorType;
    SymmetryPlane(const Dictionary& dict, const ParticleSet<Dim>& particles);
    static KeywordSchema keywords();
    const Plane<Dim>& plane() const { return plane_; }
    // Mirrored by a total-Lagrangian method with parity +1 (GhostBlock.hpp).
    const Plane<Dim>* referenceMirror(double& parity) const override {
        parity = 1.0;
        return &plane_;
    }

protected:
    void velocityConstraint(ParticleSet<Dim>& particles, std::vector<VectorType>& v, double) override;
    void accelerationConstraint(ParticleSet<Dim>& particles, std::vector<VectorType>& a, double) override;
    void positionConstraint(ParticleSet<Dim>& particles, double) override;

private:
    SymmetryPlane(const KeywordValues& values, const ParticleSet<Dim>& particles);

    // Removes the normal component of values[i] for the selected particles on or behind the plane.
    void removeNormal(const ParticleSet<Dim>& particles, std::vector<VectorType>& values) const;
    Plane<Dim> plane_;
};

}  // namespace mfdyn
