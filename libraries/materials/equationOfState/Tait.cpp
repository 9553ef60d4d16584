// Tait equation (Cole 1948, "Underwater Explosions"; in SPH Monaghan 1994, J. Comput. Phys.
// 110:399, Eq. 3.1; Batchelor 1967; Zisis 2017 elliptical drop, doc/methods/sph-impact.md 5.1 and 8.1):
//
//     P = B ((rho/rho0)^gamma - 1),    c^2 = (gamma B / rho0) (rho/rho0)^(gamma - 1),
//
// with B given, or from the sound speed at rest, B = rho0 c0^2 / gamma (the thesis gives no B).
// Barotropic, g = dP/de|_rho = 0: no energy equation. Weakly compressible liquids (gamma = 7 for
// water); in tension P tends to -B as rho -> 0.
#include "materials/equationOfState/Tait.hpp"

#include <cmath>

namespace mfdyn {

KeywordSchema Tait::keywords() {
    return KeywordSchema(familyName, "tait")
        .scalar("rho0", "kg/m^3", "reference density")
        .greaterThan(0)
        .orEnclosing()
        .scalar("B", "Pa", "pressure constant; give B or c0, not both")
        .greaterThan(0)
        .optional()
        .orEnclosing()
        .scalar("c0", "m/s", "sound speed at rho0, giving B = rho0 c0^2/gamma; give B or c0, not both")
        .greaterThan(0)
        .optional()
        .orEnclosing()
        .scalar("gamma", "-", "exponent (7 for water)")
        .greaterThan(1)
        .orDefault(7.0)
        .orEnclosing();
}

Tait::Tait(const Dictionary& dict) : EquationOfState(dict) {
    const KeywordValues v = keywords().read(dict);
    setReferenceDensity(v.scalar("rho0"));
    gamma_ = v.scalar("gamma");
    const auto B = v.optionalScalar("B");
    const auto c0 = v.optionalScalar("c0");
    if (B && c0) throw v.error("B", "give either B or c0 (B = rho0 c0^2/gamma), not both");
    if (B)
        B_ = *B;
    else if (c0)
        B_ = referenceDensity() * *c0 * *c0 / gamma_;
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

double Tait::energyDerivative(double, double) const {
    return 0.0;
}

void Tait::evaluate(std::size_t n, const double* rho, const double* e, double* p, double* c) const {
    evaluateBlock(*this, n, rho, e, p, c);
}

MFDYN_REGISTER(EquationOfState, Tait, "tait", "Tait P = B ((rho/rho0)^gamma - 1)");

}  // namespace mfdyn
