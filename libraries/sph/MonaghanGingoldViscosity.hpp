#pragma once
// `monaghanGingold`: see MonaghanGingoldViscosity.cpp for its equations and keywords.
#include "sph/Dissipation.hpp"

namespace mfdyn {

class MonaghanGingoldViscosity final : public Dissipation {
public:
    static KeywordSchema keywords();
    explicit MonaghanGingoldViscosity(const Dictionary& dict);
    DissipationParameters parameters() const override { return p_; }

private:
    DissipationParameters p_;
};

}  // namespace mfdyn
