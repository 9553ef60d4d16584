#pragma once
// Below three dimensions a body is in plane strain (2D) or uniaxial strain (1D): its Dim x Dim
// tensors are embedded in 3x3 for the material laws, which are written in three dimensions
// (doc/methods/tl-jst-sph.md 2.3). The out-of-plane diagonal is `fill`: 1 for a deformation
// gradient (unit out-of-plane stretch), 0 for a velocity gradient or a rate.
#include "core/Tensor.hpp"

namespace mfdyn {

// A Dim x Dim tensor in 3x3, the rest of the diagonal `fill` and the rest zero.
template <int Dim>
Tensor<3> embed(const Tensor<Dim>& a, double fill) {
    Tensor<3> t = Tensor<3>::Identity() * fill;
    t.template topLeftCorner<Dim, Dim>() = a;
    return t;
}

// The in-plane Dim x Dim block of a 3x3 tensor.
template <int Dim>
Tensor<Dim> inPlane(const Tensor<3>& a) {
    return a.template topLeftCorner<Dim, Dim>();
}

}  // namespace mfdyn
