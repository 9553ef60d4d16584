// Ideal gas (Zisis 2017 Eq. 1.14, doc/methods/sph-impact.md 5.1):
//
//     P = (gamma - 1) rho e,    c^2 = gamma (gamma - 1) e = gamma P / rho.
//
// (c^2 from dP/drho|_e = (gamma - 1) e and g = dP/de|_rho = (gamma - 1) rho.) Valid for e >= 0; a
// negative e gives P < 0 and c^2 < 0, which the solver reports.
#include "materials/equationOfState/IdealGas.hpp"

namespace mfdyn {

KeywordSchema IdealGas::keywords() {
    return KeywordSchema(familyName, "idealGas")
        .scalar("gamma", "-", "ratio of specific heats")
        .greaterThan(1)
        .orEnclosing()
        .scalar("rho0", "kg/m^3", "reference density, for initial conditions (0: none)")
        .atLeast(0)
        .orDefault(0)
        .orEnclosing();
}

IdealGas::IdealGas(const Dictionary& dict) : EquationOfState(dict) {
    const KeywordValues v = keywords().read(dict);
    gamma_ = v.scalar("gamma");
    setReferenceDensity(v.scalar("rho0"));
}

void IdealGas::state(double rho, double e, double& p, double& c2) const {
    p = (gamma_ - 1.0) * rho * e;
    c2 = gamma_ * (gamma_ - 1.0) * e;
}

double IdealGas::pressure(double rho, double e) const {
    return (gamma_ - 1.0) * rho * e;
}

double IdealGas::soundSpeedSquared(double, double e) const {
    return gamma_ * (gamma_ - 1.0) * e;
}

double IdealGas::energyDerivative(double rho, double) const {
    return (gamma_ - 1.0) * rho;
}

void IdealGas::evaluate(std::size_t n, const double* rho, const double* e, double* p, double* c) const {
    evaluateBlock(*this, n, rho, e, p, c);
}

MFDYN_REGISTER(EquationOfState, IdealGas, "idealGas", "ideal gas P = (gamma - 1) rho e");

}  // namespace mfdyn
