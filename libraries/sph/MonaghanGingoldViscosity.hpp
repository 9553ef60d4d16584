#pragma once
// `monaghanGingold`: see MonaghanGingoldViscosity.cpp for its equations and keywords.
#include "sph/Dissipation.hpp"
#include "sph/SphPairLoop.hpp"

#include <vector>

namespace mfdyn {

class MonaghanGingoldViscosity final : public Dissipation {
public:
    static KeywordSchema keywords();
    explicit MonaghanGingoldViscosity(const Dictionary& dict);

    void computeRates(SphPairLoop<1>& loop) override;
    void computeRates(SphPairLoop<2>& loop) override;
    void computeRates(SphPairLoop<3>& loop) override;

    // Balsara's switch of every particle, ghosts included, once a rate evaluation (when on).
    template <int Dim>
    void prepare(const SphPairLoop<Dim>& loop);
    // The pair terms (MonaghanGingoldViscosity.cpp).
    template <int Dim>
    void pair(const SphPairLoop<Dim>& loop, const SphPair<Dim>& q, SphPairSums<Dim>& s) const;

    struct Coefficients {
        double alpha = 1, beta = 2;
        bool balsara = false;
        double arho = 0, brho = 0;
    };
    const Coefficients& coefficients() const { return k_; }

private:
    Coefficients k_;
    bool massFlux_ = false;        // a_ρ > 0
    std::vector<double> balsara_;  // f_i of this rate evaluation; empty when the switch is off
};

}  // namespace mfdyn
