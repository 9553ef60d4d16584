#pragma once
// Linear EOS P = p0 + c^2 (rho - rho0) + g e (von Nida 2005 Eq. 7.1). Equations in LinearEnergy.cpp.
#include "materials/equationOfState/EquationOfState.hpp"

namespace mfdyn {

class LinearEnergy final : public EquationOfState {
public:
    explicit LinearEnergy(const Dictionary& dict);
    static KeywordSchema keywords();

    double pressure(double rho, double e) const override;
    double soundSpeedSquared(double rho, double e) const override;
    double energyDerivative(double rho, double e) const override;
    bool needsEnergy() const override { return g_ != 0.0; }
    void evaluate(std::size_t n, const double* rho, const double* e, double* p, double* c) const override;

    // P and c^2 together (shared work); inlined by evaluate().
    void state(double rho, double e, double& p, double& c2) const;

private:
    double c2_ = 0.0, g_ = 0.0, p0_ = 0.0;
};

}  // namespace mfdyn
