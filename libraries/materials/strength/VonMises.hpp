#pragma once
// `vonMises`: hookean plus a radial return to the von Mises yield surface sqrt(3 J2) = sigma_Y,
// with optional linear isotropic hardening sigma_Y = sigma_Y0 + H epsP (doc/methods/sph-impact.md §5.2,
// erratum 9; Wilkins 1964). `libersky yes` scales by min(1, sigma_Y^2/(3 J2)) instead
// (Libersky et al. 1993), which lands inside the surface.
//
//     strength { type vonMises; shearModulus 27.1e9; yieldStress 0.265e9; }
//
//     keyword           meaning                                             unit  required  default
//     shearModulus      G                                                   Pa    yes
//     yieldStress       sigma_Y0, the initial flow stress                   Pa    yes
//     hardeningModulus  H, the slope of sigma_Y against epsP               Pa    no        0
//     libersky          squared return factor (Libersky 1993)               -     no        no
//     shearFactor, deviator: as hookean.
#include "materials/strength/Hookean.hpp"

namespace mfdyn {

template <int Dim>
class VonMises : public Hookean<Dim> {
public:
    using typename Strength<Dim>::Fields;

    explicit VonMises(const Dictionary& dict);
    static KeywordSchema keywords();

    bool usesPlasticStrain() const override { return true; }
    void returnToYieldSurface(const Fields& fields, double dt) const override;
    double yieldStress(double plasticStrain, double strainRate, double temperature) const override;

    double hardeningModulus() const { return hardening_; }
    bool libersky() const { return libersky_; }

private:
    VonMises(const Dictionary& dict, const KeywordValues& values);

    double yield0_ = 0.0;
    double hardening_ = 0.0;
    bool libersky_ = false;
};

}  // namespace mfdyn
