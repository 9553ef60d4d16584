// Linear barotropic ("isothermal") equation of state (Zisis 2017 Eqs. 1.13 and 5.1,
// doc/methods/sph-impact.md 5.1; the weakly compressible form of Monaghan 1994, J. Comput. Phys. 110:399):
//
//     P = c0^2 (rho - rho0),    c^2 = c0^2.
//
// P does not depend on e (g = dP/de|_rho = 0), so no energy equation is needed. Valid for small
// density changes (|rho/rho0 - 1| << 1) or as the isothermal model problem of the shock-bar tests
// (note 8.2); it allows any tension.
#include "materials/equationOfState/LinearBarotropic.hpp"

namespace mfdyn {

KeywordSchema LinearBarotropic::keywords() {
    return KeywordSchema(familyName, "linearBarotropic")
        .scalar("rho0", "kg/m^3", "reference density")
        .greaterThan(0)
        .orEnclosing()
        .scalar("c0", "m/s", "sound speed")
        .greaterThan(0)
        .orEnclosing();
}

LinearBarotropic::LinearBarotropic(const Dictionary& dict) : EquationOfState(dict) {
    const KeywordValues v = keywords().read(dict);
    setReferenceDensity(v.scalar("rho0"));
    c0_ = v.scalar("c0");
}

void LinearBarotropic::state(double rho, double, double& p, double& c2) const {
    c2 = c0_ * c0_;
    p = c2 * (rho - referenceDensity());
}

double LinearBarotropic::pressure(double rho, double) const {
    return c0_ * c0_ * (rho - referenceDensity());
}

double LinearBarotropic::soundSpeedSquared(double, double) const {
    return c0_ * c0_;
}

double LinearBarotropic::energyDerivative(double, double) const {
    return 0.0;
}

void LinearBarotropic::evaluate(std::size_t n, const double* rho, const double* e, double* p,
                                double* c) const {
    evaluateBlock(*this, n, rho, e, p, c);
}

MFDYN_REGISTER(EquationOfState, LinearBarotropic, "linearBarotropic", "isothermal P = c0^2 (rho - rho0)");

}  // namespace mfdyn
