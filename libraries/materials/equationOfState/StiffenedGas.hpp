#pragma once
// Stiffened gas P = (gamma - 1) rho e - gamma pRef. Equations in StiffenedGas.cpp.
#include "materials/equationOfState/EquationOfState.hpp"

namespace mfdyn {

class StiffenedGas final : public EquationOfState {
public:
    explicit StiffenedGas(const Dictionary& dict);
    static KeywordSchema keywords();

    double pressure(double rho, double e) const override;
    double soundSpeedSquared(double rho, double e) const override;
    double energyDerivative(double rho, double e) const override;
    void evaluate(std::size_t n, const double* rho, const double* e, double* p, double* c) const override;

    // P and c^2 together (shared work); inlined by evaluate().
    void state(double rho, double e, double& p, double& c2) const;

private:
    double gamma_ = 0.0, pRef_ = 0.0;
};

}  // namespace mfdyn
