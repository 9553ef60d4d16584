#pragma once
// initialState swingingCube: the displacement mode of Lee et al. 2016 eq. 52 at rest. See
// SwingingCubeState.cpp.
#include "solver/InitialState.hpp"

namespace mfdyn {

template <int Dim>
class SwingingCubeState final : public InitialState<Dim> {
public:
    explicit SwingingCubeState(const Dictionary& dict);
    Vector<Dim> displacement(const Vector<Dim>& X) const override;
    Vector<Dim> velocity(const Vector<Dim>& X) const override;
    Tensor<Dim> displacementGradient(const Vector<Dim>& X) const override;
    bool hasDisplacement() const override { return true; }

private:
    double amplitude_;
};

extern template class SwingingCubeState<1>;
extern template class SwingingCubeState<2>;
extern template class SwingingCubeState<3>;

}  // namespace mfdyn
