#pragma once
// Tillotson equation of state (Tillotson 1962). Equations in Tillotson.cpp.
#include "materials/equationOfState/EquationOfState.hpp"

#include <limits>

namespace mfdyn {

class Tillotson final : public EquationOfState {
public:
    // `branch full`: the three regions of Tillotson 1962; `branch compressed`: P_c everywhere (the
    // "partial Tillotson" of von Nida 2005 Eq. 2.9).
    enum class Branch { full, compressed };

    explicit Tillotson(const Dictionary& dict);
    static KeywordSchema keywords();

    double pressure(double rho, double e) const override;
    double soundSpeedSquared(double rho, double e) const override;
    double energyDerivative(double rho, double e) const override;
    void evaluate(std::size_t n, const double* rho, const double* e, double* p, double* c) const override;

    // P and c^2 together (shared work); inlined by evaluate().
    void state(double rho, double e, double& p, double& c2) const;

    // The two branches on their own, with their partial derivatives dP/drho|_e and dP/de|_rho
    // (for tests of the interpolation and of continuity).
    void compressed(double rho, double e, double& p, double& pRho, double& pE) const;
    void expanded(double rho, double e, double& p, double& pRho, double& pE) const;

    Branch branch() const { return branch_; }
    double energyIncipientVaporisation() const { return Eiv_; }
    double energyCompleteVaporisation() const { return Ecv_; }

private:
    // P before the cut-off and its partial derivatives, of the branch (or blend) that (rho, e) is in.
    void uncut(double rho, double e, double& p, double& pRho, double& pE) const;

    Branch branch_ = Branch::full;
    double A_ = 0.0, B_ = 0.0, a_ = 0.0, b_ = 0.0, alpha_ = 0.0, beta_ = 0.0, E0_ = 0.0, Eiv_ = 0.0,
           Ecv_ = 0.0;
    double pMin_ = -std::numeric_limits<double>::infinity();
};

}  // namespace mfdyn
