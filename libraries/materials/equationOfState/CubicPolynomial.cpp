// Cubic polynomial EOS (Zisis 2017 Eqs. 5.4-5.5, doc/methods/sph-impact.md 5.1; the shape of the
// Autodyn/LS-DYNA polynomial EOS with the coefficients of a linear Us-up Hugoniot):
//
//     P  = K1 mu + K2 mu^2 + K3 mu^3 + B0 rho0 e,    mu = rho/rho0 - 1,
//     K1 = rho0 c0^2,  K2 = K1 (1 + 2 (S0 - 1)),  K3 = K1 (2 (S0 - 1) + 3 (S0 - 1)^2),
//     g   = dP/de|_rho = B0 rho0,
//     c^2 = dP/drho|_e + (P/rho^2) g = (K1 + 2 K2 mu + 3 K3 mu^2)/rho0 + B0 rho0 P / rho^2.
//
// K1 mu + K2 mu^2 + K3 mu^3 is the Taylor expansion to third order in mu of the Hugoniot of
// Us = c0 + S0 up (see MieGruneisen.cpp), so the model is accurate for moderate compression
// (mu < ~0.3). The one polynomial is used in tension as printed (no separate tension branch, no
// cut-off); B0 plays the role of a Grueneisen parameter with Gamma rho = B0 rho0.
#include "materials/equationOfState/CubicPolynomial.hpp"

namespace mfdyn {

KeywordSchema CubicPolynomial::keywords() {
    return KeywordSchema(familyName, "cubicPolynomial")
        .scalar("rho0", "kg/m^3", "reference density")
        .greaterThan(0)
        .orEnclosing()
        .scalar("c0", "m/s", "bulk sound speed")
        .greaterThan(0)
        .orEnclosing()
        .scalar("S0", "-", "slope of the linear Us-up Hugoniot")
        .orEnclosing()
        .scalar("B0", "-", "energy coefficient (Grueneisen-like, Gamma rho = B0 rho0)")
        .orEnclosing();
}

CubicPolynomial::CubicPolynomial(const Dictionary& dict) : EquationOfState(dict) {
    const KeywordValues v = keywords().read(dict);
    setReferenceDensity(v.scalar("rho0"));
    B0_ = v.scalar("B0");
    const double c0 = v.scalar("c0");
    const double sm1 = v.scalar("S0") - 1.0;
    K1_ = referenceDensity() * c0 * c0;
    K2_ = K1_ * (1.0 + 2.0 * sm1);
    K3_ = K1_ * (2.0 * sm1 + 3.0 * sm1 * sm1);
}

void CubicPolynomial::state(double rho, double e, double& p, double& c2) const {
    const double rho0 = referenceDensity();
    const double mu = rho / rho0 - 1.0;
    p = mu * (K1_ + mu * (K2_ + mu * K3_)) + B0_ * rho0 * e;
    c2 = (K1_ + mu * (2.0 * K2_ + 3.0 * mu * K3_)) / rho0 + B0_ * rho0 * p / (rho * rho);
}

double CubicPolynomial::pressure(double rho, double e) const {
    double p, c2;
    state(rho, e, p, c2);
    return p;
}

double CubicPolynomial::soundSpeedSquared(double rho, double e) const {
    double p, c2;
    state(rho, e, p, c2);
    return c2;
}

double CubicPolynomial::energyDerivative(double, double) const {
    return B0_ * referenceDensity();
}

void CubicPolynomial::evaluate(std::size_t n, const double* rho, const double* e, double* p,
                               double* c) const {
    evaluateBlock(*this, n, rho, e, p, c);
}

MFDYN_REGISTER(EquationOfState, CubicPolynomial, "cubicPolynomial",
               "cubic P = K1 mu + K2 mu^2 + K3 mu^3 + B0 rho0 e (Zisis 5.4-5.5)");

}  // namespace mfdyn
