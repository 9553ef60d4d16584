// Von Mises plasticity by radial return (Wilkins 1964, "Calculation of elastic-plastic flow",
// Methods in Computational Physics 3:211; Krieg & Key 1976 for the hardening case; Zisis 2017
// Eq. 6.14 corrected, doc/methods/sph-impact.md section 5.2 and erratum 9):
//
//     trial:   tau* = tau_n + dt dtau/dt (hookean),  sigma* = sqrt(3 J2(tau*)),  J2 = tau:tau/2
//     yield:   sigma_Y = sigma_Y0 + H epsP
//     if sigma* > sigma_Y:
//         dEpsP   = (sigma* - sigma_Y) / (3G + H)
//         sigma'  = sigma_Y + H dEpsP                     (= sigma_Y(epsP + dEpsP))
//         tau     = tau* sigma'/sigma*                    (on the surface)
//     libersky:   tau = tau* (sigma'/sigma*)^2, the factor min(1, sigma_Y^2/(3 J2)) of Libersky,
//                 Petschek, Carney, Hipp & Allahdadi 1993 (J. Comput. Phys. 109:67); the stress
//                 lands inside the surface at sigma'^2/sigma*; epsP follows the consistent return.
//
// 3G stands for 1.5 * 2mu, so that shearFactor 1 returns consistently with its own elastic law.
// Plastic work per unit volume: sigma' dEpsP (associated flow: tau:dEps_p = sigma_eq dEpsP).
// Exact for perfect plasticity and linear hardening with the trial stress of a straight strain
// path in a step; rate- and temperature-independent.
#include "materials/strength/VonMises.hpp"

#include <stdexcept>

namespace mfdyn {

template <int Dim>
KeywordSchema VonMises<Dim>::keywords() {
    return Hookean<Dim>::keywords()
        .rename(Strength<Dim>::familyName, "vonMises")
        .scalar("yieldStress", "Pa", "initial yield stress sigma_Y0")
        .greaterThan(0)
        .orEnclosing()
        .scalar("hardeningModulus", "Pa", "linear isotropic hardening modulus H")
        .atLeast(0)
        .orDefault(0.0)
        .orEnclosing()
        .flag("libersky",
              "return by the factor (sigma_Y/sigma*)^2 of Libersky et al. 1993 instead of radially")
        .orDefault(false)
        .orEnclosing();
}

template <int Dim>
VonMises<Dim>::VonMises(const Dictionary& dict) : VonMises(dict, keywords().read(dict)) {}

template <int Dim>
VonMises<Dim>::VonMises(const Dictionary& dict, const KeywordValues& v)
    : Hookean<Dim>(dict, v),
      yield0_(v.scalar("yieldStress")),
      hardening_(v.scalar("hardeningModulus")),
      libersky_(v.flag("libersky")) {}

template <int Dim>
void VonMises<Dim>::returnToYieldSurface(const Fields& f, double dt) const {
    if (hardening_ > 0.0 && !f.plasticStrain)
        throw std::invalid_argument("vonMises with hardening needs the plasticStrain field");
    const double threeG = 1.5 * this->twoMu_;
    for (std::size_t i = 0; i < f.size; ++i) {
        const double epsP = f.plasticStrain ? f.plasticStrain[i] : 0.0;
        const double trial = this->equivalentStress(f.tau[i]);
        const double yield = yield0_ + hardening_ * epsP;
        double work = 0.0;
        if (trial > yield) {
            const double dEpsP = (trial - yield) / (threeG + hardening_);
            const double flow = yield + hardening_ * dEpsP;
            double factor = flow / trial;
            if (libersky_) factor *= factor;
            for (double& c : f.tau[i].c) c *= factor;
            if (f.plasticStrain) f.plasticStrain[i] = epsP + dEpsP;
            work = flow * dEpsP / dt;
        }
        if (f.plasticWorkRate) f.plasticWorkRate[i] = work;
    }
}

template <int Dim>
double VonMises<Dim>::yieldStress(double plasticStrain, double, double) const {
    return yield0_ + hardening_ * plasticStrain;
}

template class VonMises<1>;
template class VonMises<2>;
template class VonMises<3>;

MFDYN_REGISTER_DIM(
    Strength, VonMises, "vonMises",
    "hookean + radial return to sqrt(3 J2) = sigma_Y0 + H epsP (Wilkins 1964; Libersky 1993 option)");

}  // namespace mfdyn
