// Monaghan-Gingold artificial viscosity (Monaghan & Gingold 1983, J. Comput. Phys. 52:374;
// Monaghan 1992, Annu. Rev. Astron. Astrophys. 30:543, Eq. 4.1), for approaching pairs:
//
//   μ_ij = h̄ v_ij·x_ij/(|x_ij|² + 0.01 h̄²),  Π_ij = (−α c̄ μ_ij + β μ_ij²)/ρ̄,
//   dv_i/dt −= Σ m_j Π_ij ∇̄W,  de_i/dt += ½ Σ m_j Π_ij v_ij·∇̄W,
//
// with Balsara's (1995, J. Comput. Phys. 121:357) switch f_i = |∇·v|/(|∇·v| + |∇×v| + 1e-4 c_i/h_i)
// multiplying Π by ½(f_i+f_j), which removes the viscosity from shear flow. The artificial mass
// flux of the riemann model (Eq. 4.26) combines with it: the elliptical drop of Zisis 2017 §4.5.1
// pairs Monaghan's viscosity with a_ρ = 0.5, b_ρ = 0; it is off unless given:
//
//   dρ_i/dt += Σ m_j a_ρ (P_i − P_j)/(ρ̄ v'_ρ) F,  v'_ρ = c̄ − ½ b_ρ v_ij·r̂,  F = r̂·∇̄W.
//
// ∇·v and ∇×v of the switch are SPH estimates with volumes m/ρ and ∇_iW_ij(h_i). The terms are
// added to the pair sums inside SphSolver's fused pair loop (the member pair(); SphPairLoop.hpp).
#include "sph/MonaghanGingoldViscosity.hpp"

namespace mfdyn {

KeywordSchema MonaghanGingoldViscosity::keywords() {
    return KeywordSchema(familyName, "monaghanGingold")
        .scalar("alpha", "-", "linear (bulk) viscosity coefficient")
        .atLeast(0)
        .orDefault(1.0)
        .scalar("beta", "-", "quadratic (von Neumann-Richtmyer) coefficient")
        .atLeast(0)
        .orDefault(2.0)
        .flag("balsara", "Balsara's switch against viscosity in shear flow")
        .orDefault(false)
        .vector("density", "-", "(a_rho b_rho): artificial mass flux on the pressure jump (riemann Eq. 4.26)")
        .atLeast(0)
        .ofLength(2)
        .orDefault(std::vector<double>{0.0, 0.0});
}

MonaghanGingoldViscosity::MonaghanGingoldViscosity(const Dictionary& dict) : Dissipation(dict) {
    const KeywordValues v = keywords().read(dict);
    k_.alpha = v.scalar("alpha");
    k_.beta = v.scalar("beta");
    k_.balsara = v.flag("balsara");
    k_.arho = v.vector("density")[0];
    k_.brho = v.vector("density")[1];
    massFlux_ = k_.arho > 0;
}

template <int Dim>
void MonaghanGingoldViscosity::prepare(const SphPairLoop<Dim>& loop) {
    if (!k_.balsara) return;
    balsara_.assign(loop.size, 1.0);
    const Vector<Dim>* x = loop.x;
    const Vector<Dim>* v = loop.v;
    parallelFor(loop.owned, [&](std::size_t i) {
        double div = 0;
        Eigen::Vector3d curl = Eigen::Vector3d::Zero();
        for (const auto j : loop.neighbours[i]) {
            const Vector<Dim> xij = x[i] - x[j];
            const double r = xij.norm();
            if (r == 0) continue;
            const Vector<Dim> g = (loop.W.dWdr(r, loop.h[i]) / r) * xij;
            const Vector<Dim> vji = v[j] - v[i];
            const double vol = loop.m[j] / loop.rho[j];
            div += vol * vji.dot(g);
            if constexpr (Dim >= 2) curl.z() += vol * (vji[1] * g[0] - vji[0] * g[1]);
            if constexpr (Dim == 3) {
                curl.x() += vol * (vji[2] * g[1] - vji[1] * g[2]);
                curl.y() += vol * (vji[0] * g[2] - vji[2] * g[0]);
            }
        }
        balsara_[i] = std::abs(div) / (std::abs(div) + curl.norm() + 1e-4 * loop.c[i] / loop.h[i]);
    });
    loop.particles->copyToGhosts(balsara_);
}

// One approaching pair (v_ij·r̂ < 0): Π_ij, its force, heating and the optional mass flux above.
template <int Dim>
void MonaghanGingoldViscosity::pair(const SphPairLoop<Dim>& loop, const SphPair<Dim>& q,
                                    SphPairSums<Dim>& s) const {
    const double vr = q.vr;
    if (!(vr < 0)) return;
    const std::size_t j = q.j;
    const double ci = q.ci, cj = loop.c[j], r = q.r;
    const double hBar = 0.5 * (q.hi + loop.h[j]);
    const double mu = hBar * q.vij.dot(q.xij) / (r * r + 0.01 * hBar * hBar);
    double viscous = (-k_.alpha * 0.5 * (ci + cj) * mu + k_.beta * mu * mu) / (0.5 * (q.rhoi + loop.rho[j]));
    if (!balsara_.empty()) viscous *= 0.5 * (balsara_[q.i] + balsara_[j]);
    const double F = 0.5 * (q.dWi + q.dWj);
    s.force -= (q.mi * loop.m[j] * viscous * F) * q.rhat;
    s.heating += 0.5 * loop.m[j] * viscous * vr * F;
    if (massFlux_) {
        const double sig = 0.5 * (ci + cj) - 0.5 * k_.brho * vr;
        s.massFlux += loop.m[j] * k_.arho * (q.Pi - loop.p[j]) / (0.5 * (q.rhoi + loop.rho[j]) * sig) * F;
    }
}

void MonaghanGingoldViscosity::computeRates(SphPairLoop<1>& loop) {
    loop.run(*this);
}
void MonaghanGingoldViscosity::computeRates(SphPairLoop<2>& loop) {
    loop.run(*this);
}
void MonaghanGingoldViscosity::computeRates(SphPairLoop<3>& loop) {
    loop.run(*this);
}

MFDYN_REGISTER(Dissipation, MonaghanGingoldViscosity, "monaghanGingold",
               "alpha/beta artificial viscosity with optional Balsara switch");

}  // namespace mfdyn
