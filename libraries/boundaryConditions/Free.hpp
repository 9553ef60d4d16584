#pragma once
// `free`: no constraint (a traction-free surface), so that a boundary can be named in the
// dictionary, and switched off by changing its type only.
#include "boundaryConditions/BoundaryCondition.hpp"

namespace mfdyn {

template <int Dim>
class Free : public BoundaryCondition<Dim> {
public:
    Free(const Dictionary& dict, const ParticleSet<Dim>& particles);
    static KeywordSchema keywords();
};

}  // namespace mfdyn
