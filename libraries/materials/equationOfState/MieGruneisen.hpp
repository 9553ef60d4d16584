#pragma once
// Mie-Grueneisen equation of state on a linear Us-up Hugoniot (Zisis 2017 Eqs. 6.10-6.13).
// Equations in MieGruneisen.cpp.
#include "materials/equationOfState/EquationOfState.hpp"

#include <limits>

namespace mfdyn {

class MieGruneisen final : public EquationOfState {
public:
    // The reference curve P_H(mu) in compression.
    enum class Hugoniot { cubic, linearUsUp };

    explicit MieGruneisen(const Dictionary& dict);
    static KeywordSchema keywords();

    double pressure(double rho, double e) const override;
    double soundSpeedSquared(double rho, double e) const override;
    double energyDerivative(double rho, double e) const override;
    void evaluate(std::size_t n, const double* rho, const double* e, double* p, double* c) const override;

    // P and c^2 together (shared work); inlined by evaluate().
    void state(double rho, double e, double& p, double& c2) const;

    Hugoniot hugoniot() const { return hugoniot_; }
    double minimumPressure() const { return pMin_; }

private:
    // P before the cut-off, c^2 and g = dP/de|_rho (shared by state() and energyDerivative()).
    void uncut(double rho, double e, double& p, double& c2, double& g) const;

    double c0_ = 0.0, s_ = 0.0, gamma0_ = 0.0;
    Hugoniot hugoniot_ = Hugoniot::cubic;
    bool constantRhoGamma_ = false;
    double pMin_ = -std::numeric_limits<double>::infinity();
    double A_ = 0.0, B_ = 0.0, C_ = 0.0;
};

}  // namespace mfdyn
