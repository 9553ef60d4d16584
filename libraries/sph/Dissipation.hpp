#pragma once
// Artificial dissipation of an SPH shock solver, chosen by name:
//
//   dissipation { type riemann; velocity (1 2); density (0.5 2); energy (0.1 2); signal riemann; pairs approaching; }
//   dissipation { type monaghanGingold; alpha 1; beta 2; balsara no; density (0.5 0); }  // + optional mass flux
//   dissipation { type none; }
//
// riemann (Zisis 2017 §4.2, eqs. 4.21–4.28; Price 2008), for each pair with v_ij·r̂_ij ≤ 0 (or all
// pairs), ρ̄ = ½(ρ_i+ρ_j), c̄ = ½(c_i+c_j), ∇̄W = ½(∇_iW_ij(h_i) + ∇_iW_ij(h_j)), F = r̂·∇̄W (< 0):
//   signal velocity      v'_ψ = c̄ − ½ b_ψ v_ij·r̂                          (4.22)
//                    or  √(c_i² + b(v·r̂)²) + √(c_j² + b(v·r̂)²) − v·r̂        (4.24, `signal alternative`)
//   viscosity            dv_i/dt += Σ m_j a_v v'_v (v_ij·r̂)/ρ̄ ∇̄W                      (4.27)
//   mass flux            dρ_i/dt += Σ m_j a_ρ (P_i − P_j)/(ρ̄ v'_ρ) F                  (4.26)
//   heating, conduction  de_i/dt += Σ (m_j/ρ̄)[−½ a_v v'_v (v_ij·r̂)² + a_e v'_e (e_i − e_j)] F   (4.28,
//                        conduction sign corrected to be diffusive: note §12 item 6)
// Each (a, b) pair is given per variable; a = 0 switches that term off.
//
// monaghanGingold (Monaghan & Gingold 1983; Monaghan 1992), for approaching pairs:
//   μ_ij = h̄ v_ij·x_ij/(|x_ij|² + 0.01 h̄²),  Π_ij = (−α c̄ μ_ij + β μ_ij²)/ρ̄,
//   dv_i/dt −= Σ m_j Π_ij ∇̄W,  de_i/dt += ½ Σ m_j Π_ij v_ij·∇̄W,
//   with Balsara's (1995) switch f_i = |∇·v|/(|∇·v| + |∇×v| + 1e-4 c_i/h_i) multiplying Π by ½(f_i+f_j).
#include "core/Registry.hpp"

#include <memory>

namespace mfdyn {

struct DissipationParameters {
    enum class Kind { none, riemann, monaghanGingold } kind = Kind::none;
    double av = 0, bv = 0, arho = 0, brho = 0, ae = 0, be = 0;
    bool alternativeSignal = false;
    bool allPairs = false;
    double alpha = 0, beta = 0;
    bool balsara = false;
};

class Dissipation {
public:
    static constexpr const char* familyName = "dissipation";
    using Selector = Registry<Dissipation, const Dictionary&>;
    static std::unique_ptr<Dissipation> New(const Dictionary& dict) { return Selector::New(dict); }

    explicit Dissipation(const Dictionary&) {}
    virtual ~Dissipation() = default;
    // The pair terms are evaluated inside the solver's force loop (a virtual call per pair would
    // cost more than the terms); a model states its parameters.
    virtual DissipationParameters parameters() const = 0;
};

}  // namespace mfdyn
