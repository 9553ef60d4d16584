#pragma once
// Cubic polynomial P = K1 mu + K2 mu^2 + K3 mu^3 + B0 rho0 e (Zisis 2017 Eqs. 5.4-5.5). Equations in
// CubicPolynomial.cpp.
#include "materials/equationOfState/EquationOfState.hpp"

namespace mfdyn {

class CubicPolynomial final : public EquationOfState {
public:
    explicit CubicPolynomial(const Dictionary& dict);
    static KeywordSchema keywords();

    double pressure(double rho, double e) const override;
    double soundSpeedSquared(double rho, double e) const override;
    double energyDerivative(double rho, double e) const override;
    void evaluate(std::size_t n, const double* rho, const double* e, double* p, double* c) const override;

    // P and c^2 together (shared work); inlined by evaluate().
    void state(double rho, double e, double& p, double& c2) const;

private:
    double B0_ = 0.0, K1_ = 0.0, K2_ = 0.0, K3_ = 0.0;
};

}  // namespace mfdyn
