#pragma once
// `rigidPlanarWall`: a unilateral wall; particles may leave it but not pass through it.
#include "boundaryConditions/BoundaryCondition.hpp"
#include "boundaryConditions/Plane.hpp"

namespace mfdyn {

template <int Dim>
class RigidPlanarWall : public BoundaryCondition<Dim> {
public:
    using typename BoundaryCondition<Dim>::VectorType;
    RigidPlanarWall(const Dictionary& dict, const ParticleSet<Dim>& particles);
    static KeywordSchema keywords();
    const Plane<Dim>& plane() const { return plane_; }
    double restitution() const { return restitution_; }

protected:
    void velocityConstraint(ParticleSet<Dim>& particles, std::vector<VectorType>& v, double) override;
    void accelerationConstraint(ParticleSet<Dim>& particles, std::vector<VectorType>& a, double) override;
    void positionConstraint(ParticleSet<Dim>& particles, double) override;

private:
    RigidPlanarWall(const KeywordValues& values, const ParticleSet<Dim>& particles);

    Plane<Dim> plane_;
    double restitution_;
};

}  // namespace mfdyn
