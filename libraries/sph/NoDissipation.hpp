#pragma once
// `none`: see NoDissipation.cpp for its equations and keywords.
#include "sph/Dissipation.hpp"

namespace mfdyn {

class NoDissipation final : public Dissipation {
public:
    static KeywordSchema keywords();
    explicit NoDissipation(const Dictionary& dict);
    DissipationParameters parameters() const override { return p_; }

private:
    DissipationParameters p_;
};

}  // namespace mfdyn
