#pragma once
// `mooneyRivlin`: the polyconvex nearly incompressible Mooney-Rivlin law in {F, H, J} of Bonet,
// Gil & Ortigosa 2015 and Lee et al. 2016 (Eqs. 8-12),
// W = zeta J^-2/3 F:F + xi J^-2 (H:H)^3/2 + kappa/2 (J - 1)^2 (less its value at F = I).
//
//     materials { rubber { rho0 1100; youngsModulus 17e6; poissonRatio 0.495;
//                          constitutiveLaw { type mooneyRivlin; zeta 2e6; } } }
//
// zeta, xi and kappa are read from this dictionary only. At least one of zeta and xi (or
// hDominated yes) is required. With the material's elastic constants, 2 zeta + 3 sqrt(3) xi = mu
// must hold (relative 1e-6) and a missing one of zeta, xi is derived from it; without them the
// missing one is 0 and mu = 2 zeta + 3 sqrt(3) xi, kappa then being required.
#include "materials/constitutive/ConstitutiveLaw.hpp"

namespace mfdyn {

class MooneyRivlin : public ConstitutiveLaw {
public:
    explicit MooneyRivlin(const Dictionary& dict);
    static KeywordSchema keywords();
    void stress(const Fields& fields, bool updateState) const override;

    double zeta() const { return zeta_; }
    double xi() const { return xi_; }

    // P = Sigma_F + Sigma_H x F + Sigma_J H of W(F, H, J) with these coefficients, for the block;
    // shared with neoHookean (xi = 0).
    static void evaluate(double zeta, double xi, double kappa, const Fields& fields);

protected:
    std::string describeParameters() const override;

private:
    MooneyRivlin(const Dictionary& dict, const KeywordValues& values);

    double zeta_ = 0.0;
    double xi_ = 0.0;
};

}  // namespace mfdyn
