// prescribedVelocity: v = v_p(t) and dv/dt = dv_p/dt on the selection while t < releaseTime;
// afterwards the particles move freely from the velocity they had.
//   Lee et al. 2016 §2.7 and Fig. 15 (doc/methods/tl-jst-sph.md 2.7 and 8.7, the punch): p = rho0 v_pres,
//   dp/dt = 0, v = (0, -100, 0) m/s on the mid quarter of the top face, released at t = 0.007 s.
//   A total-Lagrangian solver working in momentum multiplies velocity(t) by rho0 itself.
// The rate is set to dv_p/dt (zero for a constant velocity, the paper's dp/dt = 0) rather than
// left to the forces, so that an integrator stage between two velocity resets follows v_p(t).
//
// Usage: name { type prescribedVelocity; regions (...); | shape { ... } | all yes;
//               velocity (0 -100 0); | table ((0 (0 0 0)) (1e-3 (0 -100 0)));  [releaseTime 0.007;] }
#include "boundaryConditions/PrescribedVelocity.hpp"

#include <algorithm>

namespace mfdyn {

template <int Dim>
KeywordSchema PrescribedVelocity<Dim>::keywords() {
    return KeywordSchema("boundaryCondition", "prescribedVelocity")
        .append(vectorTableKeywords("velocity", "m/s", "the velocity of the selected particles"))
        .append(commonBoundaryConditionKeywords());
}

template <int Dim>
PrescribedVelocity<Dim>::PrescribedVelocity(const Dictionary& dict, const ParticleSet<Dim>& particles)
    : PrescribedVelocity(keywords().read(dict), particles) {}

template <int Dim>
PrescribedVelocity<Dim>::PrescribedVelocity(const KeywordValues& values, const ParticleSet<Dim>& particles)
    : BoundaryCondition<Dim>(values, particles, false), table_(values, "velocity", "m/s") {}

template <int Dim>
typename PrescribedVelocity<Dim>::VectorType PrescribedVelocity<Dim>::velocity(double t) const {
    return table_.value(t);
}

template <int Dim>
typename PrescribedVelocity<Dim>::VectorType PrescribedVelocity<Dim>::acceleration(double t) const {
    return table_.rate(t);
}

template <int Dim>
void PrescribedVelocity<Dim>::velocityConstraint(ParticleSet<Dim>&, std::vector<VectorType>& v, double t) {
    this->assignOnSelection(v, velocity(t));
}

template <int Dim>
void PrescribedVelocity<Dim>::accelerationConstraint(ParticleSet<Dim>&, std::vector<VectorType>& a,
                                                     double t) {
    this->assignOnSelection(a, acceleration(t));
}

template class PrescribedVelocity<1>;
template class PrescribedVelocity<2>;
template class PrescribedVelocity<3>;

MFDYN_REGISTER_DIM(BoundaryCondition, PrescribedVelocity, "prescribedVelocity",
                   "v = v_p(t) (constant or table) on the selection until releaseTime (punch)");

}  // namespace mfdyn
