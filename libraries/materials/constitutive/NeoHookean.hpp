#pragma once
// `neoHookean`: the nearly incompressible neo-Hookean law, mooneyRivlin with xi = 0 and
// zeta = mu/2 (Lee et al. 2016, section 2; doc/methods/tl-jst-sph.md section 1, "Named special cases").
//
//     materials { rubber { rho0 1100; youngsModulus 17e6; poissonRatio 0.45;
//                          constitutiveLaw { type neoHookean; } } }
#include "materials/constitutive/ConstitutiveLaw.hpp"

namespace mfdyn {

class NeoHookean : public ConstitutiveLaw {
public:
    explicit NeoHookean(const Dictionary& dict);
    // rho0 and the elastic constants only (ConstitutiveLaw::elasticKeywords()).
    static KeywordSchema keywords();
    void stress(const Fields& fields, bool updateState) const override;
};

}  // namespace mfdyn
