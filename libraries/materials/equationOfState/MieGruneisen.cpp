// Mie-Grueneisen equation of state referenced to the Hugoniot of a linear shock-velocity law
// (Zisis 2017 Eqs. 6.10-6.13 and 1.9-1.12, doc/methods/sph-impact.md 5.1; the form of Hiermaier 1997 and of
// the Autodyn "shock" EOS; Meyers 1994, "Dynamic Behavior of Materials", ch. 4-5):
//
//     P   = (1 - Gamma0 mu / 2) P_H(mu) + Gamma0 rho e,    mu = rho/rho0 - 1,
//     Us  = c0 + s up  (s is the note's xi),  A = rho0 c0^2,
//
// with, in compression (mu > 0), `hugoniot cubic` (the thesis, default):
//
//     P_H = A mu + B mu^2 + C mu^3,  B = A (1 + 2 (s - 1)),  C = A (2 (s - 1) + 3 (s - 1)^2),
//
// or `hugoniot linearUsUp`, the Hugoniot itself, of which the cubic is the Taylor expansion to
// O(mu^3) (from P_H = rho0 c0^2 eta / (1 - s eta)^2, eta = 1 - rho0/rho = mu/(1 + mu)):
//
//     P_H = A mu (1 + mu) / (1 - (s - 1) mu)^2,    defined for mu < 1/(s - 1) (NaN beyond),
//
// and P_H = A mu in tension (mu <= 0) for both. The Grueneisen term is exact for constant Gamma0:
// with e_H = P_H (1/rho0 - 1/rho)/2 the Hugoniot energy, Gamma0 rho e_H = Gamma0 mu P_H / 2, so
// P(rho, e_H) = P_H(mu): with linearUsUp the model reproduces the Hugoniot (P = rho0 Us up at
// e = up^2/2) to round-off; the cubic deviates from it by (1 - Gamma0 mu/2)(P_cubic - P_H) =
// O(A (s-1)^3 mu^4) (tests/unit/materials/MieGruenisenTest.cpp).
//
// Sound speed, with g = dP/de|_rho = Gamma0 rho:
//
//     c^2 = [(1 - Gamma0 mu/2) P_H'(mu) - Gamma0 P_H / 2] / rho0 + Gamma0 e + Gamma0 P / rho.
//
// `gruneisen constantRhoGamma` takes the usual hydrocode assumption Gamma rho = Gamma0 rho0
// (Gamma/V constant; e.g. Meyers 1994 §4.6) instead of the thesis's constant Gamma:
//
//     P   = (1 - Gamma0 mu / (2 (1 + mu))) P_H(mu) + Gamma0 rho0 e,    g = Gamma0 rho0,
//     c^2 = [(1 - Gamma0 mu/(2(1+mu))) P_H' - Gamma0 P_H / (2 (1+mu)^2)] / rho0 + Gamma0 rho0 P / rho^2.
//
// Both agree to first order in mu and reproduce the same Hugoniot (the Hugoniot-energy identity
// holds for any Gamma(rho)); the constant-Gamma factor (1 - Gamma0 mu/2) turns negative at
// mu = 2/Gamma0, where c^2 can become negative in a strongly compressed, little-heated particle
// (met at the contact of an aluminium-on-lead impact at 6.85 km/s); constantRhoGamma's factor stays
// above 1 - Gamma0/2 for any compression.
//
// Limits: no spall or tension cut-off in the thesis; `minimumPressure` clamps P from below
// (P = max(P, pMin)) and leaves c^2 as the uncut value, since the cut-off models failed material
// that the time step must still resolve, not a softer one; where P is cut it does not depend on e,
// so g = 0 there (and dP/drho|_e from the family's identity is the uncut c^2). c^2 can be negative
// in strong tension. Beyond mu = 1/(s - 1) (linearUsUp) P, c^2 and g are NaN.
#include "materials/equationOfState/MieGruneisen.hpp"

#include <algorithm>
#include <cmath>

