// uniformVelocity: v(X) = v0, u = 0 (a projectile, a flyer plate, a rigid translation).
//
//     velocity  v0 [m/s], a vector (extra components beyond the case's dimension must be 0)  required
#include "solver/UniformVelocity.hpp"

namespace mfdyn {

template <int Dim>
UniformVelocity<Dim>::UniformVelocity(const Dictionary& dict)
    : InitialState<Dim>(dict), v0_(dict.get<Vector<Dim>>("velocity")) {}

template <int Dim>
Vector<Dim> UniformVelocity<Dim>::velocity(const Vector<Dim>&) const {
    return v0_;
}

template class UniformVelocity<1>;
template class UniformVelocity<2>;
template class UniformVelocity<3>;

MFDYN_REGISTER_DIM(InitialState, UniformVelocity, "uniformVelocity", "v = v0 everywhere, no displacement");

}  // namespace mfdyn
