#pragma once
// Strength laws: the family `strength`, the deviatoric part of the stress of a solid.
//
// The total stress is sigma = -P I + tau (doc/methods/sph-impact.md section 5.2); the equation of state gives
// P, a strength law advances the deviatoric stress tau and its history (equivalent plastic strain,
// temperature). Conventions, fixed for every model:
//
//     L_ab = dv_a/dx_b (the velocity gradient, as the SPH loop computes it),
//     D = sym L = (L + L^T)/2,   W = skew L = (L - L^T)/2,
//     Jaumann rate:  dtau/dt = W tau - tau W + 2mu (D - alpha tr(D) I),
//
// with 2mu = shearFactor G (shearFactor 2, the standard law, or 1, the thesis's printed 6.7) and
// alpha = 1/d (deviator dimension, the thesis: no out-of-plane deviator) or 1/3 (deviator three:
// plane strain in 2D, uniaxial strain in 1D). In index form W tau - tau W is
// tau_ag w_bg + tau_gb w_ag with w_ab = (dv_a/dx_b - dv_b/dx_a)/2, the note's (6.7) with its
// rho-dot_ab = (d_b v_a - d_a v_b)/2, so the law is the thesis's; the tests check the sense of
// rotation against tau(t) = Q tau0 Q^T for the rigid motion v = W x, Q = exp(W t).
//
// Under `deviator three` with d < 3, tau holds the in-plane components only; the 3 - d normal
// components out of the plane are equal and implied by tr tau = 0 (each -tr_d(tau)/(3 - d)), and
// enter J2 and the equivalent stress. Under `deviator dimension`, tr tau = 0 in the plane.
//
// Equivalent stress sigmaEq = sqrt(3 J2), J2 = tau:tau/2 (plus the implied components);
// equivalent strain rate epsDotEq = sqrt(2/3 D':D'), D' = D - alpha tr(D) I, so that
// sigmaEq = 3 G epsEq in the elastic range (2mu = 2G) for any loading path without rotation.
//
// Interface for solver loops: one virtual call per block of particles, with the fields as plain
// arrays (struct Fields). A solver either
//   - calls update(fields, dt): tau <- tau + dt dtau/dt (forward Euler), then the return to the
//     yield surface, the thesis's step 5; or
//   - integrates tau itself from stressRate(fields) and calls returnToYieldSurface(fields, dt)
//     after each stage that changes tau.
// Both are per-particle updates (own data only) and may run on disjoint blocks in parallel.
//
// Fields a model uses (ParticleSet allocates only those): allocatesStress() (tau; false for
// `none`, so a fluid carries no tau), usesPlasticStrain(), usesTemperature() (initialise it to
// initialTemperature()), usesDensity().
//
// Keywords: each model declares them once in `static KeywordSchema keywords()` (core/
// KeywordSchema.hpp) and reads its dictionary through it; `-describe strength` and
// doc/models/strength/ list them. Parameters are read from the strength dictionary, then from the
// enclosing material dictionary (dict.parent(), orEnclosing), so that shared constants stay with
// the material:
//
//     materials { target { rho0 2785; shearModulus 27.1e9; yieldStress 0.265e9;
//                          strength { type vonMises; } } }
//
// Plastic work. plasticWorkRate receives sigma:dEpsP/dt per unit volume [W/m^3]. The SPH energy
// equation's deviatoric term tau:D/rho (the note's Y_i) already contains it: it is for the
// temperature of johnsonCook and for diagnostics, and must not be added to e again.
#include "core/Dictionary.hpp"
#include "core/Registry.hpp"
#include "core/Tensor.hpp"

#include <cstddef>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace mfdyn {

template <int Dim>
class Strength {
public:
    static constexpr const char* familyName = "strength";
    using Selector = Registry<Strength, const Dictionary&>;
    static std::unique_ptr<Strength> New(const Dictionary& dict) { return Selector::New(dict); }

    // One block of particles. Arrays have `size` entries; pointers a model does not use may be
    // null (see the uses...() queries).
    struct Fields {
        std::size_t size = 0;
        const Tensor<Dim>* velocityGradient = nullptr;  // in: L_ab = dv_a/dx_b [1/s]
        const double* density = nullptr;                // in: rho [kg/m^3] (johnsonCook heating)
        SymmTensor<Dim>* tau = nullptr;                 // in/out: deviatoric stress [Pa]
        SymmTensor<Dim>* tauRate = nullptr;             // out of stressRate: Jaumann rate [Pa/s]
        double* plasticStrain = nullptr;                // in/out: equivalent plastic strain [-]
        double* temperature = nullptr;                  // in/out: temperature [K]
        double* plasticWorkRate = nullptr;              // out, optional: sigma:dEpsP/dt [W/m^3]
    };

    virtual ~Strength() = default;
    Strength(const Strength&) = delete;
    Strength& operator=(const Strength&) = delete;

    const std::string& type() const { return type_; }

    virtual bool allocatesStress() const { return true; }
    virtual bool usesPlasticStrain() const { return false; }
    virtual bool usesTemperature() const { return false; }
    virtual bool usesDensity() const { return false; }
    // The temperature a solver starts particles at when usesTemperature().
    virtual double initialTemperature() const { return 0.0; }

    // tau <- tau + dt dtau/dt, then returnToYieldSurface. Needs velocityGradient and tau.
    virtual void update(const Fields& fields, double dt) const = 0;
    // tauRate = Jaumann rate at the current tau. Needs velocityGradient, tau, tauRate.
    virtual void stressRate(const Fields& fields) const = 0;
    // Project tau onto the yield surface and advance the history; dt is the step over which the
    // trial stress was reached (for the plastic work rate and strain-rate dependence).
    virtual void returnToYieldSurface(const Fields& /*fields*/, double /*dt*/) const {}

    // Flow stress sigma_Y [Pa] at an equivalent plastic strain, equivalent strain rate [1/s] and
    // temperature [K]: +infinity for a law without yield, 0 for `none`.
    virtual double yieldStress(double plasticStrain, double strainRate, double temperature) const = 0;

    // G [Pa] (0 for none).
    double shearModulus() const { return shearModulus_; }
    // M [Pa], what the law's elastic response adds to rho c^2 for a longitudinal (uniaxial-strain)
    // wave: the normal deviatoric stress per unit strain of the Jaumann rate above, 2mu (1 - alpha)
    // (4G/3 in 3D), so that the elastic wave speed is sqrt(c^2 + M/rho). 0 for a law without an
    // elastic deviator. A time-step vote that leaves it out runs the shear part beyond its limit.
    virtual double longitudinalStiffness() const { return 0.0; }
    // sqrt(3 J2) with the implied out-of-plane components (see the header comment).
    double equivalentStress(const SymmTensor<Dim>& tau) const;
    // sqrt(2/3 D':D') of the strain rate of L with the same deviator convention.
    double equivalentStrainRate(const Tensor<Dim>& velocityGradient) const;
    // The trace weight alpha of the deviator: 1/d or 1/3.
    double deviatorWeight() const { return deviatorWeight_; }
    // Normal components outside the dimension carried implicitly by tr tau = 0 (0 or 3 - d).
    int impliedComponents() const { return impliedComponents_; }

protected:
    explicit Strength(const Dictionary& dict);

    // A number as a user would write it (0.265e9 as 2.65e+08, not 265000000.000000).
    static std::string formatNumber(double value);

    double shearModulus_ = 0.0;
    double deviatorWeight_ = 1.0 / Dim;
    int impliedComponents_ = 0;

private:
    std::string type_;
};

}  // namespace mfdyn
