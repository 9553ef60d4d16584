// Swinging cube: Lee, Gil, Greto, Karim & Bonet 2016, "A new Jameson-Schmidt-Turkel Smooth
// Particle Hydrodynamics algorithm for large strain explicit fast dynamics", Comput. Methods
// Appl. Mech. Engrg. 311:71, section 8.2, eq. (52); doc/methods/tl-jst-sph.md 8.2.
//
//     u(X, t) = U0 cos(omega t) phi(X),
//     phi     = [sin(pi X/2) cos(pi Y/2) cos(pi Z/2), cos sin cos, cos cos sin]   (3D)
//
// with the factors of the absent coordinates dropped in 2D and 1D (1D: phi = sin(pi X/2)).
// phi = grad psi, psi = -(2/pi) prod_k cos(pi X_k/2), so phi is irrotational and
// lap psi = -Dim (pi/2)^2 psi. Small-strain linear elasticity,
//
//     rho0 u_tt = mu lap u + (lambda + mu) grad div u = (lambda + 2 mu) grad div u   (curl u = 0),
//
// with grad div u = grad lap psi U0 cos(omega t) = -Dim (pi/2)^2 u, is satisfied when
//
//     omega = sqrt(Dim)/2 c_d pi,   c_d = sqrt((lambda + 2 mu)/rho0).
//
// The paper's sqrt(3)/2 is the 3D case of this (c_d = 144.2 m/s, omega = 392.4 rad/s, T = 16.01 ms
// for rho0 = 1100, E = 17 MPa, nu = 0.3); 2D is plane strain with the same lambda, mu.
// Boundary values: phi_k = 0 on X_k = 0 (rollers, u_n = 0); phi_j = 0 (j != k) on X_k = 1
// (tangential u = 0). Valid while the strain is small (U0 << 1; the note: U0 < 1e-3 m).
//
//     v = du/dt,  p = rho0 v,  F = I + grad u,  P = lambda tr(grad u) I + mu (grad u + grad u^T).
#include "verification/SwingingCube.hpp"

#include "core/Error.hpp"

#include <cmath>
#include <numbers>

namespace mfdyn {

template <int Dim>
SwingingCube<Dim>::SwingingCube(double rho0, double E, double nu, double amplitude)
    : rho0_(rho0), U0_(amplitude) {
    if (!(rho0 > 0) || !(E > 0) || !(nu > -1 && nu < 0.5) || !std::isfinite(amplitude))
        throw Error("swinging cube: expected rho0 > 0, E > 0, -1 < nu < 0.5 and a finite amplitude");
    mu_ = E / (2 * (1 + nu));
    lambda_ = E * nu / ((1 + nu) * (1 - 2 * nu));
    cd_ = std::sqrt((lambda_ + 2 * mu_) / rho0);
    omega_ = std::sqrt(double(Dim)) / 2 * cd_ * std::numbers::pi;
}

template <int Dim>
Vector<Dim> SwingingCube<Dim>::modeShape(const Vector<Dim>& X, double amplitude) {
    const double k = std::numbers::pi / 2;
    Vector<Dim> u;
    for (int i = 0; i < Dim; ++i) {
        double f = amplitude;
        for (int j = 0; j < Dim; ++j) f *= i == j ? std::sin(k * X(j)) : std::cos(k * X(j));
        u(i) = f;
    }
    return u;
}

template <int Dim>
Tensor<Dim> SwingingCube<Dim>::modeGradient(const Vector<Dim>& X, double amplitude) {
    const double k = std::numbers::pi / 2;
    Tensor<Dim> g;
    for (int i = 0; i < Dim; ++i)
        for (int J = 0; J < Dim; ++J) {
            // d/dX_J of prod_j (i == j ? sin : cos)(k X_j): differentiate the J-th factor.
            double f = amplitude * k;
            for (int j = 0; j < Dim; ++j) {
                const double s = std::sin(k * X(j)), c = std::cos(k * X(j));
                if (j == J)
                    f *= i == j ? c : -s;
                else
                    f *= i == j ? s : c;
            }
            g(i, J) = f;
        }
    return g;
}

template <int Dim>
double SwingingCube<Dim>::period() const {
    return 2 * std::numbers::pi / omega_;
}

template <int Dim>
Vector<Dim> SwingingCube<Dim>::displacement(const Vector<Dim>& X, double t) const {
    return modeShape(X, U0_ * std::cos(omega_ * t));
}

template <int Dim>
Vector<Dim> SwingingCube<Dim>::velocity(const Vector<Dim>& X, double t) const {
    return modeShape(X, -U0_ * omega_ * std::sin(omega_ * t));
}

template <int Dim>
Vector<Dim> SwingingCube<Dim>::momentum(const Vector<Dim>& X, double t) const {
    return rho0_ * velocity(X, t);
}

template <int Dim>
Tensor<Dim> SwingingCube<Dim>::displacementGradient(const Vector<Dim>& X, double t) const {
    return modeGradient(X, U0_ * std::cos(omega_ * t));
}

template <int Dim>
Tensor<Dim> SwingingCube<Dim>::deformationGradient(const Vector<Dim>& X, double t) const {
    return Tensor<Dim>::Identity() + displacementGradient(X, t);
}

template <int Dim>
Tensor<Dim> SwingingCube<Dim>::firstPiolaStress(const Vector<Dim>& X, double t) const {
    const Tensor<Dim> H = displacementGradient(X, t);
    return lambda_ * H.trace() * Tensor<Dim>::Identity() + mu_ * (H + H.transpose());
}

template class SwingingCube<1>;
template class SwingingCube<2>;
template class SwingingCube<3>;

}  // namespace mfdyn
