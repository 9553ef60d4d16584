#pragma once
// `riemann`: see RiemannDissipation.cpp for its equations and keywords.
#include "sph/Dissipation.hpp"

namespace mfdyn {

class RiemannDissipation final : public Dissipation {
public:
    static KeywordSchema keywords();
    explicit RiemannDissipation(const Dictionary& dict);
    DissipationParameters parameters() const override { return p_; }

private:
    DissipationParameters p_;
};

}  // namespace mfdyn
