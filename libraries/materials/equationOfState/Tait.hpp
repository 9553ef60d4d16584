#pragma once
// Tait P = B ((rho/rho0)^gamma - 1). Equations in Tait.cpp.
#include "materials/equationOfState/EquationOfState.hpp"

namespace mfdyn {

class Tait final : public EquationOfState {
public:
    explicit Tait(const Dictionary& dict);
    static KeywordSchema keywords();

    double pressure(double rho, double e) const override;
    double soundSpeedSquared(double rho, double e) const override;
    double energyDerivative(double rho, double e) const override;
    bool needsEnergy() const override { return false; }
    void evaluate(std::size_t n, const double* rho, const double* e, double* p, double* c) const override;

    // P and c^2 together (shared work); inlined by evaluate().
    void state(double rho, double e, double& p, double& c2) const;

private:
    double gamma_ = 0.0, B_ = 0.0;
};

}  // namespace mfdyn
