// The conservation projections of Lee et al. 2016 (eqs. 45-51): after the projection the total
// force and the total moment about x~ vanish to round-off; the projection is the V-weighted
// least-squares one (idempotent, and the change is orthogonal to every field it leaves alone).
#include "tlSph/MomentumProjection.hpp"

#include <gtest/gtest.h>
#include <Eigen/Geometry>

#include <random>

namespace mfdyn {
namespace {

template <int Dim>
struct Cloud {
    std::vector<Vector<Dim>> x, f;
    std::vector<double> V;
};

template <int Dim>
Cloud<Dim> randomCloud(std::size_t n, unsigned seed) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> u(-1, 1);
    Cloud<Dim> c;
    for (std::size_t i = 0; i < n; ++i) {
        Vector<Dim> x, f;
        for (int d = 0; d < Dim; ++d) x[d] = 3 + u(rng), f[d] = 1e6 * u(rng);  // off-origin on purpose
        c.x.push_back(x), c.f.push_back(f), c.V.push_back(0.5 + 0.5 * (u(rng) + 1));
    }
    return c;
}

template <int Dim>
Vector<Dim> totalForce(const Cloud<Dim>& c) {
    Vector<Dim> s = Vector<Dim>::Zero();
    for (std::size_t i = 0; i < c.x.size(); ++i) s += c.V[i] * c.f[i];
    return s;
}

double moment(const Cloud<3>& c, Vector<3>& out) {
    out.setZero();
    double scale = 0;
    for (std::size_t i = 0; i < c.x.size(); ++i)
        out += c.V[i] * c.x[i].cross(c.f[i]), scale += c.V[i] * c.x[i].norm() * c.f[i].norm();
    return scale;
}

TEST(MomentumProjection, RemovesForceAndMomentIn3D) {
    for (std::size_t n : {50u, 6000u}) {  // serial and parallel reductions
        auto c = randomCloud<3>(n, 7);
        double scale = 0;
        for (std::size_t i = 0; i < n; ++i) scale += c.V[i] * c.f[i].norm();
        MomentumProjection<3>::momentum(c.f, c.V, c.x);
        EXPECT_LT(totalForce(c).norm(), 1e-13 * scale);
        Vector<3> m;
        const double mScale = moment(c, m);
        EXPECT_LT(m.norm(), 1e-13 * mScale);
        // Idempotent: a second projection changes nothing beyond round-off.
        const auto before = c.f;
        MomentumProjection<3>::momentum(c.f, c.V, c.x);
        double change = 0;
        for (std::size_t i = 0; i < n; ++i) change = std::max(change, (c.f[i] - before[i]).norm());
        EXPECT_LT(change, 1e-15 * scale);
    }
}

TEST(MomentumProjection, LeastSquaresChangeIsOrthogonalToConservingFields) {
    // f~ - f lies in span{constant, omega x x}; a field g with sum V g = 0, sum V x x g = 0 is
    // V-orthogonal to it.
    auto c = randomCloud<3>(200, 11);
    auto g = randomCloud<3>(200, 12).f;
    MomentumProjection<3>::momentum(g, c.V, c.x);
    const auto f0 = c.f;
    MomentumProjection<3>::momentum(c.f, c.V, c.x);
    double dot = 0, scale = 0;
    for (std::size_t i = 0; i < c.x.size(); ++i) {
        dot += c.V[i] * (c.f[i] - f0[i]).dot(g[i]);
        scale += c.V[i] * (c.f[i] - f0[i]).norm() * g[i].norm();
    }
    EXPECT_LT(std::abs(dot), 1e-12 * scale);
}

TEST(MomentumProjection, TwoDimensionsZMomentOnly) {
    auto c = randomCloud<2>(300, 3);
    MomentumProjection<2>::momentum(c.f, c.V, c.x);
    double m = 0, scale = 0;
    for (std::size_t i = 0; i < c.x.size(); ++i) {
        m += c.V[i] * (c.x[i][0] * c.f[i][1] - c.x[i][1] * c.f[i][0]);
        scale += c.V[i] * c.x[i].norm() * c.f[i].norm();
    }
    EXPECT_LT(std::abs(m), 1e-13 * scale);
    EXPECT_LT(totalForce(c).norm(), 1e-13 * scale);
}

TEST(MomentumProjection, LinearOnlyAndOneDimension) {
    auto c = randomCloud<3>(100, 5);
    MomentumProjection<3>::momentum(c.f, c.V, c.x, false);
    Vector<3> m;
    const double mScale = moment(c, m);
    EXPECT_LT(totalForce(c).norm(), 1e-13 * 100 * 1e6);  // round-off of sums of ~100 terms of 1e6
    EXPECT_GT(m.norm(), 1e-3 * mScale);                  // the moment is left alone
    auto d = randomCloud<1>(100, 6);
    MomentumProjection<1>::momentum(d.f, d.V, d.x);
    EXPECT_LT(std::abs(totalForce(d)[0]), 1e-13 * 100 * 1e6);
}

TEST(MomentumProjection, MeanRemoval) {
    std::vector<double> g{1, 2, 3, 4}, V{1, 1, 2, 0.5};
    MomentumProjection<3>::mean(g, V);
    double s = 0;
    for (std::size_t i = 0; i < g.size(); ++i) s += V[i] * g[i];
    EXPECT_NEAR(s, 0.0, 1e-14);
    EXPECT_NEAR(g[1] - g[0], 1.0, 1e-15);
}

// The J dissipation's mean is removed over the particles it acts on: the clamped ones (skip 1)
// keep their value (0: D(J) is off there) and do not enter the mean (issue 16: the mean of the
// whole body moved the clamped particles' J off det F).
TEST(MomentumProjection, MeanRemovalOverTheUnskippedParticlesOnly) {
    std::vector<double> g{1, 2, 0, 4}, V{1, 1, 2, 0.5};
    const std::vector<char> skip{0, 0, 1, 0};
    MomentumProjection<3>::mean(g, V, skip);
    EXPECT_EQ(g[2], 0.0);  // untouched
    // sum over the unskipped V g = 0: mean (1 + 2 + 2) / 2.5 = 2 removed.
    EXPECT_NEAR(g[0], -1.0, 1e-15);
    EXPECT_NEAR(g[1], 0.0, 1e-15);
    EXPECT_NEAR(g[3], 2.0, 1e-15);
    std::vector<double> h{1, 2, 3, 4}, all{1, 2, 3, 4};
    MomentumProjection<3>::mean(h, V, {});  // no mask: the plain mean removal
    MomentumProjection<3>::mean(all, V);
    EXPECT_EQ(h, all);
}

}  // namespace
}  // namespace mfdyn
