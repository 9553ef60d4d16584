// free: a traction-free surface, t = 0 (doc/methods/sph-impact.md section 4: "free surfaces: nothing
// special"; doc/methods/tl-jst-sph.md 2.7: "traction-free boundaries need no work"). Every hook is a no-op.
//
// Usage: name { type free; [regions (...); | shape { ... }] }   (default: all particles)
#include "boundaryConditions/Free.hpp"

namespace mfdyn {

template <int Dim>
KeywordSchema Free<Dim>::keywords() {
    return KeywordSchema("boundaryCondition", "free").append(commonBoundaryConditionKeywords());
}

template <int Dim>
Free<Dim>::Free(const Dictionary& dict, const ParticleSet<Dim>& particles)
    : BoundaryCondition<Dim>(keywords().read(dict), particles, true) {}

template class Free<1>;
template class Free<2>;
template class Free<3>;

MFDYN_REGISTER_DIM(BoundaryCondition, Free, "free", "no constraint: a traction-free surface");

}  // namespace mfdyn
