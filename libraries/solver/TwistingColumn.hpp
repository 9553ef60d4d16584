#pragma once
// initialState twistingColumn (3D): v = omega(X) x (X - c), omega = Omega sin(pi s/(2L)) e_axis. The
// formula is verification/TwistingColumnMotion; this reads it from a dictionary. See TwistingColumn.cpp.
#include "solver/InitialState.hpp"
#include "verification/TwistingColumnMotion.hpp"

#include <optional>

namespace mfdyn {

template <int Dim>
class TwistingColumn final : public InitialState<Dim> {
public:
    explicit TwistingColumn(const Dictionary& dict);
    Vector<Dim> velocity(const Vector<Dim>& X) const override;

private:
    std::optional<TwistingColumnMotion> motion_;  // set in 3D, the only dimension it is built in
};

extern template class TwistingColumn<1>;
extern template class TwistingColumn<2>;
extern template class TwistingColumn<3>;

}  // namespace mfdyn
