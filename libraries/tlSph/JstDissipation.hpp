#pragma once
#include "tlSph/TlDissipation.hpp"

namespace mfdyn {

class JstDissipation final : public TlDissipation {
public:
    static KeywordSchema keywords();
    explicit JstDissipation(const Dictionary& dict);
    bool needsMomentumLaplacian() const override { return momentum2_ || momentum4_; }
    bool needsMomentumBiLaplacian() const override { return momentum4_ != 0; }
    bool needsJacobianLaplacian() const override { return jacobian2_ || jacobian4_; }
    bool needsJacobianBiLaplacian() const override { return jacobian4_ != 0; }
    void evaluate(const Block& block) const override;
    std::string stabilityWarning(double courant, double shearOverPressure, bool evolvesJ) const override;
    std::string describe() const override;

private:
    double momentum2_ = 0, momentum4_ = 0;  // eps2_p, eps4_p
    double jacobian2_ = 0, jacobian4_ = 0;  // eps2_J, eps4_J
    bool momentumOnShear_ = false;          // momentumSpeed shear: D(p) scales with c_s, not c_p
};

}  // namespace mfdyn
