#pragma once
// `none`: see NoDissipation.cpp for its equations and keywords.
#include "sph/Dissipation.hpp"
#include "sph/SphPairLoop.hpp"

namespace mfdyn {

class NoDissipation final : public Dissipation {
public:
    static KeywordSchema keywords();
    explicit NoDissipation(const Dictionary& dict);

    void computeRates(SphPairLoop<1>& loop) override;
    void computeRates(SphPairLoop<2>& loop) override;
    void computeRates(SphPairLoop<3>& loop) override;

    // No pair terms.
    template <int Dim>
    void pair(const SphPairLoop<Dim>&, const SphPair<Dim>&, SphPairSums<Dim>&) const {}
};

}  // namespace mfdyn
