// mpmFsi's updated-Lagrangian material path (UpdatedLagrangianStress.hpp, where the equations
// are): equation of state + strength law (or viscosity) per particle, from the solver's velocity
// gradient and J.
#include "mpm/UpdatedLagrangianStress.hpp"

#include "core/Dictionary.hpp"
#include "core/Error.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace mfdyn {

template <int Dim>
UpdatedLagrangianStress<Dim>::UpdatedLagrangianStress(const MaterialSet<Dim>& materials,
                                                      ParticleSet<Dim>& particles)
    : materials_(materials) {
    const std::size_t count = materials.size();
    ul_.assign(count, 0);
    floorC2_.assign(count, 0.0);
    bool strength = false, hardening = false, temperature = false;
    for (std::size_t k = 0; k < count; ++k) {
        const auto& m = materials[k];
        const Dictionary& dict = *m.dict;
        // One path per material: the constitutive law is a total stress of F, the equation of
        // state + strength an updated pair (p, tau); both would be two stresses for one body.
        if (m.constitutiveLaw && m.eos)
            throw dict.error("equationOfState",
                             "material '" + m.name +
                                 "' names both a constitutiveLaw and an equationOfState: mpmFsi takes "
                                 "one or the other per material (a constitutiveLaw, or an "
                                 "equationOfState with an optional strength)");
        if (!m.eos && dict.findDict("strength"))
            throw dict.error("strength", "material '" + m.name +
                                             "' names a strength law without an equationOfState: the "
                                             "strength law gives only the deviator tau; mpmFsi takes an "
                                             "equationOfState for the pressure beside it");
        if (!m.eos) continue;
        ul_[k] = 1;
        any_ = true;
        const double rho0 = m.eos->referenceDensity();
        if (!(rho0 > 0))
            throw dict.error("equationOfState", "material '" + m.name +
                                                    "': its equationOfState has no reference density "
                                                    "rho0, which mpmFsi needs (V0 = mass / rho0)");
        floorC2_[k] = std::max(0.0, m.eos->soundSpeedSquared(rho0, 0.0));
        if (m.strength) {
            strength = true;
            hardening = hardening || m.strength->usesPlasticStrain();
            temperature = temperature || m.strength->usesTemperature();
        }
    }
    if (!any_) return;
    material_ = &particles.integerField("material");
    J_ = &particles.scalarField("jacobian");
    e_ = &particles.scalarField("specificInternalEnergy");
    p_ = &particles.scalarField("pressure");
    c_ = &particles.scalarField("soundSpeed");
    if (strength) tau_ = &particles.symmTensorField("deviatoricStress");
    if (hardening) plasticStrain_ = &particles.scalarField("plasticStrain");
    if (temperature) {
        const bool had = particles.hasField("temperature");
        temperature_ = &particles.scalarField("temperature");
        if (!had)
            for (std::size_t i = 0; i < material_->size(); ++i)
                if (const auto& law = materials[std::size_t((*material_)[i])].strength;
                    law && law->usesTemperature())
                    (*temperature_)[i] = law->initialTemperature();
    }
}

template <int Dim>
double UpdatedLagrangianStress<Dim>::referenceDensity(std::int64_t k) const {
    const auto& m = materials_[std::size_t(k)];
    return m.eos ? m.eos->referenceDensity() : m.constitutiveLaw->referenceDensity();
}

