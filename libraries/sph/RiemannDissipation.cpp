// Riemann-like artificial dissipation (Zisis 2017 §4.2, eqs. 4.21-4.28; Price 2008, J. Comput.
// Phys. 227:10040; doc/methods/sph-impact.md section 3). For each pair with v_ij·r̂_ij ≤ 0 (or all pairs),
// ρ̄ = ½(ρ_i+ρ_j), c̄ = ½(c_i+c_j), ∇̄W = ½(∇_iW_ij(h_i) + ∇_iW_ij(h_j)), F = r̂·∇̄W (< 0):
//
//   signal velocity      v'_ψ = c̄ − ½ b_ψ v_ij·r̂                          (4.22)
//                    or  √(c_i² + b(v·r̂)²) + √(c_j² + b(v·r̂)²) − v·r̂        (4.24, `signal alternative`)
//   viscosity            dv_i/dt += Σ m_j a_v v'_v (v_ij·r̂)/ρ̄ ∇̄W                      (4.27)
//   mass flux            dρ_i/dt += Σ m_j a_ρ (P_i − P_j)/(ρ̄ v'_ρ) F                  (4.26)
//   heating, conduction  de_i/dt += Σ (m_j/ρ̄)[−½ a_v v'_v (v_ij·r̂)² + a_e v'_e (e_i − e_j)] F   (4.28,
//                        conduction sign corrected to be diffusive: doc/methods/sph-impact.md §12 item 6)
//
// Each (a, b) pair is given per variable: a the coefficient, b the factor of the relative
// velocity in the signal velocity; a = 0 switches that term off. The terms are applied in
// SphSolver's force loop from parameters().
#include "sph/RiemannDissipation.hpp"

namespace mfdyn {

KeywordSchema RiemannDissipation::keywords() {
    return KeywordSchema(familyName, "riemann")
        .vector("velocity", "-", "(a_v b_v): viscosity and viscous heating, coefficient and signal factor")
        .atLeast(0)
        .ofLength(2)
        .orDefault(std::vector<double>{1.0, 2.0})
        .vector("density", "-", "(a_rho b_rho): artificial mass flux on the pressure jump")
        .atLeast(0)
        .ofLength(2)
        .orDefault(std::vector<double>{0.5, 2.0})
        .vector("energy", "-", "(a_e b_e): conduction of specific internal energy")
        .atLeast(0)
        .ofLength(2)
        .orDefault(std::vector<double>{0.1, 2.0})
        .word("signal", {"riemann", "alternative"}, "signal velocity: Eq. 4.22 (riemann) or Eq. 4.24")
        .orDefault("riemann")
        .word("pairs", {"approaching", "all"}, "pairs dissipated: approaching only (v_ij·r_ij ≤ 0) or all")
        .orDefault("approaching");
}

RiemannDissipation::RiemannDissipation(const Dictionary& dict) : Dissipation(dict) {
    const KeywordValues v = keywords().read(dict);
    p_.kind = DissipationParameters::Kind::riemann;
    p_.av = v.vector("velocity")[0];
    p_.bv = v.vector("velocity")[1];
    p_.arho = v.vector("density")[0];
    p_.brho = v.vector("density")[1];
    p_.ae = v.vector("energy")[0];
    p_.be = v.vector("energy")[1];
    p_.alternativeSignal = v.word("signal") == "alternative";
    p_.allPairs = v.word("pairs") == "all";
}

MFDYN_REGISTER(
    Dissipation, RiemannDissipation, "riemann",
    "Riemann-like signal-velocity dissipation on v, rho (mass flux) and e (Zisis 2017, Price 2008)");

}  // namespace mfdyn
