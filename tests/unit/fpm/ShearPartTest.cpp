// fpm/ShearPart: the shear part's dimensional upwinding (doc/methods/fpm.md §3.3). R3 of §4b: for
// linear v and S the upwind corrections of the derivatives vanish (grad v_D = grad v,
// div S_D = div S to 1e-12 relative), the printed dimensional velocity equals v, and the corrected
// one differs from it by exactly the linear fields' bracket of (5.52): for S linear with constant
// d_l S^il, -(1/(d Z)) sum_l (S^il(x - l e_l) - S^il(x + l e_l))/2 = (l/(d Z)) (div S)_i. With a
// uniform S both variants equal v. On the jittered cube of EulerPartTest (13^3 on [0, 1]^3, h =
// 2.2 dx, the thesis's fit), interior (shifted supports inside the cloud) to 1e-12, every shifted
// particle to 1e-10 (the supports near the faces half full: the fit's own bound there).
#include "fpm/ShearPart.hpp"

#include "core/Dictionary.hpp"
#include "particles/NeighbourSearch.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>

namespace mfdyn {
namespace {

LeastSquaresOperators<3>::Options fitOptions() {
    LeastSquaresOperators<3>::Options o;
    o.order = 1;
    o.form = LeastSquaresOperators<3>::Form::value;
    o.derivative = LeastSquaresOperators<3>::Derivative::full;
    o.minNeighbours = 8;
    return o;
}

struct Fields {
    std::vector<Vector<3>> x;
    double h = 0;
    NeighbourList rows;
    std::unique_ptr<FitWeight> weight =
        FitWeight::New(Dictionary::parse("type truncatedGaussian; alpha 6.25; squared yes;", "test"));
    LeastSquaresOperators<3> fit{fitOptions()};
    std::vector<double> rho, mu;
    std::vector<Vector<3>> v;
    std::vector<SymmTensor<3>> S;
    Tensor<3> G;              // grad v
    SymmTensor<3> S0, dS[3];  // S = S0 + sum_k dS[k] x_k
    explicit Fields(bool uniformStress) {
        const int n = 13;
        const double dx = 1.0 / (n - 1);
        h = 2.2 * dx;
        std::mt19937_64 rng(23);
        std::uniform_real_distribution<double> jitter(-0.2, 0.2);
        for (int k = 0; k < n; ++k)
            for (int j = 0; j < n; ++j)
                for (int i = 0; i < n; ++i) {
                    Vector<3> p(i * dx, j * dx, k * dx);
                    for (int d = 0; d < 3; ++d) p[d] += jitter(rng) * dx;
                    x.push_back(p);
                }
        NeighbourSearchOptions o;
        o.criterion = PairCriterion::gather;
        o.includeSelf = true;
        o.sortRows = true;
        NeighbourSearch<3> search(NeighbourDomain<3>{}, o);
        rows = search.build(x, 1.5 * h);
        fit.rebuild(x, x, rows, std::vector<double>(x.size(), h), *weight);
        G << 0.1, 0.02, -0.03, 0.04, -0.05, 0.06, -0.01, 0.03, 0.08;
        S0.c = {1.0, -0.4, -0.6, 0.3, -0.2, 0.5};
        if (!uniformStress) {
            dS[0].c = {0.2, -0.1, -0.1, 0.05, 0.3, -0.2};
            dS[1].c = {-0.3, 0.1, 0.2, 0.4, 0.1, 0.07};
            dS[2].c = {0.1, 0.2, -0.3, -0.15, 0.25, 0.1};
        }
        for (const auto& p : x) {
            v.push_back(Vector<3>(0.1, -0.2, 0.3) + G * p);
            SymmTensor<3> s = S0;
            for (int k = 0; k < 3; ++k)
                for (int c = 0; c < 6; ++c) s.c[std::size_t(c)] += dS[k].c[std::size_t(c)] * p(k);
            S.push_back(s);
        }
        rho.assign(x.size(), 1.3);
        mu.assign(x.size(), 0.8);
    }
    Vector<3> divS() const {
        Vector<3> d = Vector<3>::Zero();
        for (int a = 0; a < 3; ++a)
            for (int b = 0; b < 3; ++b) d(a) += dS[b](a, b);
        return d;
    }
    bool interior(const Vector<3>& p) const {
        return p.minCoeff() >= 1.5 * h && p.maxCoeff() <= 1.0 - 1.5 * h;
    }
};

void run(bool uniformStress, bool corrected) {
    Fields s(uniformStress);
    fpm::ShearOptions o;
    o.deltaIsTime = false;
    o.delta = 0.3;  // l = 0.3 h
    o.correctedVelocity = corrected;
    fpm::ShearPart<3> shear(fitOptions(), o);
    shear.upwind(s.x, s.rows, s.h, *s.weight, s.rho, s.v, s.S, s.mu, s.fit.gradientOf(s.v),
                 fpm::ShearPart<3>::divergence(s.fit, s.S));
    const auto& r = shear.result();
    const std::size_t n = s.x.size();
    EXPECT_EQ(r.unstrained, 0u);
    EXPECT_LT(r.tooFew, n / 10);
    const Vector<3> div = s.divS();
    const double Z = std::sqrt(0.8 * 1.3), l = 0.3 * s.h;
    const double divScale = uniformStress ? 1.0 : div.norm();
    double err[2][3] = {{0, 0, 0}, {0, 0, 0}};  // [interior, all][grad v, div S, v_D]
    std::size_t interior = 0, shifted = 0;
    for (std::size_t i = 0; i < n; ++i) {
        if (r.shift[i] == 0) continue;
        ++shifted;
        // l, or l/2, l/4, l/8 where a shifted point beyond the cloud's edge failed (the shortened shift)
        const double k = std::log2(l / r.shift[i]);
        EXPECT_TRUE(k >= 0 && k <= 3 && k == std::round(k)) << r.shift[i];
        const bool in = s.interior(s.x[i]);
        interior += in;
        const Vector<3> vExact = corrected ? Vector<3>(s.v[i] + (r.shift[i] / (3 * Z)) * div) : s.v[i];
        const double e[3] = {(r.gradV[i] - s.G).norm() / s.G.norm(), (r.divS[i] - div).norm() / divScale,
                             (r.vD[i] - vExact).norm() / s.v[i].norm()};
        for (int k = 0; k < 2; ++k)
            if (k == 1 || in)
                for (int q = 0; q < 3; ++q) err[k][q] = std::max(err[k][q], e[q]);
    }
    EXPECT_EQ(shifted + r.tooFew, n);
    EXPECT_GT(r.shortened, 0u);  // the corners and edges of the cube
    EXPECT_GT(interior, 100u);
    for (int k = 0; k < 2; ++k) {
        const double tol = k == 0 ? 1e-12 : 1e-10;
        for (int q = 0; q < 3; ++q) EXPECT_LT(err[k][q], tol) << k << " " << q;
        std::printf(
            "[measured] R3 shear, %s S, v_D %s, %s (%zu of %zu shifted, l = 0.3 h): relative "
            "|grad v_D - G| %.1e, |div S_D - div S| %.1e, |v_D - exact| %.1e\n",
            uniformStress ? "uniform" : "linear", corrected ? "corrected" : "printed",
            k == 0 ? "interior" : "all", k == 0 ? interior : shifted, n, err[k][0], err[k][1], err[k][2]);
    }
}

TEST(ShearPart, correctionsVanishForLinearFieldsWithThePrintedVelocity) {
    run(false, false);
}
TEST(ShearPart, theCorrectedVelocityAddsTheLinearBracket) {
    run(false, true);
}
TEST(ShearPart, bothVelocitiesEqualVForAUniformStress) {
    run(true, false);
    run(true, true);
}

// The update is (5.47)-(5.49) with the deviator 1/d in forward Euler; mu = 0 leaves a particle
// central and S unchanged.
TEST(ShearPart, theUpdateIsForwardEulerOfTheSplitEquations) {
    Fields s(false);
    const std::size_t n = s.x.size();
    s.mu[0] = 0;  // not shifted
    fpm::ShearOptions o;
    o.deltaIsTime = false;
    fpm::ShearPart<3> shear(fitOptions(), o);
    shear.upwind(s.x, s.rows, s.h, *s.weight, s.rho, s.v, s.S, s.mu, s.fit.gradientOf(s.v),
                 fpm::ShearPart<3>::divergence(s.fit, s.S));
    const auto& r = shear.result();
    EXPECT_EQ(r.unstrained, 1u);
    EXPECT_EQ(r.shift[0], 0.0);
    std::vector<Vector<3>> v = s.v;
    std::vector<double> p(n, 0.7), e(n, 2.0), g(n, 1.5);
    std::vector<SymmTensor<3>> S = s.S;
    const double dt = 1e-3;
    shear.advance(dt, s.rho, v, p, S, &e, g, s.mu, 1.0 / 3.0);
    for (std::size_t i = 0; i < n; ++i) {
        const Tensor<3>& G = r.gradV[i];
        const Tensor<3> D = 0.5 * (G + G.transpose());
        const double work = (s.S[i].full().array() * D.array()).sum();
        EXPECT_DOUBLE_EQ(p[i], 0.7 + dt * (1.5 / 1.3) * (work - 0.7 * G.trace()));
        EXPECT_DOUBLE_EQ(e[i], 2.0 + dt * work / 1.3);
        EXPECT_LT((v[i] - s.v[i] - (dt / 1.3) * r.divS[i]).norm(), 1e-15);
        const Tensor<3> Sn = s.S[i].full() + dt * 2 * s.mu[i] * (D - G.trace() / 3.0 * Tensor<3>::Identity());
        EXPECT_LT((S[i].full() - Sn).norm(), 1e-14);
    }
    EXPECT_EQ(S[0].c, s.S[0].c);
}

}  // namespace
}  // namespace mfdyn
