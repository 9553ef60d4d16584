#pragma once
// initialState twistingColumn (3D): v = omega(X) x (X - c), omega = Omega sin(pi s/(2L)) e_axis. See
// TwistingColumn.cpp.
#include "solver/InitialState.hpp"

namespace mfdyn {

template <int Dim>
class TwistingColumn final : public InitialState<Dim> {
public:
    explicit TwistingColumn(const Dictionary& dict);
    Vector<Dim> velocity(const Vector<Dim>& X) const override;

private:
    double Omega_, length_;
    int axis_;
    Vector<Dim> centre_;
};

extern template class TwistingColumn<1>;
extern template class TwistingColumn<2>;
extern template class TwistingColumn<3>;

}  // namespace mfdyn
