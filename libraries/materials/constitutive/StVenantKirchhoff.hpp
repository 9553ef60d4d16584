#pragma once
// `stVenantKirchhoff`: S = lambda tr(E) I + 2 mu E, the law of the material point method's thesis
// (doc/methods/mpm.md section 1, law 1). See StVenantKirchhoff.cpp.
//
//     materials { bar { rho0 1500; youngsModulus 1e5; poissonRatio 0;
//                       constitutiveLaw { type stVenantKirchhoff; } } }
#include "materials/constitutive/ConstitutiveLaw.hpp"

namespace mfdyn {

class StVenantKirchhoff : public ConstitutiveLaw {
public:
    explicit StVenantKirchhoff(const Dictionary& dict);
    // rho0 and the elastic constants only (ConstitutiveLaw::elasticKeywords()).
    static KeywordSchema keywords();
    void stress(const Fields& fields, bool updateState) const override;
};

}  // namespace mfdyn