template <int Dim>
void UpdatedLagrangianStress<Dim>::update(std::size_t p, const Tensor<Dim>& L, double Jold, double Jnew,
                                          double rho0, double dt, bool advance, SymmTensor<Dim>& sigma,
                                          double* sigmaZZ, double& W) {
    const std::size_t k = std::size_t((*material_)[p]);
    const auto& m = materials_[k];
    const EquationOfState& eos = *m.eos;
    const Strength<Dim>* law = m.strength.get();
    const double rho = rho0 / Jnew;
    double& e = (*e_)[p];
    double pressure, c;
    SymmTensor<Dim> zero{};
    SymmTensor<Dim>& tau = law ? (*tau_)[p] : zero;
    const Tensor<Dim> D = 0.5 * (L + L.transpose());
    // A fluid's viscous deviator from the present rate, tau_v = 2 mu dev D with the trace of the
    // 3D rate (D_zz = 0 below 3D: plane strain), so tau_v,zz = -2 mu tr D / 3 (Newtonian.cpp).
    const double mu = m.viscosity ? m.viscosity->dynamicViscosity(rho, e) : 0.0;
    const double trD = D.trace();
    Tensor<Dim> tauV = Tensor<Dim>::Zero();
    if (mu > 0) {
        tauV = 2.0 * mu * D;
        for (int d = 0; d < Dim; ++d) tauV(d, d) -= 2.0 * mu * trD / 3.0;
    }
    if (advance && dt > 0) {
        const SymmTensor<Dim> tauOld = tau;
        if (law) {
            typename Strength<Dim>::Fields f;
            f.size = 1;
            f.velocityGradient = &L;
            f.density = &rho;
            f.tau = &tau;
            f.plasticStrain = plasticStrain_ ? &(*plasticStrain_)[p] : nullptr;
            f.temperature = temperature_ ? &(*temperature_)[p] : nullptr;
            law->update(f, dt);
        }
        // tau:D with the step average of tau, per unit mass with the average specific volume.
        // The viscous work tau_v:D = 2 mu dev D:dev D >= 0 (the out-of-plane tau_v,zz does no work,
        // D_zz = 0) is added the same way: dissipation into e, so that m e + kinetic stays closed.
        const double deviatoric =
            dt * ((0.5 * (tauOld.full() + tau.full())).cwiseProduct(D).sum() + tauV.cwiseProduct(D).sum()) *
            (Jold + Jnew) / (2.0 * rho0);
        const double dV = (Jnew - Jold) / rho0;  // change of the specific volume 1/rho
        const double pOld = (*p_)[p];
        const double ePredicted = e - pOld * dV + deviatoric;
        double pPredicted, cPredicted;
        eos.evaluate(1, &rho, &ePredicted, &pPredicted, &cPredicted);
        e = e - 0.5 * (pOld + pPredicted) * dV + deviatoric;
    }
    eos.evaluate(1, &rho, &e, &pressure, &c);
    (*p_)[p] = pressure;
    (*c_)[p] = c;
    Tensor<Dim> s = tau.full() + tauV;
    for (int d = 0; d < Dim; ++d) s(d, d) -= pressure;
    sigma = SymmTensor<Dim>::fromFull(s);
    if (sigmaZZ) {
        // The out-of-plane normal deviator implied by tr tau = 0 (Strength.hpp), 0 without it.
        double tauZZ = 0;
        if (law && law->impliedComponents() > 0) tauZZ = -tau.full().trace() / law->impliedComponents();
        *sigmaZZ = -pressure + tauZZ - 2.0 * mu * trD / 3.0;
    }
    W = rho0 * e;
}

template <int Dim>
double UpdatedLagrangianStress<Dim>::waveSpeed(std::size_t p, double rho0) const {
    const std::size_t k = std::size_t((*material_)[p]);
    const auto& m = materials_[k];
    const double rho = rho0 / (*J_)[p];
    const double c = (*c_)[p];
    const double c2 = std::max(std::isfinite(c) ? c * c : 0.0, floorC2_[k]);
    const double shear = m.strength ? 4.0 / 3.0 * m.strength->shearModulus() / rho : 0.0;
    return std::sqrt(c2 + shear);
}

template <int Dim>
bool UpdatedLagrangianStress<Dim>::isFluid(std::int64_t k) const {
    return handles(k) && !materials_[std::size_t(k)].strength;
}

template <int Dim>
double UpdatedLagrangianStress<Dim>::pressureAt(std::size_t p, double J, double rho0) const {
    const auto& m = materials_[std::size_t((*material_)[p])];
    return m.eos->pressure(rho0 / J, (*e_)[p]);
}

template <int Dim>
double UpdatedLagrangianStress<Dim>::viscousTimeStep(std::size_t p, double rho0, double dx) const {
    const auto& m = materials_[std::size_t((*material_)[p])];
    const double mu = m.viscosity ? m.viscosity->maximumViscosity() : 0.0;
    if (!(mu > 0)) return std::numeric_limits<double>::infinity();
    // The explicit diffusion limit of the momentum equation, nu dt / dx^2 <= 1/4 (note 2.7).
    const double rho = rho0 / (*J_)[p];
    return rho * dx * dx / (4.0 * mu);
}

template class UpdatedLagrangianStress<1>;
template class UpdatedLagrangianStress<2>;
template class UpdatedLagrangianStress<3>;

}  // namespace mfdyn
