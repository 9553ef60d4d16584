#pragma once
// initialState linearVelocity: v = v0 + G (X - origin). See LinearVelocity.cpp.
#include "solver/InitialState.hpp"

namespace mfdyn {

template <int Dim>
class LinearVelocity final : public InitialState<Dim> {
public:
    explicit LinearVelocity(const Dictionary& dict);
    Vector<Dim> velocity(const Vector<Dim>& X) const override;
    // G = dv/dX (for exact references of linear flows, e.g. fpmSolid's reference linearFlow).
    const Tensor<Dim>& gradient() const { return gradient_; }

private:
    Vector<Dim> v0_;
    Tensor<Dim> gradient_;
    Vector<Dim> origin_;
};

extern template class LinearVelocity<1>;
extern template class LinearVelocity<2>;
extern template class LinearVelocity<3>;

}  // namespace mfdyn
