// Stiffened gas (Zisis 2017 Eq. 5.3 with the sign of doc/methods/sph-impact.md 12.5: Eq. 1.15's "+" is wrong;
// Harlow & Amsden 1971, LA-4700; Menikoff & Plohr 1989, Rev. Mod. Phys. 61:75):
//
//     P = (gamma - 1) rho e - gamma pRef,    c^2 = gamma (P + pRef) / rho.
//
// (dP/drho|_e = (gamma - 1) e, g = dP/de|_rho = (gamma - 1) rho, and (gamma - 1) rho e = P + gamma pRef.)
// pRef = 0 is the ideal gas; water-like liquids take gamma ~ 4.4, pRef ~ 6e8 Pa. c^2 > 0 needs
// P > -pRef.
#include "materials/equationOfState/StiffenedGas.hpp"

namespace mfdyn {

KeywordSchema StiffenedGas::keywords() {
    return KeywordSchema(familyName, "stiffenedGas")
        .scalar("gamma", "-", "ratio of specific heats")
        .greaterThan(1)
        .orEnclosing()
        .scalar("pRef", "Pa", "stiffening pressure (0: the ideal gas)")
        .atLeast(0)
        .orEnclosing()
        .scalar("rho0", "kg/m^3", "reference density, for initial conditions (0: none)")
        .atLeast(0)
        .orDefault(0)
        .orEnclosing();
}

StiffenedGas::StiffenedGas(const Dictionary& dict) : EquationOfState(dict) {
    const KeywordValues v = keywords().read(dict);
    gamma_ = v.scalar("gamma");
    pRef_ = v.scalar("pRef");
    setReferenceDensity(v.scalar("rho0"));
}

void StiffenedGas::state(double rho, double e, double& p, double& c2) const {
    p = (gamma_ - 1.0) * rho * e - gamma_ * pRef_;
    c2 = gamma_ * (p + pRef_) / rho;
}

double StiffenedGas::pressure(double rho, double e) const {
    return (gamma_ - 1.0) * rho * e - gamma_ * pRef_;
}

double StiffenedGas::soundSpeedSquared(double rho, double e) const {
    return gamma_ * (pressure(rho, e) + pRef_) / rho;
}

double StiffenedGas::energyDerivative(double rho, double) const {
    return (gamma_ - 1.0) * rho;
}

void StiffenedGas::evaluate(std::size_t n, const double* rho, const double* e, double* p, double* c) const {
    evaluateBlock(*this, n, rho, e, p, c);
}

MFDYN_REGISTER(EquationOfState, StiffenedGas, "stiffenedGas",
               "stiffened gas P = (gamma - 1) rho e - gamma pRef");

}  // namespace mfdyn
