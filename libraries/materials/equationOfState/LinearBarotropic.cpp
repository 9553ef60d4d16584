// Linear barotropic ("isothermal") equation of state (Zisis 2017 Eqs. 1.13 and 5.1,
// sph-impact.md 5.1; the weakly compressible form of Monaghan 1994, J. Comput. Phys. 110:399):
//
//     P = c0^2 (rho - rho0),    c^2 = c0^2.
//
// P does not depend on e, so no energy equation is needed. Valid for small density changes (|rho/rho0
// - 1| << 1) or as the isothermal model problem of the shock-bar tests (note 8.2); it allows any
// tension.
//
//     keyword  meaning                           unit     required
//     rho0     reference density                 kg/m^3   yes (here or in the material)
//     c0       sound speed                       m/s      yes (here or in the material)
#include "materials/equationOfState/LinearBarotropic.hpp"

namespace mfdyn {

LinearBarotropic::LinearBarotropic(const Dictionary& dict)
    : EquationOfState(dict, positiveParameter(dict, "rho0")), c0_(positiveParameter(dict, "c0")) {}

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

void LinearBarotropic::evaluate(std::size_t n, const double* rho, const double* e, double* p,
                                double* c) const {
    evaluateBlock(*this, n, rho, e, p, c);
}

MFDYN_REGISTER(EquationOfState, LinearBarotropic, "linearBarotropic",
               "isothermal P = c0^2 (rho - rho0); keywords rho0, c0");

}  // namespace mfdyn
