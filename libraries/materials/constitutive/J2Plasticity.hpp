#pragma once
// `j2Plasticity`: multiplicative finite-strain J2 (von Mises) plasticity with linear isotropic
// hardening (Simo 1992; Simo & Hughes 1998, Box 9.1): a neo-Hookean isochoric elastic response
// in b_e_bar, U(J) = kappa/2 (J - 1)^2, radial return of the Kirchhoff deviator.
//
//     materials { aluminium { rho0 2700; youngsModulus 70e9; poissonRatio 0.33;
//                             yieldStress 250e6;
//                             constitutiveLaw { type j2Plasticity; hardeningModulus 700e6; } } }
//
// Plastic state per particle: Cp^-1 (initialise to I) and eps_p (initialise to 0).
#include "materials/constitutive/ConstitutiveLaw.hpp"

namespace mfdyn {

class J2Plasticity : public ConstitutiveLaw {
public:
    explicit J2Plasticity(const Dictionary& dict);
    static KeywordSchema keywords();
    void stress(const Fields& fields, bool updateState) const override;
    bool usesPlasticState() const override { return true; }

    double yieldStress() const { return yield0_; }
    double hardeningModulus() const { return hardening_; }

protected:
    std::string describeParameters() const override;

private:
    J2Plasticity(const Dictionary& dict, const KeywordValues& values);

    double yield0_ = 0.0;
    double hardening_ = 0.0;
};

}  // namespace mfdyn
