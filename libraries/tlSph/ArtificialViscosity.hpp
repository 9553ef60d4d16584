#pragma once
#include "tlSph/TlDissipation.hpp"

namespace mfdyn {

class ArtificialViscosity final : public TlDissipation {
public:
    static KeywordSchema keywords();
    explicit ArtificialViscosity(const Dictionary& dict);
    TlDissipationCoefficients coefficients() const override { return c_; }
    std::string describe() const override;

private:
    TlDissipationCoefficients c_;
};

}  // namespace mfdyn
