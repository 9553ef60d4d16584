#pragma once
// The swinging cube of Lee et al. 2016 (eq. 52; doc/methods/tl-jst-sph.md 8.2): a standing
// irrotational wave of small-strain linear elasticity in the unit cube [0, 1]^Dim, with rollers
// (u_n = 0) on the planes X_k = 0 and skew-symmetric conditions (tangential u = 0) on X_k = 1.
// Equations, the frequency in Dim dimensions and the checks are in SwingingCube.cpp.
#include "core/Tensor.hpp"

namespace mfdyn {

template <int Dim>
class SwingingCube {
public:
    // Reference density rho0 [kg/m^3], Young's modulus E [Pa], Poisson's ratio nu, amplitude U0 [m].
    // Throws Error unless rho0 > 0, E > 0, -1 < nu < 0.5 and U0 finite.
    SwingingCube(double rho0, double youngsModulus, double poissonRatio, double amplitude);

    // The mode shape U0 phi(X) (the displacement at t = 0) and its gradient dPhi_i/dX_J: the
    // functions the initial state and the exact solution share.
    static Vector<Dim> modeShape(const Vector<Dim>& X, double amplitude);
    static Tensor<Dim> modeGradient(const Vector<Dim>& X, double amplitude);

    double lambda() const { return lambda_; }
    double mu() const { return mu_; }
    // Dilatational wave speed c_d = sqrt((lambda + 2 mu)/rho0) and omega = sqrt(Dim)/2 c_d pi.
    double waveSpeed() const { return cd_; }
    double angularFrequency() const { return omega_; }
    double period() const;

    Vector<Dim> displacement(const Vector<Dim>& X, double t) const;
    Vector<Dim> velocity(const Vector<Dim>& X, double t) const;
    // p = rho0 v.
    Vector<Dim> momentum(const Vector<Dim>& X, double t) const;
    Tensor<Dim> displacementGradient(const Vector<Dim>& X, double t) const;
    // F = I + grad u.
    Tensor<Dim> deformationGradient(const Vector<Dim>& X, double t) const;
    // P = lambda tr(grad u) I + mu (grad u + grad u^T), the linearElastic law.
    Tensor<Dim> firstPiolaStress(const Vector<Dim>& X, double t) const;

private:
    double rho0_, lambda_, mu_, U0_, cd_, omega_;
};

extern template class SwingingCube<1>;
extern template class SwingingCube<2>;
extern template class SwingingCube<3>;

}  // namespace mfdyn