namespace mfdyn {

KeywordSchema MieGruneisen::keywords() {
    return KeywordSchema(familyName, "mieGruneisen")
        .scalar("rho0", "kg/m^3", "reference density")
        .greaterThan(0)
        .orEnclosing()
        .scalar("c0", "m/s", "bulk sound speed, Us at up = 0")
        .greaterThan(0)
        .orEnclosing()
        .scalar("s", "-", "slope of the linear Us-up Hugoniot (the note's xi)")
        .orEnclosing()
        .scalar("gamma0", "-", "Grueneisen parameter at rho0")
        .orEnclosing()
        .word("hugoniot", {"cubic", "linearUsUp"},
              "reference curve in compression: the cubic of Zisis 2017 Eq. 6.11, or the exact Hugoniot of Us "
              "= c0 + s up")
        .orDefault("cubic")
        .word("gruneisen", {"constant", "constantRhoGamma"},
              "Gamma constant (Zisis 2017), or Gamma rho = Gamma0 rho0 (hydrocodes)")
        .orDefault("constant")
        .scalar("minimumPressure", "Pa", "tension cut-off pMin: P = max(P, pMin), c^2 uncut, g = 0 where cut")
        .atMost(0)
        .optional()
        .orEnclosing();
}

MieGruneisen::MieGruneisen(const Dictionary& dict) : EquationOfState(dict) {
    const KeywordValues v = keywords().read(dict);
    setReferenceDensity(v.scalar("rho0"));
    c0_ = v.scalar("c0");
    s_ = v.scalar("s");
    gamma0_ = v.scalar("gamma0");
    hugoniot_ = v.word("hugoniot") == "cubic" ? Hugoniot::cubic : Hugoniot::linearUsUp;
    constantRhoGamma_ = v.word("gruneisen") == "constantRhoGamma";
    if (auto pMin = v.optionalScalar("minimumPressure")) pMin_ = *pMin;
    const double sm1 = s_ - 1.0;
    A_ = referenceDensity() * c0_ * c0_;
    B_ = A_ * (1.0 + 2.0 * sm1);
    C_ = A_ * (2.0 * sm1 + 3.0 * sm1 * sm1);
}

void MieGruneisen::uncut(double rho, double e, double& p, double& c2, double& g) const {
    const double rho0 = referenceDensity();
    const double mu = rho / rho0 - 1.0;
    double pH = A_ * mu, dpH = A_;
    if (mu > 0.0) {
        if (hugoniot_ == Hugoniot::cubic) {
            pH = mu * (A_ + mu * (B_ + mu * C_));
            dpH = A_ + mu * (2.0 * B_ + 3.0 * mu * C_);
        } else {
            const double d = 1.0 - (s_ - 1.0) * mu;
            if (!(d > 0.0)) {
                p = c2 = g = std::numeric_limits<double>::quiet_NaN();
                return;
            }
            pH = A_ * mu * (1.0 + mu) / (d * d);
            dpH = A_ * ((1.0 + 2.0 * mu) / (d * d) + 2.0 * (s_ - 1.0) * mu * (1.0 + mu) / (d * d * d));
        }
    }
    if (constantRhoGamma_) {
        const double q = 1.0 / (1.0 + mu);
        const double f = 1.0 - 0.5 * gamma0_ * mu * q;
        g = gamma0_ * rho0;
        p = f * pH + g * e;
        c2 = (f * dpH - 0.5 * gamma0_ * pH * q * q) / rho0 + g * p / (rho * rho);
        return;
    }
    const double f = 1.0 - 0.5 * gamma0_ * mu;
    g = gamma0_ * rho;
    p = f * pH + g * e;
    c2 = (f * dpH - 0.5 * gamma0_ * pH) / rho0 + gamma0_ * e + gamma0_ * p / rho;
}

void MieGruneisen::state(double rho, double e, double& p, double& c2) const {
    double g;
    uncut(rho, e, p, c2, g);
    p = std::max(p, pMin_);
}

double MieGruneisen::pressure(double rho, double e) const {
    double p, c2;
    state(rho, e, p, c2);
    return p;
}

double MieGruneisen::soundSpeedSquared(double rho, double e) const {
    double p, c2;
    state(rho, e, p, c2);
    return c2;
}

double MieGruneisen::energyDerivative(double rho, double e) const {
    double p, c2, g;
    uncut(rho, e, p, c2, g);
    return p < pMin_ ? 0.0 : g;
}

void MieGruneisen::evaluate(std::size_t n, const double* rho, const double* e, double* p, double* c) const {
    evaluateBlock(*this, n, rho, e, p, c);
}

MFDYN_REGISTER(EquationOfState, MieGruneisen, "mieGruneisen",
               "Mie-Grueneisen on a linear Us-up Hugoniot (Zisis 6.10-6.13)");

}  // namespace mfdyn
