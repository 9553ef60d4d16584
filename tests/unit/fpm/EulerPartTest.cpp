// fpm/EulerPart: the Euler part's pressure-gradient upwinding (doc/methods/fpm.md §3.2). R3 of §4b:
// for linear v and p the upwind corrections of the derivatives vanish (div v_uw = tr grad v,
// grad p_uw = grad p to 1e-12), and the value corrections are the exact differences of the linear
// fields at x -+ l n: v_uw - Pi^c v = -(l |grad p| / (rho c)) n, p_uw - Pi^c p = -rho c l n.G n.
// On a jittered lattice on [0, 1]^3 (13^3) with a free face, h = 2.2 dx, the thesis's fit (linear
// basis, full derivative, truncated Gaussian squared). Relative to |grad p|, |G|: 1e-12 where the
// shifted points' supports lie inside the cloud (the shared fit's R1 test takes the same points);
// near the faces a shifted point's support is less than half full, M's condition and the round-off
// grow (the fit's own test measures 1e-11 there): 1e-10.
#include "fpm/EulerPart.hpp"

#include "core/Dictionary.hpp"
#include "particles/NeighbourSearch.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace mfdyn {
namespace {

struct Cloud {
    std::vector<Vector<3>> x;
    double h = 0;
};

Cloud cloud(int n) {
    Cloud c;
    const double dx = 1.0 / (n - 1);
    c.h = 2.2 * dx;
    std::mt19937_64 rng(19);
    std::uniform_real_distribution<double> jitter(-0.2, 0.2);
    for (int k = 0; k < n; ++k)
        for (int j = 0; j < n; ++j)
            for (int i = 0; i < n; ++i) {
                Vector<3> x(i * dx, j * dx, k * dx);
                for (int d = 0; d < 3; ++d)
                    if (!(d == 0 && i == 0)) x[d] += jitter(rng) * dx;
                c.x.push_back(x);
            }
    return c;
}

LeastSquaresOperators<3>::Options fitOptions() {
    LeastSquaresOperators<3>::Options o;
    o.order = 1;
    o.form = LeastSquaresOperators<3>::Form::value;
    o.derivative = LeastSquaresOperators<3>::Derivative::full;
    o.minNeighbours = 8;
    return o;
}

struct Fields {
    Cloud c = cloud(13);
    NeighbourList rows;
    std::unique_ptr<FitWeight> weight =
        FitWeight::New(Dictionary::parse("type truncatedGaussian; alpha 6.25; squared yes;", "test"));
    LeastSquaresOperators<3> fit{fitOptions()};
    std::vector<double> rho, p, c2, cs;
    std::vector<Vector<3>> v;
    Vector<3> a{0.3, -0.7, 0.2};  // grad p
    Tensor<3> G;                  // grad v
    Fields() {
        NeighbourSearchOptions o;
        o.criterion = PairCriterion::gather;
        o.includeSelf = true;
        o.sortRows = true;
        NeighbourSearch<3> search(NeighbourDomain<3>{}, o);
        rows = search.build(c.x, 1.5 * c.h);
        fit.rebuild(c.x, c.x, rows, std::vector<double>(c.x.size(), c.h), *weight);
        G << 0.1, 0.02, -0.03, 0.04, -0.05, 0.06, -0.01, 0.03, 0.08;
        const std::size_t n = c.x.size();
        rho.assign(n, 1.3);
        cs.assign(n, 1.7);
        for (std::size_t i = 0; i < n; ++i) {
            p.push_back(2.0 + a.dot(c.x[i]));
            v.push_back(Vector<3>(0.1, -0.2, 0.3) + G * c.x[i]);
        }
    }
};

TEST(EulerPart, correctionsVanishForLinearFields) {
    Fields s;
    fpm::UpwindOptions u;
    u.deltaIsTime = false;
    u.delta = 0.3;  // l = 0.3 h
    fpm::EulerPart<3> euler(fitOptions(), u);
    euler.upwind(s.c.x, s.rows, s.c.h, *s.weight, s.rho, s.p, s.v, s.cs, s.fit.gradientOf(s.p),
                 s.fit.gradientOf(s.v));
    const auto& r = euler.result();
    const std::size_t n = s.c.x.size();
    EXPECT_EQ(r.flat, 0u);
    EXPECT_LT(r.tooFew, n / 10);  // some on the free face and the corners
    EXPECT_GT(r.shortened, 0u);
    const Vector<3> nn = s.a.normalized();
    std::size_t upwinded = 0;
    // [0]: interior (the shifted supports inside the cloud), [1]: all
    double divErr[2] = {0, 0}, gpErr[2] = {0, 0}, vcErr[2] = {0, 0}, pcErr[2] = {0, 0};
    std::size_t interior = 0;
    const double lo = 1.5 * s.c.h, hi = 1.0 - 1.5 * s.c.h;
    for (std::size_t i = 0; i < n; ++i) {
        if (r.shift[i] == 0) continue;
        ++upwinded;
        const double l = r.shift[i], rc = s.rho[i] * s.cs[i];
        // 0.3 h, or 0.3 h / 2^k (k <= 3) where a shifted point beyond the free face failed
        const double k = std::log2(0.3 * s.c.h / l);
        EXPECT_TRUE(k >= 0 && k <= 3 && k == std::round(k)) << l;
        const Vector<3>& x = s.c.x[i];
        const bool in = x.minCoeff() >= lo && x.maxCoeff() <= hi;
        interior += in;
        const double e[4] = {std::abs(r.divV[i] - s.G.trace()) / s.G.norm(),
                             (r.gradP[i] - s.a).norm() / s.a.norm(),
                             (r.vCorrect[i] + (l * s.a.norm() / rc) * nn).norm() / (l * s.a.norm() / rc),
                             std::abs(r.pCorrect[i] + rc * l * nn.dot(s.G * nn)) / (rc * l * s.G.norm())};
        for (int k = 0; k < 2; ++k) {
            if (k == 0 && !in) continue;
            divErr[k] = std::max(divErr[k], e[0]);
            gpErr[k] = std::max(gpErr[k], e[1]);
            vcErr[k] = std::max(vcErr[k], e[2]);
            pcErr[k] = std::max(pcErr[k], e[3]);
        }
    }
    EXPECT_EQ(upwinded + r.tooFew, n);
    EXPECT_GT(interior, 100u);
    for (int k = 0; k < 2; ++k) {
        const double tol = k == 0 ? 1e-12 : 1e-10;
        EXPECT_LT(divErr[k], tol) << k;
        EXPECT_LT(gpErr[k], tol) << k;
        EXPECT_LT(vcErr[k], tol) << k;
        EXPECT_LT(pcErr[k], tol) << k;
        std::printf(
            "[measured] R3 %s (%zu particles of %zu upwinded, l = 0.3 h; %zu central): relative "
            "|div v_uw - tr G| %.1e, |grad p_uw - a| %.1e, value corrections off the exact %.1e %.1e\n",
            k == 0 ? "interior" : "all", k == 0 ? interior : upwinded, n, r.tooFew, divErr[k], gpErr[k],
            vcErr[k], pcErr[k]);
    }
}

TEST(EulerPart, theShiftIsDeltaCClampedToHalfH) {
    Fields s;
    fpm::UpwindOptions u;  // delta 0.3 s: l = 0.3 c
    fpm::EulerPart<3> euler(fitOptions(), u);
    s.cs.assign(s.c.x.size(), 0.1 * s.c.h);  // l = 0.03 h
    s.cs[0] = 10 * s.c.h;                    // l = 3 h, clamped to 0.5 h
    euler.upwind(s.c.x, s.rows, s.c.h, *s.weight, s.rho, s.p, s.v, s.cs, s.fit.gradientOf(s.p),
                 s.fit.gradientOf(s.v));
    const auto& r = euler.result();
    for (std::size_t i = 1; i < s.c.x.size(); ++i)
        if (r.shift[i] != 0) {
            const double k = std::log2(0.3 * 0.1 * s.c.h / r.shift[i]);  // or shortened by 2^k
            EXPECT_TRUE(k >= 0 && k <= 3 && k == std::round(k)) << r.shift[i];
        }
    ASSERT_NE(r.shift[0], 0.0);  // particle 0 (a corner) is shifted: the clamp applies (then halved)
    const double k0 = std::log2(0.5 * s.c.h / r.shift[0]);
    EXPECT_TRUE(k0 >= 0 && k0 <= 3 && k0 == std::round(k0)) << r.shift[0];
}

TEST(EulerPart, uniformPressureIsCentralAndTheUpdateIsForwardEuler) {
    Fields s;
    const std::size_t n = s.c.x.size();
    s.p.assign(n, 2.0);
    fpm::EulerPart<3> euler(fitOptions(), fpm::UpwindOptions{});
    const std::vector<Tensor<3>> gradV = s.fit.gradientOf(s.v);
    euler.upwind(s.c.x, s.rows, s.c.h, *s.weight, s.rho, s.p, s.v, s.cs, s.fit.gradientOf(s.p), gradV);
    const auto& r = euler.result();
    EXPECT_EQ(r.flat, n);
    EXPECT_EQ(r.tooFew, 0u);
    std::vector<double> rho = s.rho, p = s.p, e(n, 5.0);
    std::vector<Vector<3>> v = s.v;
    const double dt = 1e-3;
    euler.advance(dt, rho, v, p, &e, s.cs);
    for (std::size_t i = 0; i < n; ++i) {
        const double div = gradV[i].trace();
        EXPECT_NEAR(div, s.G.trace(), 1e-12);
        EXPECT_DOUBLE_EQ(rho[i], s.rho[i] - dt * s.rho[i] * div);
        EXPECT_DOUBLE_EQ(p[i], s.p[i] - dt * s.rho[i] * s.cs[i] * s.cs[i] * div);
        EXPECT_DOUBLE_EQ(e[i], 5.0 - dt * s.p[i] * div / s.rho[i]);
        EXPECT_LT((v[i] - s.v[i]).norm(), 1e-14);  // grad p = 0 to round-off
    }
}

}  // namespace
}  // namespace mfdyn
