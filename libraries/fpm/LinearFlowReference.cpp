// The uniform-state reference of the academic validations: see LinearFlowReference.hpp (the ODE
// and its source).
#include "fpm/LinearFlowReference.hpp"

#include "materials/equationOfState/EquationOfState.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>

namespace mfdyn::fpm {

template <int Dim>
LinearFlowReference<Dim>::LinearFlowReference(const Tensor<Dim>& A, bool moving, Parts parts,
                                              const EquationOfState* eos, double mu, double alpha,
                                              UniformState<Dim> start)
    : A_(A), moving_(moving), parts_(parts), eos_(eos), mu_(mu), alpha_(alpha), start_(start) {}

template <int Dim>
Tensor<Dim> LinearFlowReference<Dim>::gradient(double t) const {
    if (!moving_) return A_;
    const Tensor<Dim> F = Tensor<Dim>::Identity() + t * A_;
    return A_ * F.inverse();
}

template <int Dim>
UniformState<Dim> LinearFlowReference<Dim>::rate(double t, const UniformState<Dim>& s) const {
    const Tensor<Dim> G = gradient(t);
    const Tensor<Dim> D = 0.5 * (G + G.transpose()), W = 0.5 * (G - G.transpose());
    const double trace = G.trace();
    const Tensor<Dim> S = s.S.full();
    UniformState<Dim> r;
    r.rho = 0;
    r.p = 0;
    r.e = 0;
    Tensor<Dim> dS = Tensor<Dim>::Zero();
    const double c2 = !eos_            ? 0.0
                      : parts_.literal ? eos_->densityDerivative(s.rho, s.e)
                                       : eos_->soundSpeedSquared(s.rho, s.e);
    const double g = eos_ ? eos_->energyDerivative(s.rho, s.e) : 0.0;
    if (parts_.euler) {
        r.rho = -s.rho * trace;
        r.p += -s.rho * c2 * trace;
        r.e += -s.p * trace / s.rho;
    }
    if (parts_.shear) {
        const double work = (S.array() * D.array()).sum();
        r.p += (g / s.rho) * (work - (parts_.literal ? s.p * trace : 0.0));
        r.e += work / s.rho;
        dS += 2.0 * mu_ * (D - alpha_ * trace * Tensor<Dim>::Identity());
    }
    if (parts_.rotation) dS += W * S - S * W;
    r.S = SymmTensor<Dim>::fromFull(dS);
    return r;
}

template <int Dim>
UniformState<Dim> LinearFlowReference<Dim>::advanced(UniformState<Dim> s, double t0, double t1) const {
    const int steps = std::max(1, int(std::ceil(std::abs(t1 - t0) / 1e-3)));
    const double h = (t1 - t0) / steps;
    const auto axpy = [](const UniformState<Dim>& a, double f, const UniformState<Dim>& b) {
        UniformState<Dim> r = a;
        r.rho += f * b.rho;
        r.p += f * b.p;
        r.e += f * b.e;
        for (int k = 0; k < SymmTensor<Dim>::size; ++k) r.S.c[std::size_t(k)] += f * b.S.c[std::size_t(k)];
        return r;
    };
    for (int k = 0; k < steps; ++k) {
        const double t = t0 + k * h;
        const UniformState<Dim> k1 = rate(t, s);
        const UniformState<Dim> k2 = rate(t + 0.5 * h, axpy(s, 0.5 * h, k1));
        const UniformState<Dim> k3 = rate(t + 0.5 * h, axpy(s, 0.5 * h, k2));
        const UniformState<Dim> k4 = rate(t + h, axpy(s, h, k3));
        s = axpy(s, h / 6.0, k1);
        s = axpy(s, h / 3.0, k2);
        s = axpy(s, h / 3.0, k3);
        s = axpy(s, h / 6.0, k4);
    }
    return s;
}

template class LinearFlowReference<1>;
template class LinearFlowReference<2>;
template class LinearFlowReference<3>;

}  // namespace mfdyn::fpm
