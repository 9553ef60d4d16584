#pragma once
// initialState uniformVelocity: v = v0 everywhere. See UniformVelocity.cpp.
#include "solver/InitialState.hpp"

namespace mfdyn {

template <int Dim>
class UniformVelocity final : public InitialState<Dim> {
public:
    explicit UniformVelocity(const Dictionary& dict);
    Vector<Dim> velocity(const Vector<Dim>& X) const override;

private:
    Vector<Dim> v0_;
};

extern template class UniformVelocity<1>;
extern template class UniformVelocity<2>;
extern template class UniformVelocity<3>;

}  // namespace mfdyn
