#pragma once
// `riemann`: see RiemannDissipation.cpp for its equations and keywords.
#include "sph/Dissipation.hpp"
#include "sph/SphPairLoop.hpp"

namespace mfdyn {

class RiemannDissipation final : public Dissipation {
public:
    static KeywordSchema keywords();
    explicit RiemannDissipation(const Dictionary& dict);

    void computeRates(SphPairLoop<1>& loop) override;
    void computeRates(SphPairLoop<2>& loop) override;
    void computeRates(SphPairLoop<3>& loop) override;

    // The pair terms (RiemannDissipation.cpp).
    template <int Dim>
    void pair(const SphPairLoop<Dim>& loop, const SphPair<Dim>& q, SphPairSums<Dim>& s) const;

    // The values read: (a, b) per variable, the signal velocity and the pairs dissipated.
    struct Coefficients {
        double av = 1, bv = 2, arho = 0.5, brho = 2, ae = 0.1, be = 2;
        bool alternativeSignal = false, allPairs = false;
        bool contactLimiter = true;  // densityLimiter contact (default), false: none
    };
    const Coefficients& coefficients() const { return k_; }

    // κ of Eq. 4.26′ (RiemannDissipation.cpp): the density contrast |ρ_i − ρ_j|/max(ρ_i, ρ_j) at which a pair is a contact in full.
    static constexpr double contactContrast = 0.3;

private:
    Coefficients k_;
    bool massFlux_ = true;  // a_ρ > 0
};

}  // namespace mfdyn
