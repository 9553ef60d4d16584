#pragma once
// initialState cantileverMode: the first bending mode velocity of a clamped plate. The formula is
// verification/CantileverModeShape; this reads it from a dictionary. See CantileverMode.cpp.
#include "solver/InitialState.hpp"
#include "verification/CantileverModeShape.hpp"

#include <optional>

namespace mfdyn {

template <int Dim>
class CantileverMode final : public InitialState<Dim> {
public:
    explicit CantileverMode(const Dictionary& dict);
    Vector<Dim> velocity(const Vector<Dim>& X) const override;
    // The transverse velocity at distance s from the clamp (0 for s <= 0).
    double transverseVelocity(double s) const;

private:
    double clampX_ = 0;
    bool planeSections_ = false;  // `sections plane`: v_x = -(Y - neutralAxis) v_y'(s)
    double neutralAxis_ = 0;
    std::optional<CantileverModeShape> mode_;  // set once the dictionary has been checked
};

extern template class CantileverMode<1>;
extern template class CantileverMode<2>;
extern template class CantileverMode<3>;

}  // namespace mfdyn
