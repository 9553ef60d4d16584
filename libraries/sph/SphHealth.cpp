// impactSph's health indicators (SphHealth.hpp), one gather over the pairs within the support of
// h_a (W(r_ab, h_a) > 0), for the owned particles a, ghosts among the neighbours b:
//
//   neighbourDeficiency  the Shepard sum S_a = Σ_b (m_b/ρ_b) W_ab(h_a), self included: 1 where the
//                        support is full (to the kernel's quadrature error), 1/2 at a plane free
//                        surface of a continuum, 1/4 at a right-angled edge, 0.5^d at a corner of a
//                        d-dimensional box (a lattice adds half of its surface row's own sum: 0.735
//                        at a face, 0.540 at a square's corner for the Gaussian at η = 1.2).
//                        Counted: S_a < 0.5^d. No part of a body's boundary whose angles are not
//                        sharper than a cube's corner goes below it, so a particle under it has lost
//                        neighbours that no such shape explains (detached, spalled, a tip drawn
//                        out). The self term alone is
//                        (m/ρ) W(0, h) = (1/(η √π))^d for the Gaussian at h = η (m/ρ)^(1/d):
//                        0.47, 0.22, 0.10 at η = 1.2 in 1, 2, 3 D, so an isolated particle is
//                        counted; a pair in 3D (0.16) is not. value: the smallest S_a.
//   tensileInstability   Swegle, Hicks & Attaway 1995 (J. Comput. Phys. 116:123): under tension
//                        the SPH pair force of a kernel with W'' > 0 at the neighbour distance
//                        pulls particles together, and they clump in pairs. Among the particles in
//                        tension (P < 0, or with a deviator the largest principal value of
//                        σ = −P I + τ above 0) q_a = min_b |x_ab| / (m_a/ρ_a)^(1/d), the nearest
//                        distance against the spacing the particle's own volume implies (its own
//                        mirror image left out): about 1 on any regular lattice (1.07 hexagonal),
//                        so q_a < 1/2 is two particles within half a spacing, a clump no lattice
//                        and no smooth compression makes. value: the smallest q_a in tension (1
//                        when no particle is in tension).
//   hourglass            the reproduction error of the velocity field (the idea of Ganzenmüller
//                        2015, Comput. Methods Appl. Mech. Engrg. 286:87: the pair's actual relative
//                        motion against the one the local smooth map predicts; there the
//                        total-Lagrangian F and positions, here velocities). With v_a + C_a φ(x_ba)
//                        the kernel-weighted least-squares fit of the neighbours' velocities by a
//                        quadratic field (φ: the d linear and d(d+1)/2 quadratic monomials of
//                        x_ba/h_a),
//                            e_a² = Σ_b W_ab |v_ba − C_a φ(x_ba)|² / Σ_b W_ab |v_ba|²,
//                        the fraction of the neighbours' velocity differences that no smooth field
//                        explains. e_a ∈ [0, 1] (C = 0 is a candidate); 0 to round-off for a linear
//                        (and a quadratic) field on any neighbourhood, a free surface or a jittered
//                        lattice included (the fit is exact there, which the solver's uncorrected
//                        SPH gradient is not). A linear fit alone would also count every smooth
//                        extremum of v (there v_ba ≈ ½ v'' r², all of it non-linear): the quadratic
//                        term takes those, and a smooth field with length scale ℓ gives e ~ (h/ℓ)².
//                        A zig-zag mode (v alternating on the lattice) gives 0.80 in 1D and 0.86 on a
//                        square lattice (Gaussian, η = 1.2: the fit takes what a parabola through
//                        the rings can). Counted: e_a > 0.7, half of the differences' square or more
//                        unexplained by any smooth field. On Sod's tube the particles counted are
//                        those of the contact, whose velocity wiggles from particle to particle by
//                        ~1e-3 of the flow speed (the known blip of SPH at a contact, Price 2008):
//                        the measure is one of shape, not amplitude. So e_a is set to 0 where the
//                        unexplained part is slow, its kernel-weighted RMS (Σ W |v_ba − C φ|²/Σ W)^½
//                        below 1e-3 of the particle's sound speed: a mode oscillating at the
//                        lattice's frequency ~ c/Δ moves neighbours apart by ~ (δv/c) Δ, under a
//                        thousandth of a spacing there, the noise of any SPH solid or gas at rest
//                        (the Taylor bar at rest after its impact: e up to 0.97 at 2e-5 to 5e-4 c,
//                        none counted; at 20 us, 12 particles at the impact face at 1e-3 to 8e-3 c
//                        are). value: the largest e_a.
//
// The pass builds its own gather list (one neighbour search, at the health check's writes only).
#include "sph/SphHealth.hpp"

