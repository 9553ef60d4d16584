// Polytrope (Zisis 2017, the proof of section 5, sph-impact.md 5.1, there written c rho^gamma;
// Chandrasekhar 1939, "An Introduction to the Study of Stellar Structure", ch. IV):
//
//     P = K rho^gamma,    c^2 = gamma K rho^(gamma - 1).
//
// Barotropic (an isentrope of the ideal gas when gamma is its ratio of specific heats); P > 0 for
// every rho > 0, so the reference pressure K rho0^gamma is not zero.
//
//     keyword  meaning                                   unit              required  default
//     K        polytropic constant, > 0                  Pa (m^3/kg)^gamma yes
//     gamma    exponent, > 1                             -                 yes
//     rho0     reference density (initial conditions)    kg/m^3            no        0 (none)
#include "materials/equationOfState/Polytropic.hpp"

#include <cmath>

namespace mfdyn {

Polytropic::Polytropic(const Dictionary& dict)
    : EquationOfState(dict, parameterOrDefault(dict, "rho0", 0.0)),
      K_(positiveParameter(dict, "K")),
      gamma_(checkAbove(dict, "gamma", parameter(dict, "gamma"), 1.0)) {}

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

void Polytropic::evaluate(std::size_t n, const double* rho, const double* e, double* p, double* c) const {
    evaluateBlock(*this, n, rho, e, p, c);
}

MFDYN_REGISTER(EquationOfState, Polytropic, "polytropic", "polytrope P = K rho^gamma; keywords K, gamma");

}  // namespace mfdyn
