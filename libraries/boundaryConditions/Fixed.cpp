// fixed: v = 0 and dv/dt = 0 on the selection.
//   Zisis 2017 section 5.4 (doc/methods/sph-impact.md section 4): wall particles whose velocity is reset to 0
//   every step; they keep density, pressure and stress and so act on their neighbours.
//   Lee, Gil, Greto, Karim & Bonet 2016 §2.7 (doc/methods/tl-jst-sph.md 2.7, "clamped"): p = dp/dt = 0,
//   which this is when the solver passes its momentum array.
// Both the rate and the velocity are zeroed (see BoundaryCondition.hpp) so that no integrator
// stage moves the particles.
//
// Usage: name { type fixed; regions (wall); | shape { ... } | all yes;  [releaseTime t;] }
// A selection is required: a forgotten `regions` must not freeze every particle.
#include "boundaryConditions/Fixed.hpp"

namespace mfdyn {

template <int Dim>
KeywordSchema Fixed<Dim>::keywords() {
    return KeywordSchema("boundaryCondition", "fixed").append(commonBoundaryConditionKeywords());
}

template <int Dim>
Fixed<Dim>::Fixed(const Dictionary& dict, const ParticleSet<Dim>& particles)
    : BoundaryCondition<Dim>(keywords().read(dict), particles, false) {}

template <int Dim>
void Fixed<Dim>::velocityConstraint(ParticleSet<Dim>&, std::vector<VectorType>& v, double) {
    this->assignOnSelection(v, VectorType::Zero());
}

template <int Dim>
void Fixed<Dim>::accelerationConstraint(ParticleSet<Dim>&, std::vector<VectorType>& a, double) {
    this->assignOnSelection(a, VectorType::Zero());
}

template class Fixed<1>;
template class Fixed<2>;
template class Fixed<3>;

MFDYN_REGISTER_DIM(BoundaryCondition, Fixed, "fixed", "v = 0 and dv/dt = 0 on the selection (wall, clamped)");

}  // namespace mfdyn
