#pragma once
// `linearElastic`: small-strain Hooke law written on F, P = lambda tr(F - I) I + mu (F + F^T - 2 I).
// Not objective (a rigid rotation stresses it): for small deformations only, as in the cable and
// swinging-cube tests of Lee et al. 2016 (sections 8.1, 8.2).
//
//     materials { steel { rho0 7000; youngsModulus 21e9; poissonRatio 0.3;
//                         constitutiveLaw { type linearElastic; } } }
#include "materials/constitutive/ConstitutiveLaw.hpp"

namespace mfdyn {

class LinearElastic : public ConstitutiveLaw {
public:
    explicit LinearElastic(const Dictionary& dict);
    // rho0 and the elastic constants only (ConstitutiveLaw::elasticKeywords()).
    static KeywordSchema keywords();
    void stress(const Fields& fields, bool updateState) const override;
};

}  // namespace mfdyn
