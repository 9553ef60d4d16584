#pragma once
// mpmFsi's updated-Lagrangian material path: the materials of impactSph (an equationOfState and
// an optional strength law, materials/MaterialSet.hpp) on material points, beside the
// total-Lagrangian constitutive laws of tlSph. A material names either a constitutiveLaw or an
// equationOfState (with or without a strength law), never both:
//
//     materials
//     {
//         copper { #includeEtc "materials/copperTaylorBar"  s 1.5; gamma0 2.0;
//                  equationOfState { type mieGruneisen; }  strength { type vonMises; deviator three; } }
//         water  { equationOfState { type tait; rho0 1000; c0 1480; gamma 7; } }   // a fluid: no tau
//         oil    { equationOfState { type tait; rho0 900; B 1e6; gamma 7; }
//                  viscosity { type newtonian; mu 0.1; } }                          // a viscous fluid
//     }
//
// Per particle p, over a step dt with the velocity gradient L of the solver (L = sum_I v_I (x)
// grad N_Ip, the same L that advances F <- (I + dt L) F), D = sym L, and J^n, J^{n+1} = det F
// before and after (doc/methods/sph-impact.md sections 5.1 and 5.2 for the laws, the same
// conventions as impactSph):
//
//   density     rho^{n+1} = rho0 / J^{n+1}                      (mass conservation, exact in J)
//   deviator    tau^{n+1} = strength.update(tau^n, L, dt)       (Jaumann rate, forward Euler, then
//                                                                the return to the yield surface)
//   energy      de/dt = (-p tr D + tau:D) / rho, discretised with the volume change the particle
//               actually had, tr D dt / rho ~ (J^{n+1} - J^n) / rho0, and step averages:
//                   e^{n+1} = e^n - pbar (J^{n+1} - J^n) / rho0
//                                 + dt (tau^n + tau^{n+1})/2 : D (J^n + J^{n+1}) / (2 rho0)
//               pbar = (p^n + p*)/2, p* = P(rho^{n+1}, e*) from the predictor e* (the same update
//               with pbar = p^n): exact for a barotropic law (P(rho) only), second order otherwise.
//               The pressure work then equals -int p dV of the discrete volume, so the stored
//               energy sum m e balances the kinetic energy to the order of the step.
//   viscosity   a fluid with a viscosity (materials/viscosity/, never beside a strength law) has
//               the viscous deviator tau_v = 2 mu dev D of the present L, dev D = D - tr D/3 I
//               (Stokes' hypothesis; D_zz = 0 below 3D), not stored; its work tau_v:D enters
//               the deviatoric energy term above beside tau:D (dissipation into e)
//   pressure    p^{n+1} = P(rho^{n+1}, e^{n+1}) and c from the equation of state
//   stress      sigma = -p I + tau + tau_v; below 3D (plane strain) sigma_zz = -p + tau_zz
//               - 2 mu tr D / 3 with tau_zz the component implied by tr tau = 0 under `deviator
//               three` (Strength.hpp), 0 under `deviator dimension`
//   stored      W = rho0 e (per reference volume), so that the solver's sum V0 W is sum m e, the
//               internal energy conservedQuantities adds to the kinetic energy (plastic work
//               included: tau:D holds it, Strength.hpp)
//   wave speed  for the CFL vote, c_p = sqrt(c^2 + 4/3 G / rho) (the p-wave speed of the solid,
//               c alone for a fluid), c^2 floored at the equation of state's c^2(rho0, 0), so
//               that a state in tension (where c^2 may be negative) never shortens the vote to
//               NaN or lengthens it beyond the reference.
//
// Fields (allocated only when some material takes this path, each only where a model uses it):
// specificInternalEnergy e (always: the stored energy), pressure, soundSpeed, deviatoricStress
// (a strength law that carries stress), plasticStrain (its hardening), temperature (johnsonCook;
// set to the law's initialTemperature on a fresh start). A fresh start has e = 0 and tau = 0
// unless the particle file gives them.
#include "materials/MaterialSet.hpp"
#include "particles/ParticleSet.hpp"

#include <cstdint>
#include <vector>

namespace mfdyn {

class Dictionary;

template <int Dim>
class UpdatedLagrangianStress {
public:
    // Checks every material (a constitutiveLaw, or an equationOfState with an optional strength:
    // an InputError at the entry otherwise, naming what mpmFsi takes) and allocates the fields.
    // `particles` must hold the integer field "material" (solver/MaterialAssignment).
    UpdatedLagrangianStress(const MaterialSet<Dim>& materials, ParticleSet<Dim>& particles);

    // Some material takes this path.
    bool any() const { return any_; }
    // Material k takes this path (it has an equation of state).
    bool handles(std::int64_t k) const { return ul_[std::size_t(k)] != 0; }
    // rho0 of material k, from its equation of state or its constitutive law.
    double referenceDensity(std::int64_t k) const;

    // Particle p (of a material this path handles): with advance, the step above from J^n = Jold
    // to J^{n+1} = Jnew over dt with velocity gradient L; without, only p, c and sigma of the
    // present state (the start, or a restart). Writes sigma (in-plane), sigmaZZ (below 3D, may be
    // null in 3D) and W = rho0 e.
    void update(std::size_t p, const Tensor<Dim>& L, double Jold, double Jnew, double rho0, double dt,
                bool advance, SymmTensor<Dim>& sigma, double* sigmaZZ, double& W);

    // The p-wave speed of particle p for the CFL vote (see the header comment).
    double waveSpeed(std::size_t p, double rho0) const;

    // Material k is a fluid: an equation of state and no strength law (its deviatoric stress, if
    // any, is viscous). Pressure smoothing (PressureSmoothing.hpp) acts on fluids only.
    bool isFluid(std::int64_t k) const;
    // The equation of state's pressure of particle p at jacobian J (density rho0 / J), with the
    // particle's present specific internal energy; no state is changed.
    double pressureAt(std::size_t p, double J, double rho0) const;
    // The particles' stored pressure p^n (the next energy update's), null before bind: pressure
    // smoothing writes the pressure it gives a particle here, so the field written and the next
    // step's pressure work agree with the stress.
    std::vector<double>* pressureField() const { return p_; }
    // The viscous time-step limit of particle p, rho dx^2 / (4 mu) (doc/methods/mpm.md 2.7), with
    // rho = rho0 / J; infinity for a material without viscosity.
    double viscousTimeStep(std::size_t p, double rho0, double dx) const;

private:
    const MaterialSet<Dim>& materials_;
    std::vector<char> ul_;
    std::vector<double> floorC2_;  // c^2(rho0, 0) per material
    bool any_ = false;
    const std::vector<std::int64_t>* material_ = nullptr;
    const std::vector<double>* J_ = nullptr;
    std::vector<double>* e_ = nullptr;
    std::vector<double>* p_ = nullptr;
    std::vector<double>* c_ = nullptr;
    std::vector<SymmTensor<Dim>>* tau_ = nullptr;
    std::vector<double>* plasticStrain_ = nullptr;
    std::vector<double>* temperature_ = nullptr;
};

extern template class UpdatedLagrangianStress<1>;
extern template class UpdatedLagrangianStress<2>;
extern template class UpdatedLagrangianStress<3>;

}  // namespace mfdyn
