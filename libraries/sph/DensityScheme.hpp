#pragma once
// The smoothed-density scheme of SPH (Zisis 2017 §3–4; doc/methods/sph-impact.md §2), chosen
// by name, with the momentum and energy equations matched to it variationally:
//
//     densityScheme { type number; form continuity; gradH yes; omegaMin 0.5; }
//
// All three measures share one algebraic shape, with per-particle coefficients a_i, b_i, c_i:
//
//     summation    ρ_i = c_i Σ_j b_j W_ij(h_i)
//     continuity   dρ_i/dt = (c_i/ω_i) Σ_j b_j v_ij·∇_iW_ij(h_i)
//     momentum     m_i dv_i/dt = −Σ_j [a_i b_j P_i/ω_i ∇_iW_ij(h_i) + a_j b_i P_j/ω_j ∇_iW_ij(h_j)]
//     energy       de_i/dt = (P_i/ρ_i²) dρ_i/dt          (a_i = m_i c_i/ρ_i², so Σ m(e + ½v²) is kept)
//     grad-h       ω_i = 1 + h_i/(d D_i) Σ_j b_j ∂W_ij/∂h(h_i),  D_i = ρ_i/c_i
//
//                  a_i          b_j         c_i
//     mass         m_i/ρ_i²     m_j         1       (ρ = Σ m W)
//     number       m_i²/ρ_i²    1           m_i     (ρ = m ñ, ñ = Σ W; Hu & Adams 2006)
//     volume       m_i/ρ_i      m_j/ρ_j     ρ_i     (colour-function measure)
//
// The momentum sum is antisymmetric in i, j, so linear momentum is conserved to round-off for
// every scheme; with ω the energy equation is exactly the work of the pressure forces. ω is
// floored at omegaMin (at a free surface the sum behind it loses its far half). The keywords
// form, gradH and omegaMin are common to the schemes (commonKeywords); doc/models/densityScheme/.
#include "core/KeywordSchema.hpp"
#include "core/Registry.hpp"

#include <cstddef>
#include <memory>

namespace mfdyn {

class DensityScheme {
public:
    static constexpr const char* familyName = "densityScheme";
    using Selector = Registry<DensityScheme, const Dictionary&>;
    static std::unique_ptr<DensityScheme> New(const Dictionary& dict) { return Selector::New(dict); }

    virtual ~DensityScheme();

    // a, b, c for n particles.
    virtual void coefficients(std::size_t n, const double* mass, const double* rho, double* a, double* b,
                              double* c) const = 0;
    // Whether ρ_i = c_i Σ b_j W can be evaluated explicitly (volume: b depends on ρ itself).
    virtual bool explicitSummation() const { return true; }

    bool summation() const { return summation_; }
    bool gradH() const { return gradH_; }
    // The floor of the grad-h factor ω.
    double omegaMin() const { return omegaMin_; }

protected:
    explicit DensityScheme(const KeywordValues& v);
    // form, gradH and omegaMin, declared for the scheme `type`.
    static KeywordSchema commonKeywords(const char* type);

private:
    bool summation_;
    bool gradH_;
    double omegaMin_;
};

}  // namespace mfdyn
