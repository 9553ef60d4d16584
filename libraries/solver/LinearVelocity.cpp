// linearVelocity: v(X) = v0 + G (X - X0), u = 0.
//   Lee, Gil, Greto, Karim & Bonet 2016 section 8.8 (doc/methods/tl-jst-sph.md 8.8): the bending column,
//   v = V [Y/L, 0, 0] (V = 10 m/s, L = 6 m): gradient ((0 1.6667 0) (0 0 0) (0 0 0));
//   section 8.4, the tensile cube, v = (0, V Y, 0): gradient ((0 0 0) (0 V 0) (0 0 0)).
//
//     keyword   meaning                                                   required  default
//     velocity  v0 [m/s], the velocity at the origin                      no        0
//     gradient  G = dv_i/dX_J [1/s], row by row: ((G11 G12 G13) (G21 ...) ...) yes
//               or flat (G11 G12 ... ); a 3x3 G in a 2D or 1D case must be 0
//               outside its leading Dim x Dim block
//     origin    X0 [m]                                                    no        0
#include "solver/LinearVelocity.hpp"

#include "core/TensorEntry.hpp"

#include <string>

namespace mfdyn {

template <int Dim>
LinearVelocity<Dim>::LinearVelocity(const Dictionary& dict)
    : InitialState<Dim>(dict),
      v0_(dict.getOrDefault<Vector<Dim>>("velocity", Vector<Dim>::Zero())),
      gradient_(readTensor<Dim>(dict, "gradient")),
      origin_(dict.getOrDefault<Vector<Dim>>("origin", Vector<Dim>::Zero())) {}

template <int Dim>
Vector<Dim> LinearVelocity<Dim>::velocity(const Vector<Dim>& X) const {
    return v0_ + gradient_ * (X - origin_);
}

template class LinearVelocity<1>;
template class LinearVelocity<2>;
template class LinearVelocity<3>;

MFDYN_REGISTER_DIM(InitialState, LinearVelocity, "linearVelocity",
                   "v = v0 + G (X - origin): bending column, tensile cube (Lee et al. 2016 8.8, 8.4)");

}  // namespace mfdyn
