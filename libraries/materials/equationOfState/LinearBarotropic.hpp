#pragma once
// Barotropic ("isothermal") P = c0^2 (rho - rho0). Equations in LinearBarotropic.cpp.
#include "materials/equationOfState/EquationOfState.hpp"

namespace mfdyn {

class LinearBarotropic final : public EquationOfState {
public:
    explicit LinearBarotropic(const Dictionary& dict);
    static KeywordSchema keywords();

    double pressure(double rho, double e) const override;
    double soundSpeedSquared(double rho, double e) const override;
    double energyDerivative(double rho, double e) const override;
    bool needsEnergy() const override { return false; }
    void evaluate(std::size_t n, const double* rho, const double* e, double* p, double* c) const override;

    // P and c^2 together (shared work); inlined by evaluate().
    void state(double rho, double e, double& p, double& c2) const;

private:
    double c0_ = 0.0;
};

}  // namespace mfdyn
