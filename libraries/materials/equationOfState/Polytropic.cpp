// Polytrope (Zisis 2017, the proof of section 5, doc/methods/sph-impact.md 5.1, there written c rho^gamma;
// Chandrasekhar 1939, "An Introduction to the Study of Stellar Structure", ch. IV):
//
//     P = K rho^gamma,    c^2 = gamma K rho^(gamma - 1).
//
// Barotropic, g = dP/de|_rho = 0 (an isentrope of the ideal gas when gamma is its ratio of specific
// heats); P > 0 for every rho > 0, so the reference pressure K rho0^gamma is not zero.
#include "materials/equationOfState/Polytropic.hpp"

#include <cmath>

namespace mfdyn {

KeywordSchema Polytropic::keywords() {
    return KeywordSchema(familyName, "polytropic")
        .scalar("K", "Pa (m^3/kg)^gamma", "polytropic constant")
        .greaterThan(0)
        .orEnclosing()
        .scalar("gamma", "-", "polytropic exponent")
        .greaterThan(1)
        .orEnclosing()
        .scalar("rho0", "kg/m^3", "reference density, for initial conditions (0: none)")
        .atLeast(0)
        .orDefault(0)
        .orEnclosing();
}

Polytropic::Polytropic(const Dictionary& dict) : EquationOfState(dict) {
    const KeywordValues v = keywords().read(dict);
    K_ = v.scalar("K");
    gamma_ = v.scalar("gamma");
    setReferenceDensity(v.scalar("rho0"));
}

void Polytropic::state(double rho, double, double& p, double& c2) const {
    const double r = K_ * std::pow(rho, gamma_ - 1.0);
    p = r * rho;
    c2 = gamma_ * r;
}

double Polytropic::pressure(double rho, double) const {
    return K_ * std::pow(rho, gamma_);
}

double Polytropic::soundSpeedSquared(double rho, double) const {
    return gamma_ * K_ * std::pow(rho, gamma_ - 1.0);
}

double Polytropic::energyDerivative(double, double) const {
    return 0.0;
}

void Polytropic::evaluate(std::size_t n, const double* rho, const double* e, double* p, double* c) const {
    evaluateBlock(*this, n, rho, e, p, c);
}

MFDYN_REGISTER(EquationOfState, Polytropic, "polytropic", "polytrope P = K rho^gamma");

}  // namespace mfdyn
