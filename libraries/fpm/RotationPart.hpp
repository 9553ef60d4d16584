#pragma once
// The rotation (R) part of the finite pointset method's split (von Nida 2005 §5.3;
// doc/methods/fpm.md §3.4): with the velocity gradient held constant over the step, the Jaumann
// term DS/Dt = W S - S W (the note's §7 item 1 sign) is integrated exactly,
//
//     S <- M S M^T,   M = exp(dt W),   W = (grad v - grad v^T) / 2   (the spin),
//
// which keeps the invariants of S to round-off. In 3D exp is Rodrigues' formula (the note's 5.59):
// with w the axial vector of W (W a = w x a) and omega = |w|,
//
//     M = I + (sin(omega dt) / omega) W + ((1 - cos(omega dt)) / omega^2) W^2,
//
// and below a rotation angle theta = omega dt of 1e-3 the two coefficients are their Taylor
// series, dt (1 - theta^2/6 + theta^4/120) and dt^2 (1/2 - theta^2/24 + theta^4/720), whose first
// omitted terms are below 1e-21 relative there (the note's small-angle guard: at omega -> 0 the
// quotients lose every digit). In 2D M is the plane rotation by theta = dt W_10; in 1D M = I.
#include "core/Tensor.hpp"

#include <cmath>

namespace mfdyn::fpm {

// sin(theta)/omega and (1 - cos(theta))/omega^2 for theta = omega dt, guarded at small theta.
inline void rodriguesCoefficients(double omega, double dt, double& a, double& b) {
    const double theta = omega * dt;
    if (std::abs(theta) < 1e-3) {
        const double t2 = theta * theta;
        a = dt * (1.0 - t2 / 6.0 + t2 * t2 / 120.0);
        b = dt * dt * (0.5 - t2 / 24.0 + t2 * t2 / 720.0);
    } else {
        a = std::sin(theta) / omega;
        b = (1.0 - std::cos(theta)) / (omega * omega);
    }
}

// exp(dt W) for a skew W (its symmetric part is ignored: W is taken as (W - W^T) / 2).
template <int Dim>
Tensor<Dim> spinExponential(const Tensor<Dim>& spin, double dt) {
    const Tensor<Dim> W = 0.5 * (spin - spin.transpose());
    if constexpr (Dim == 1) {
        return Tensor<Dim>::Identity();
    } else if constexpr (Dim == 2) {
        const double theta = dt * W(1, 0);
        Tensor<Dim> M;
        M << std::cos(theta), -std::sin(theta), std::sin(theta), std::cos(theta);
        return M;
    } else {
        const double omega = std::sqrt(W(2, 1) * W(2, 1) + W(0, 2) * W(0, 2) + W(1, 0) * W(1, 0));
        double a, b;
        rodriguesCoefficients(omega, dt, a, b);
        return Tensor<Dim>::Identity() + a * W + b * (W * W);
    }
}

// The rotation by angle omega dt about the unit axis n (right-handed), as a 3x3 matrix: the exact
// motion of a rigidly rotating body over a step, x <- c + Q (x - c).
inline Tensor<3> axisRotation(const Vector<3>& axis, double omega, double dt) {
    Tensor<3> K;
    K << 0, -axis(2), axis(1), axis(2), 0, -axis(0), -axis(1), axis(0), 0;
    double a, b;
    rodriguesCoefficients(omega, dt, a, b);  // of the unit spin omega K: a omega K, b omega^2 K^2
    return Tensor<3>::Identity() + a * omega * K + b * omega * omega * (K * K);
}

// S <- M S M^T.
template <int Dim>
SymmTensor<Dim> rotated(const SymmTensor<Dim>& S, const Tensor<Dim>& M) {
    return SymmTensor<Dim>::fromFull(M * S.full() * M.transpose());
}

}  // namespace mfdyn::fpm
