// swingingCube: the initial state of the swinging cube, Lee, Gil, Greto, Karim & Bonet 2016
// section 8.2, eq. (52) at t = 0 (doc/methods/tl-jst-sph.md 8.2):
//
//     u(X) = U0 [sin(pi X/2) cos(pi Y/2) cos(pi Z/2), cos sin cos, cos cos sin],   v = 0,
//     F = I + grad u (analytic),
//
// the factors of absent coordinates dropped in 2D and 1D (1D: u = U0 sin(pi X/2)). The cube is
// [0, 1]^Dim. The exact solution that follows is verification/SwingingCube (and the function
// object swingingCubeError); linear, so keep U0 small (the paper: U0 = 5e-4 m, linear for < 1e-3).
//
//     amplitude  U0 [m]   required
#include "solver/SwingingCubeState.hpp"

#include "verification/SwingingCube.hpp"

#include <cmath>

namespace mfdyn {

template <int Dim>
SwingingCubeState<Dim>::SwingingCubeState(const Dictionary& dict)
    : InitialState<Dim>(dict), amplitude_(dict.get<double>("amplitude")) {
    if (!std::isfinite(amplitude_)) throw dict.error("amplitude", "expected a finite length [m]");
}

template <int Dim>
Vector<Dim> SwingingCubeState<Dim>::displacement(const Vector<Dim>& X) const {
    return SwingingCube<Dim>::modeShape(X, amplitude_);
}

template <int Dim>
Vector<Dim> SwingingCubeState<Dim>::velocity(const Vector<Dim>&) const {
    return Vector<Dim>::Zero();
}

template <int Dim>
Tensor<Dim> SwingingCubeState<Dim>::displacementGradient(const Vector<Dim>& X) const {
    return SwingingCube<Dim>::modeGradient(X, amplitude_);
}

template class SwingingCubeState<1>;
template class SwingingCubeState<2>;
template class SwingingCubeState<3>;

MFDYN_REGISTER_DIM(
    InitialState, SwingingCubeState, "swingingCube",
    "u = U0 sin(pi X/2)cos(pi Y/2)cos(pi Z/2)..., v = 0: swinging cube (Lee et al. 2016 eq. 52)");

}  // namespace mfdyn
