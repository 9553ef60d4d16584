#pragma once
// The closure of one side of an exact Riemann problem: ideal gas, stiffened gas or linear barotropic,
// with the wave curves (pressure functions) and fan states that the exact solver needs.
//
// A closed set of three value types rather than the runtime-selectable equationOfState family: the
// exact solver needs each closure's shock and rarefaction curves in closed form, which a general EOS
// does not provide, and a value type keeps RiemannSolver copyable. See RiemannEquationOfState.cpp.
#include <string>

namespace mfdyn {

// A uniform 1D state: density, velocity, pressure (positive in compression).
struct PrimitiveState {
    double density = 0.0;
    double velocity = 0.0;
    double pressure = 0.0;
};

// A sampled state of the exact solution. internalEnergy is NaN for a barotropic material, which
// has no energy equation (doc/methods/sph-impact.md 5.1).
struct FlowState {
    double density = 0.0;
    double velocity = 0.0;
    double pressure = 0.0;
    double internalEnergy = 0.0;
};

class RiemannEquationOfState {
public:
    enum class Kind { idealGas, stiffenedGas, linearBarotropic };

    // P = (gamma - 1) rho e.
    static RiemannEquationOfState idealGas(double gamma);
    // P = (gamma - 1) rho e - gamma pRef, c^2 = gamma (P + pRef)/rho (doc/methods/sph-impact.md erratum 5).
    static RiemannEquationOfState stiffenedGas(double gamma, double pRef);
    // P = c0^2 (rho - rho0), c = c0, no energy equation.
    static RiemannEquationOfState linearBarotropic(double rho0, double c0);

    Kind kind() const { return kind_; }
    bool hasEnergy() const { return kind_ != Kind::linearBarotropic; }
    double gamma() const { return gamma_; }
    double referencePressure() const { return pRef_; }
    double referenceDensity() const { return rho0_; }
    double barotropicSoundSpeed() const { return c0_; }
    // "idealGas(gamma=1.4)" and the like, for messages.
    std::string describe() const;
    bool operator==(const RiemannEquationOfState& other) const = default;

    // Pressure from density and specific internal energy (e is ignored by a barotropic material).
    double pressure(double rho, double e) const;
    // e from rho and P; NaN for a barotropic material.
    double internalEnergy(double rho, double p) const;
    double soundSpeed(double rho, double p) const;
    // Infimum of admissible pressures: where the density of an isentrope reaches zero
    // (0 for an ideal gas, -pRef for a stiffened gas, -c0^2 rho0 for the barotropic material).
    double pressureFloor() const;
    // Density on the pressure-to-density map of this material: the barotropic relation.
    // Only meaningful for the barotropic material.
    double barotropicDensity(double p) const;

    // Throws Error when state k is not admissible for this material (rho <= 0, P at or below the
    // floor, or a barotropic pressure inconsistent with the density).
    void check(const PrimitiveState& k, const std::string& side) const;

    // Velocity jump across the wave that joins state k to pressure p (Toro 2009, Eqs. 4.6-4.7):
    // a shock for p > p_k, a rarefaction otherwise; value and derivative in p.
    struct WaveFunction {
        double value;
        double derivative;
    };
    WaveFunction waveFunction(const PrimitiveState& k, double p) const;

    // Density behind the wave from state k to pressure pStar (Hugoniot or isentrope).
    double densityBehind(const PrimitiveState& k, double pStar) const;
    // Shock speed for the shock from k to pStar; side = -1 left-facing, +1 right-facing.
    double shockSpeed(const PrimitiveState& k, double pStar, int side) const;
    // State inside the rarefaction fan of state k at similarity coordinate xi = (x - x0)/t.
    FlowState fan(const PrimitiveState& k, double xi, int side) const;

private:
    RiemannEquationOfState(Kind kind, double gamma, double pRef, double rho0, double c0);

    Kind kind_;
    double gamma_ = 0.0;
    double pRef_ = 0.0;
    double rho0_ = 0.0;
    double c0_ = 0.0;
};

}  // namespace mfdyn
