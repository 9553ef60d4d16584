#pragma once
#include "tlSph/TlDissipation.hpp"

namespace mfdyn {

class ArtificialViscosity final : public TlDissipation {
public:
    static KeywordSchema keywords();
    explicit ArtificialViscosity(const Dictionary& dict);
    bool needsMomentumLaplacian() const override { return viscosity_ != 0; }
    void evaluate(const Block& block) const override;
    std::string describe() const override;

private:
    double viscosity_ = 0;  // mu_vis [Pa s]
};

}  // namespace mfdyn