#include "core/Parallel.hpp"
#include "particles/NeighbourSearch.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

namespace mfdyn {

namespace {

// M⁺ for a symmetric positive semi-definite M: eigenvalues below 1e-12 of the largest are dropped
// (neighbours on a line in 2D, none at all).
template <int N>
Eigen::Matrix<double, N, N> pseudoInverse(const Eigen::Matrix<double, N, N>& M) {
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix<double, N, N>> eigen(M);
    const auto& lambda = eigen.eigenvalues();
    const double largest = lambda.cwiseAbs().maxCoeff();
    Eigen::Matrix<double, N, 1> inverse = Eigen::Matrix<double, N, 1>::Zero();
    for (int k = 0; k < N; ++k)
        if (lambda[k] > 1e-12 * largest) inverse[k] = 1.0 / lambda[k];
    return eigen.eigenvectors() * inverse.asDiagonal() * eigen.eigenvectors().transpose();
}

template <int Dim>
bool inTension(const SphHealthState<Dim>& s, std::size_t a) {
    if (!s.tau) return s.p[a] < 0;
    const Tensor<Dim> sigma = s.tau[a].full() - s.p[a] * Tensor<Dim>::Identity();
    return Eigen::SelfAdjointEigenSolver<Tensor<Dim>>(sigma, Eigen::EigenvaluesOnly)
               .eigenvalues()
               .maxCoeff() > 0;
}

// The three counts and the three worst particles, one global reduction.
struct IndicatorSums {
    double deficient = 0, clumped = 0, hourglass = 0;
    ArgMin shepard, nearest, mode;  // mode holds −e: the largest e
    IndicatorSums& operator+=(const IndicatorSums& o) {
        deficient += o.deficient, clumped += o.clumped, hourglass += o.hourglass;
        shepard += o.shepard, nearest += o.nearest, mode += o.mode;
        return *this;
    }
};

std::string number(double v) {
    char s[32];
    std::snprintf(s, sizeof s, "%g", v);
    return s;
}

}  // namespace

template <int Dim>
SphHealthValues<Dim> sphHealthValues(const SphHealthState<Dim>& s) {
    const std::size_t n = s.owned;
    const std::vector<Vector<Dim>> x(s.x, s.x + s.size);
    std::vector<double> radius(s.size);
    for (std::size_t i = 0; i < s.size; ++i) radius[i] = s.h[i] / s.W.invKappa;
    NeighbourSearchOptions options;
    options.criterion = PairCriterion::gather;
    NeighbourSearch<Dim> search(NeighbourDomain<Dim>{}, options);
    const NeighbourList list = search.build(x, radius);
    SphHealthValues<Dim> out;
    out.shepard.resize(n), out.nearestRatio.resize(n), out.hourglass.resize(n), out.tension.resize(n);
    const KernelEvaluator<Dim> W = s.W;
    parallelForWork(n, list.pairCount(), [&](std::size_t a) {
        const double ha = s.h[a], Va = s.m[a] / s.rho[a];
        double S = Va * W.W(0.0, ha), nearest = std::numeric_limits<double>::infinity();
        double weights = 0, total = 0;
        for (const auto b : list[a]) {
            const Vector<Dim> xba = x[b] - x[a];
            const double r = xba.norm();
            const bool ownImage = b >= s.owned && s.imageOf && s.imageOf[b - s.owned] == a;
            if (!ownImage) nearest = std::min(nearest, r);
            const double w = W.W(r, ha);
            if (!(w > 0)) continue;
            S += s.m[b] / s.rho[b] * w;
            total += w * (s.v[b] - s.v[a]).squaredNorm();
            weights += w;
        }
        out.shepard[a] = S;
        out.nearestRatio[a] = nearest / std::pow(Va, 1.0 / Dim);
        out.tension[a] = inTension(s, a);
        const double floor = hourglassNoiseFloor * (s.soundSpeed ? s.soundSpeed[a] : s.v[a].norm());
        double e = 0;
        if (weights > 0 && total > floor * floor * weights) {
            // The quadratic fit in ξ = x_ba/h_a (scaled, so that M is well conditioned).
            constexpr int P = Dim + Dim * (Dim + 1) / 2;
            using Basis = Eigen::Matrix<double, P, 1>;
            auto basis = [&](const Vector<Dim>& xba) {
                const Vector<Dim> xi = xba / ha;
                Basis phi;
                int k = 0;
                for (int d = 0; d < Dim; ++d) phi[k++] = xi[d];
                for (int d = 0; d < Dim; ++d)
                    for (int f = d; f < Dim; ++f) phi[k++] = xi[d] * xi[f];
                return phi;
            };
            Eigen::Matrix<double, P, P> Mq = Eigen::Matrix<double, P, P>::Zero();
            Eigen::Matrix<double, Dim, P> Gq = Eigen::Matrix<double, Dim, P>::Zero();
            for (const auto b : list[a]) {
                const Vector<Dim> xba = x[b] - x[a];
                const double w = W.W(xba.norm(), ha);
                if (!(w > 0)) continue;
                const Basis phi = basis(xba);
                Mq += w * phi * phi.transpose();
                Gq += w * (s.v[b] - s.v[a]) * phi.transpose();
            }
            const Eigen::Matrix<double, Dim, P> C = Gq * pseudoInverse<P>(Mq);
            double residual = 0;  // summed again, not total − tr(G M⁺ Gᵀ): that cancels to √eps
            for (const auto b : list[a]) {
                const Vector<Dim> xba = x[b] - x[a];
                const double w = W.W(xba.norm(), ha);
                if (w > 0) residual += w * (s.v[b] - s.v[a] - C * basis(xba)).squaredNorm();
            }
            // A mode slower than the gate is noise (SphHealth.cpp's head).
            if (residual > floor * floor * weights) e = std::sqrt(std::min(1.0, residual / total));
        }
        out.hourglass[a] = e;
    });
    return out;
}

template <int Dim>
std::vector<HealthIndicator> sphHealthIndicators(const SphHealthState<Dim>& s) {
    const SphHealthValues<Dim> values = sphHealthValues(s);
    const double deficiencyThreshold = std::pow(0.5, Dim);
    const IndicatorSums sums = GlobalReduce::sum<IndicatorSums>(s.owned, [&](std::size_t a) {
        IndicatorSums t;
        const std::int64_t id = s.globalId[a];
        t.shepard = {values.shepard[a], id};
        t.deficient = values.shepard[a] < deficiencyThreshold ? 1 : 0;
        if (values.tension[a]) {
            t.nearest = {values.nearestRatio[a], id};
            t.clumped = values.nearestRatio[a] < tensileClumpRatio ? 1 : 0;
        }
        t.mode = {-values.hourglass[a], id};
        t.hourglass = values.hourglass[a] > hourglassThreshold ? 1 : 0;
        return t;
    });
    const std::string d = std::to_string(Dim);
    std::vector<HealthIndicator> out(3);
    out[0] = {"neighbourDeficiency", sums.shepard.particle() >= 0 ? sums.shepard.value : 1.0,
              std::size_t(sums.deficient), sums.shepard.particle(),
              "the smallest Shepard sum S_a = sum_b (m_b/rho_b) W_ab(h_a), self included (1 inside, 1/2 at a "
              "free surface); counted: S_a < 0.5^" +
                  d + " = " + number(deficiencyThreshold) +
                  ", below a box corner's: a particle that lost its neighbours"};
    out[1] = {"tensileInstability",
              // 1 when none is in tension: no clumping to report, and no NaN in health.csv.
              sums.nearest.particle() >= 0 ? sums.nearest.value : 1.0,
              std::size_t(sums.clumped), sums.nearest.particle(),
              "among particles in tension (P < 0, or a principal stress of -P I + tau above 0) the smallest "
              "nearest-neighbour distance over the spacing (m/rho)^(1/d) (1 when none is in tension); "
              "counted: "
              "below " +
                  number(tensileClumpRatio) + ", particles clumping in pairs (Swegle, Hicks & Attaway 1995)"};
    const bool mode = sums.mode.value < 0;  // some e_a > 0 (else no particle is named)
    out[2] = {
        "hourglass", mode ? -sums.mode.value : 0.0, std::size_t(sums.hourglass),
        mode ? sums.mode.particle() : -1,
        "the largest reproduction error e_a of the velocity field: the kernel-weighted RMS of what a "
        "least-squares quadratic fit about particle a leaves of v_b - v_a, over the RMS of v_b - v_a (0: a "
        "smooth field, 0.8 to 0.86: a zig-zag mode; cf. Ganzenmueller 2015); counted: e_a > " +
            number(hourglassThreshold)};
    return out;
}

template SphHealthValues<1> sphHealthValues(const SphHealthState<1>&);
template SphHealthValues<2> sphHealthValues(const SphHealthState<2>&);
template SphHealthValues<3> sphHealthValues(const SphHealthState<3>&);
template std::vector<HealthIndicator> sphHealthIndicators(const SphHealthState<1>&);
template std::vector<HealthIndicator> sphHealthIndicators(const SphHealthState<2>&);
template std::vector<HealthIndicator> sphHealthIndicators(const SphHealthState<3>&);

}  // namespace mfdyn
