// Tait equation (Cole 1948, "Underwater Explosions"; in SPH Monaghan 1994, J. Comput. Phys.
// 110:399, Eq. 3.1; Batchelor 1967; Zisis 2017 elliptical drop, sph-impact.md 5.1 and 8.1):
//
//     P = B ((rho/rho0)^gamma - 1),    c^2 = (gamma B / rho0) (rho/rho0)^(gamma - 1),
//
// with B given, or from the sound speed at rest, B = rho0 c0^2 / gamma (the thesis gives no B).
// Barotropic: no energy equation. Weakly compressible liquids (gamma = 7 for water); in tension P
// tends to -B as rho -> 0.
//
//     keyword  meaning                                      unit     required  default
//     rho0     reference density                            kg/m^3   yes (here or in the material)
//     B        pressure constant; or                        Pa       one of B, c0
//     c0       sound speed at rho0, B = rho0 c0^2/gamma     m/s      one of B, c0
//     gamma    exponent, > 1                                -        no        7
#include "materials/equationOfState/Tait.hpp"

#include <cmath>

namespace mfdyn {

Tait::Tait(const Dictionary& dict)
    : EquationOfState(dict, positiveParameter(dict, "rho0")),
      gamma_(checkAbove(dict, "gamma", parameterOrDefault(dict, "gamma", 7.0), 1.0)) {
    const auto B = optionalParameter(dict, "B");
    const auto c0 = optionalParameter(dict, "c0");
    if (B && c0) throw parameterError(dict, "B", "give either B or c0 (B = rho0 c0^2/gamma), not both");
    if (B)
        B_ = positiveParameter(dict, "B");
    else if (c0)
        B_ = referenceDensity() * std::pow(positiveParameter(dict, "c0"), 2) / gamma_;
    else
        throw InputError(dict.where(), dict.scope(),
                         "missing keyword 'B' or 'c0' (a real number; B = rho0 c0^2/gamma), looked for in '" +
                             dict.scope() + "'" +
                             (dict.parent() ? " and in the enclosing '" + dict.parent()->scope() + "'" : ""));
}

void Tait::state(double rho, double, double& p, double& c2) const {
    const double rho0 = referenceDensity();
    const double r = std::pow(rho / rho0, gamma_ - 1.0);
    p = B_ * (r * rho / rho0 - 1.0);
    c2 = gamma_ * B_ / rho0 * r;
}

double Tait::pressure(double rho, double) const {
    return B_ * (std::pow(rho / referenceDensity(), gamma_) - 1.0);
}

double Tait::soundSpeedSquared(double rho, double) const {
    const double rho0 = referenceDensity();
    return gamma_ * B_ / rho0 * std::pow(rho / rho0, gamma_ - 1.0);
}

void Tait::evaluate(std::size_t n, const double* rho, const double* e, double* p, double* c) const {
    evaluateBlock(*this, n, rho, e, p, c);
}

MFDYN_REGISTER(EquationOfState, Tait, "tait",
               "Tait P = B ((rho/rho0)^gamma - 1); keywords rho0, B or c0, gamma (default 7)");

}  // namespace mfdyn
