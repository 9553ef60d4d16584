#pragma once
// initialState cantileverMode: the first bending mode velocity of a clamped plate. See CantileverMode.cpp.
#include "solver/InitialState.hpp"

namespace mfdyn {

template <int Dim>
class CantileverMode final : public InitialState<Dim> {
public:
    explicit CantileverMode(const Dictionary& dict);
    Vector<Dim> velocity(const Vector<Dim>& X) const override;
    // The transverse velocity at distance s from the clamp (0 for s <= 0).
    double transverseVelocity(double s) const;

private:
    double length_, velocity_, kL_, clampX_;
    double shape(double s) const;
};

extern template class CantileverMode<1>;
extern template class CantileverMode<2>;
extern template class CantileverMode<3>;

}  // namespace mfdyn
