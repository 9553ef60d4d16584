#pragma once
// `prescribedVelocity`: the selection moves with a given velocity until `releaseTime`.
//
//   velocity (vx vy vz);                            constant [m/s], or
//   table ((t0 (vx vy vz)) (t1 (vx vy vz)) ...);    piecewise linear in t [s], held constant
//                                                   before the first and after the last time.
#include "boundaryConditions/BoundaryCondition.hpp"
#include "boundaryConditions/VectorTable.hpp"

#include <vector>

namespace mfdyn {

template <int Dim>
class PrescribedVelocity : public BoundaryCondition<Dim> {
public:
    using typename BoundaryCondition<Dim>::VectorType;
    PrescribedVelocity(const Dictionary& dict, const ParticleSet<Dim>& particles);
    static KeywordSchema keywords();

    // v_prescribed(t) and its time derivative.
    VectorType velocity(double t) const;
    VectorType acceleration(double t) const;

protected:
    void velocityConstraint(ParticleSet<Dim>&, std::vector<VectorType>& v, double t) override;
    void accelerationConstraint(ParticleSet<Dim>&, std::vector<VectorType>& a, double t) override;

private:
    PrescribedVelocity(const KeywordValues& values, const ParticleSet<Dim>& particles);

    VectorTable<Dim> table_;
};

}  // namespace mfdyn
