#pragma once
// `neoHookeanLogJ`: the compressible neo-Hookean law with the ln J volumetric energy,
// sigma = mu/J (B - I) + lambda ln J / J I, of the material point method's thesis
// (doc/methods/mpm.md section 1, law 2). Not the same energy as `neoHookean`: see
// NeoHookeanLogJ.cpp.
//
//     materials { block { rho0 1500; youngsModulus 1e5; poissonRatio 0.3;
//                         constitutiveLaw { type neoHookeanLogJ; } } }
#include "materials/constitutive/ConstitutiveLaw.hpp"

namespace mfdyn {

class NeoHookeanLogJ : public ConstitutiveLaw {
public:
    explicit NeoHookeanLogJ(const Dictionary& dict);
    // rho0 and the elastic constants only (ConstitutiveLaw::elasticKeywords()).
    static KeywordSchema keywords();
    void stress(const Fields& fields, bool updateState) const override;
};

}  // namespace mfdyn
