#pragma once
// `fixed`: the selected particles do not move (wall particles, a clamped face).
#include "boundaryConditions/BoundaryCondition.hpp"

namespace mfdyn {

template <int Dim>
class Fixed : public BoundaryCondition<Dim> {
public:
    using typename BoundaryCondition<Dim>::VectorType;
    Fixed(const Dictionary& dict, const ParticleSet<Dim>& particles);
    static KeywordSchema keywords();

protected:
    void velocityConstraint(ParticleSet<Dim>&, std::vector<VectorType>& v, double) override;
    void accelerationConstraint(ParticleSet<Dim>&, std::vector<VectorType>& a, double) override;
};

}  // namespace mfdyn
