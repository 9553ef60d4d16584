#pragma once
// Polytrope P = K rho^gamma. Equations in Polytropic.cpp.
#include "materials/equationOfState/EquationOfState.hpp"

namespace mfdyn {

class Polytropic final : public EquationOfState {
public:
    explicit Polytropic(const Dictionary& dict);
    static KeywordSchema keywords();

    double pressure(double rho, double e) const override;
    double soundSpeedSquared(double rho, double e) const override;
    double energyDerivative(double rho, double e) const override;
    bool needsEnergy() const override { return false; }
    void evaluate(std::size_t n, const double* rho, const double* e, double* p, double* c) const override;

    // P and c^2 together (shared work); inlined by evaluate().
    void state(double rho, double e, double& p, double& c2) const;

private:
    double K_ = 0.0, gamma_ = 0.0;
};

}  // namespace mfdyn
