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
// The mass flux acts at contacts only (`densityLimiter contact`, the default; issue 16):
//
//   mass flux (limited)  dρ_i/dt += Σ m_j a_ρ sgn(P_i − P_j) min(1, |ρ_i − ρ_j|/(κ max(ρ_i, ρ_j)))
//                                    × max(0, |P_i − P_j|/(ρ̄ v'_ρ) − |v_ij·r̂|) F,   κ = 0.3     (4.26′)
//
// Why: 4.26 diffuses ρ on every pressure jump, and at a shock the jump is the shock's own. It changes ρ
// without work (e is untouched, so P = P(ρ, e) moves with ρ), and a particle crossing the front keeps a
// net change that does not depend on h or Δt (the flux ~ ΔP/h acts for the crossing time ~ h/s): the
// post-shock plateau is off by a fixed fraction (+1.1% in ρ and P at a pressure ratio of 10, ±1.5% at
// 10³–10⁵) and the L1 error stops converging, the mass-flux analogue of wall heating (Noh 1987). The
// term is meant for contacts, where the pressure should be continuous and SPH's smoothed density jump
// makes it blip (as Price 2008's conductivity, whose signal √(|ΔP|/ρ̄) is built for them). 4.26′ keeps
// it there: |ΔP|/(ρ̄ v'_ρ) is the velocity jump the pressure jump implies (a linearised Riemann
// problem's), so its excess over the pair's approach speed is the part no compression carries (zero
// through a shock, whole at a contact, where v_ij·r̂ ≈ 0), and the density contrast switches it off
// where there is no density jump to smooth (a diaphragm between equal densities, where at rest the
// whole jump is excess, and a solid's interior); a contrast of κ = 30% or more (Sod's 1:8, the
// isentropic bar's 1:2.5 interface) is a contact in full. Measured (strongShockTube/README.md): the
// plateau within 0.25% at pressure ratios 10–10⁵ and L1(ρ) of order 0.75–0.9; Sod's L1(ρ) 4.1e-3 → 4.8e-3.
// `densityLimiter none` is 4.26 as published (tests/cases/impactSph/strongShock*.sh measure both).
//
// Each (a, b) pair is given per variable: a the coefficient, b the factor of the relative
// velocity in the signal velocity; a = 0 switches that term off. The terms are added to the
// pair sums inside SphSolver's fused pair loop (the member pair(); SphPairLoop.hpp).
#include "sph/RiemannDissipation.hpp"

#include <algorithm>
#include <cmath>

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
        .orDefault("approaching")
        .word("densityLimiter", {"contact", "none"},
              "where the mass flux acts: at contacts only (contact: the pair's density contrast times the "
              "pressure jump its approach does not carry; converges at strong shocks) or on every pressure "
              "jump (none: Eq. 4.26 as published, a plateau error behind strong shocks)")
        .orDefault("contact");
}

RiemannDissipation::RiemannDissipation(const Dictionary& dict) : Dissipation(dict) {
    const KeywordValues v = keywords().read(dict);
    k_.av = v.vector("velocity")[0];
    k_.bv = v.vector("velocity")[1];
    k_.arho = v.vector("density")[0];
    k_.brho = v.vector("density")[1];
    k_.ae = v.vector("energy")[0];
    k_.be = v.vector("energy")[1];
    k_.alternativeSignal = v.word("signal") == "alternative";
    k_.allPairs = v.word("pairs") == "all";
    k_.contactLimiter = v.word("densityLimiter") == "contact";
    massFlux_ = k_.arho > 0;
}

// One pair, approaching (v_ij·r̂ ≤ 0) or any with `pairs all`: Eqs. 4.22/4.24, 4.26-4.28 above.
template <int Dim>
void RiemannDissipation::pair(const SphPairLoop<Dim>& loop, const SphPair<Dim>& q,
                              SphPairSums<Dim>& s) const {
    const double vr = q.vr;
    if (!(k_.allPairs || vr <= 0)) return;
    const std::size_t j = q.j;
    const double ci = q.ci, cj = loop.c[j];
    const double invRhoBar = 2.0 / (q.rhoi + loop.rho[j]);
    const double F = 0.5 * (q.dWi + q.dWj);  // r̂·∇̄W
    auto signal = [&](double bb) {
        if (k_.alternativeSignal)
            return std::sqrt(ci * ci + bb * vr * vr) + std::sqrt(cj * cj + bb * vr * vr) - vr;
        return 0.5 * (ci + cj) - 0.5 * bb * vr;
    };
    const double vSignal = signal(k_.bv);
    const double mjF = loop.m[j] * invRhoBar * F;
    s.force += (q.mi * k_.av * vSignal * vr * mjF) * q.rhat;
    if (massFlux_) {
        const double dP = q.Pi - loop.p[j];
        if (k_.contactLimiter) {
            // Eq. 4.26′ above: the velocity jump the pressure jump implies, |ΔP|/(ρ̄ v'_ρ), less the
            // pair's approach speed (what a shock's compression carries), times the density contrast.
            const double excess = std::abs(dP) * invRhoBar / signal(k_.brho) - std::abs(vr);
            if (excess > 0) {
                const double rhoj = loop.rho[j];
                const double contrast =
                    std::min(1.0, std::abs(q.rhoi - rhoj) / (contactContrast * std::max(q.rhoi, rhoj)));
                s.massFlux += k_.arho * contrast * std::copysign(excess, dP) * loop.m[j] * F;
            }
        } else {
            s.massFlux += k_.arho * dP / signal(k_.brho) * mjF;
        }
    }
    s.heating +=
        (-0.5 * k_.av * vSignal * vr * vr + k_.ae * signal(k_.be) * (q.ei - (loop.e ? loop.e[j] : 0.0))) *
        mjF;
}

// Named for the unit tests of the pair terms (tests/unit/sph/DissipationTest.cpp).
template void RiemannDissipation::pair<1>(const SphPairLoop<1>&, const SphPair<1>&, SphPairSums<1>&) const;

void RiemannDissipation::computeRates(SphPairLoop<1>& loop) {
    loop.run(*this);
}
void RiemannDissipation::computeRates(SphPairLoop<2>& loop) {
    loop.run(*this);
}
void RiemannDissipation::computeRates(SphPairLoop<3>& loop) {
    loop.run(*this);
}

MFDYN_REGISTER(Dissipation, RiemannDissipation, "riemann",
               "Riemann-like signal-velocity dissipation on v, rho (mass flux, at contacts only by default: "
               "densityLimiter) and e (Zisis 2017, Price 2008)");

}  // namespace mfdyn
