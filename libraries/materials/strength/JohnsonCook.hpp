#pragma once
// `johnsonCook`: hookean plus a radial return to the Johnson-Cook flow stress (Johnson & Cook
// 1983), with the temperature raised by the plastic work.
//
//     strength
//     {
//         type johnsonCook; shearModulus 27.6e9;
//         A 265e6; B 426e6; n 0.34; C 0.015; m 1.0; Tmelt 775; specificHeat 875;   // 2024-T351
//     }
//
//     keyword         meaning                                              unit    required  default
//     shearModulus    G                                                    Pa      yes
//     A               yield stress at epsP = 0, rate epsilonDot0, Troom    Pa      yes
//     B               strain-hardening coefficient                         Pa      yes
//     n               strain-hardening exponent                            -       yes
//     C               strain-rate coefficient                              -       yes
//     m               thermal-softening exponent                           -       yes
//     epsilonDot0     reference strain rate                                1/s     no        1
//     Troom           room (reference) temperature                         K       no        293.15
//     Tmelt           melting temperature                                  K       yes
//     specificHeat    c_v                                                  J/kg/K  yes
//     taylorQuinney   beta, fraction of plastic work turned into heat      -       no        0.9
//     shearFactor, deviator: as hookean.
#include "materials/strength/Hookean.hpp"

namespace mfdyn {

template <int Dim>
class JohnsonCook : public Hookean<Dim> {
public:
    using typename Strength<Dim>::Fields;

    explicit JohnsonCook(const Dictionary& dict);
    static KeywordSchema keywords();

    bool usesPlasticStrain() const override { return true; }
    bool usesTemperature() const override { return true; }
    bool usesDensity() const override { return true; }
    double initialTemperature() const override { return roomTemperature_; }

    void returnToYieldSurface(const Fields& fields, double dt) const override;
    double yieldStress(double plasticStrain, double strainRate, double temperature) const override;

private:
    JohnsonCook(const Dictionary& dict, const KeywordValues& values);

    // (1 + C ln(max(rate/epsilonDot0, 1))) (1 - T*^m): the factor of A + B epsP^n.
    double softening(double strainRate, double temperature) const;

    double a_ = 0.0, b_ = 0.0, n_ = 0.0, c_ = 0.0, m_ = 0.0;
    double referenceRate_ = 1.0;
    double roomTemperature_ = 0.0, meltTemperature_ = 0.0;
    double specificHeat_ = 0.0;
    double taylorQuinney_ = 0.9;
};

}  // namespace mfdyn
