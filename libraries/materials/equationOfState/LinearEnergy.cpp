// Linear equation of state in density and specific energy (von Nida 2005, "Meshfree Methods for the
// Dynamics of Solids", PhD thesis, TU Kaiserslautern / Fraunhofer ITWM, Eq. 7.1, used for all its
// coupled runs; doc/methods/fpm.md section 1, "Linear EOS (7.1)"):
//
//     P = p0 + c^2 (rho - rho0) + g e,
//
// with constant c and g, p0 = 0 in the thesis (a stress-free reference). The thesis's c and g are
// the partial derivatives of its Eq. 1.29:
//
//     dP/drho|_e = c^2,    g = dP/de|_rho,
//
// so its "c" is not the sound speed. soundSpeedSquared returns the family's isentropic one,
//
//     c_s^2 = dP/drho|_e + (P/rho^2) g = c^2 + P g / rho^2,
//
// and rho c_s^2 = rho c^2 + g P / rho is the bracket of the thesis's pressure rate, Eq. 7.2,
// Dp/Dt = -(rho c^2 + (g/rho) p) div v + (g/rho) S:epsdot, which must stay > 0 (else the body
// "gains volume"; Remark 7.1 sets an outer pressure p_o = 10 in its shear-only runs to keep it so).
// Where P < -rho^2 c^2 / g the bracket and c_s^2 are <= 0; c_s^2 is returned as is and the solver
// decides (family contract).
//
// Range: a linearisation about (rho0, e = 0); the thesis motivates it by the near-linear Tillotson
// pressure of iron for rho in [0.9, 1.1] rho0 and e in [0, 0.1 E0] (Fig. 7.1). g = 0 is barotropic
// (needsEnergy() false), the linearBarotropic model shifted by p0.
#include "materials/equationOfState/LinearEnergy.hpp"

namespace mfdyn {

KeywordSchema LinearEnergy::keywords() {
    return KeywordSchema(familyName, "linearEnergy")
        .scalar("c", "m/s", "dP/drho at constant e is c^2 (von Nida 2005's c; not the sound speed)")
        .greaterThan(0)
        .scalar("g", "kg/m^3", "g = dP/de at constant rho (0: barotropic)")
        .atLeast(0)
        .scalar("rho0", "kg/m^3", "reference density")
        .greaterThan(0)
        .orEnclosing()
        .scalar("p0", "Pa", "pressure at rho0 and e = 0")
        .orDefault(0.0);
}

LinearEnergy::LinearEnergy(const Dictionary& dict) : EquationOfState(dict) {
    const KeywordValues v = keywords().read(dict);
    const double c = v.scalar("c");
    c2_ = c * c;
    g_ = v.scalar("g");
    setReferenceDensity(v.scalar("rho0"));
    p0_ = v.scalar("p0");
}

void LinearEnergy::state(double rho, double e, double& p, double& c2) const {
    p = p0_ + c2_ * (rho - referenceDensity()) + g_ * e;
    c2 = c2_ + p * g_ / (rho * rho);
}

double LinearEnergy::pressure(double rho, double e) const {
    return p0_ + c2_ * (rho - referenceDensity()) + g_ * e;
}

double LinearEnergy::soundSpeedSquared(double rho, double e) const {
    return c2_ + pressure(rho, e) * g_ / (rho * rho);
}

double LinearEnergy::energyDerivative(double, double) const {
    return g_;
}

void LinearEnergy::evaluate(std::size_t n, const double* rho, const double* e, double* p, double* c) const {
    evaluateBlock(*this, n, rho, e, p, c);
}

MFDYN_REGISTER(EquationOfState, LinearEnergy, "linearEnergy",
               "linear P = p0 + c^2 (rho - rho0) + g e (von Nida 2005 Eq. 7.1)");

}  // namespace mfdyn
