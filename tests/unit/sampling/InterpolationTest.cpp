// Interpolation from particles to points: first-order MLS reproduces linear fields to
// round-off; Shepard is exact for constants and, for a linear field, off by grad f . (the
// offset of the weighted neighbour centroid from the point), which vanishes on a symmetric
// lattice and stays a small fraction of the jitter on a jittered one.
#include "functionObjects/Interpolation.hpp"
#include "particles/ParticleSet.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>

using namespace mfdyn;

namespace {

// f = 1 + 2x - 3y (+ 0.5z in 3D).
double linear(const SamplePoint& x, int dim) {
    return 1.0 + 2.0 * x[0] - 3.0 * x[1] + (dim == 3 ? 0.5 * x[2] : 0.0);
}

// n^Dim particles on [0, 1]^Dim, spacing dx = 1/(n-1), each moved by up to `jitter` dx per axis
// (uniform, fixed seed), carrying the linear field `f`.
template <int Dim>
ParticleSet<Dim> jitteredLattice(int n, double jitter) {
    std::size_t total = 1;
    for (int d = 0; d < Dim; ++d) total *= n;
    ParticleSet<Dim> p(total);
    std::mt19937 random(12345);
    std::uniform_real_distribution<double> offset(-jitter, jitter);
    const double dx = 1.0 / (n - 1);
    auto& x = p.position();
    auto& f = p.scalarField("f");
    for (std::size_t i = 0; i < total; ++i) {
        std::size_t rest = i;
        SamplePoint y{0, 0, 0};
        for (int d = 0; d < Dim; ++d) {
            y[d] = (double(rest % n) + offset(random)) * dx;
            x[i](d) = y[d];
            rest /= n;
        }
        f[i] = linear(y, Dim);
    }
    return p;
}

// Random points of [lo, hi]^Dim.
std::vector<SamplePoint> randomPoints(int dim, std::size_t count, double lo, double hi) {
    std::mt19937 random(777);
    std::uniform_real_distribution<double> u(lo, hi);
    std::vector<SamplePoint> points(count, SamplePoint{0, 0, 0});
    for (auto& x : points)
        for (int d = 0; d < dim; ++d) x[d] = u(random);
    return points;
}

Dictionary dictionary(const std::string& text) {
    return Dictionary::parse(text, "test");
}

// Largest |interpolated - exact| of the linear field over `points`, all of which must be ok.
double maxError(const Interpolation& interpolation, const FieldBase& f,
                const std::vector<SamplePoint>& points, int dim) {
    const auto stencils = interpolation.stencils(points);
    const auto values = Interpolation::apply(stencils, f);
    double worst = 0.0;
    for (std::size_t p = 0; p < points.size(); ++p) {
        EXPECT_EQ(stencils[p].status, Interpolation::Status::ok) << "point " << p;
        worst = std::max(worst, std::abs(values[p][0] - linear(points[p], dim)));
    }
    return worst;
}

template <int Dim>
void checkLinear(int n, const std::string& method, double tolerance) {
    // Jitter of 0.1 dx; h = 1.3 dx, so the Wendland C2 support 2h = 2.6 dx holds ~20 neighbours
    // in 2D and ~70 in 3D.
    const auto particles = jitteredLattice<Dim>(n, 0.1);
    const double dx = 1.0 / (n - 1), h = 1.3 * dx;
    const Interpolation interpolation(
        dictionary("interpolation " + method + "; kernel { type wendlandC2; } h " + std::to_string(h) + ";"),
        particles);
    // Interior: one support radius plus the jitter away from the boundary, where the
    // neighbourhood is complete.
    const double margin = 2.0 * h + 0.1 * dx;
    const auto points = randomPoints(Dim, 200, margin, 1.0 - margin);
    // The field's scale: max |f| on the unit cube is |1 - 3| = 2 ... |1 + 2 + 0.5| = 3.5.
    const double scale = Dim == 3 ? 3.5 : 3.0;
    const double error = maxError(interpolation, particles.field("f"), points, Dim) / scale;
    std::printf("%dD %s, n = %d: max relative error %.3g\n", Dim, method.c_str(), n, error);
    EXPECT_LT(error, tolerance);
}

}  // namespace

// MLS: a + b.(x_j - x) fits a linear field exactly, so only round-off remains: the solve of
// a 3x3 (4x4) system with O(1) entries and sums of ~20-70 terms of O(1), i.e. ~1e-14; 1e-10
// leaves room for the conditioning of a jittered neighbourhood.
TEST(Interpolation, mlsReproducesLinearField1D) {
    checkLinear<1>(101, "mls", 1e-10);
}
TEST(Interpolation, mlsReproducesLinearField2D) {
    checkLinear<2>(41, "mls", 1e-10);
}
TEST(Interpolation, mlsReproducesLinearField3D) {
    checkLinear<3>(21, "mls", 1e-10);
}

// Shepard: the error is grad f . sum_j phi_j (x_j - x), the offset of the weighted neighbour
// centroid from the point. It vanishes by symmetry on a regular lattice (and is O(h^2) on a
// smoothly deformed one); random jitter of 0.1 dx breaks the symmetry, leaving an offset of a
// fraction of 0.1 dx, so here the error falls like dx. Measured (max over 200 interior points,
// divided by max |f|): 2D 8.1e-4 at dx = 1/100, 3.7e-4 at 1/200; 3D 1.3e-3 at 1/40, 8.6e-4 at
// 1/60, 7.0e-4 at 1/80. The lattices below are fine enough to stay below 1e-3 with margin.
TEST(Interpolation, shepardLinearField2D) {
    checkLinear<2>(201, "shepard", 1e-3);
}
TEST(Interpolation, shepardLinearField3D) {
    checkLinear<3>(81, "shepard", 1e-3);
}

// Shepard is a weighted average: a constant is reproduced to round-off everywhere, boundary
// included.
TEST(Interpolation, shepardExactForConstants) {
    auto particles = jitteredLattice<2>(21, 0.1);
    auto& c = particles.scalarField("c");
    std::fill(c.begin(), c.end(), 4.25);
    const Interpolation interpolation(dictionary("interpolation shepard; h 0.065;"), particles);
    const auto points = randomPoints(2, 100, 0.0, 1.0);
    const auto values = Interpolation::apply(interpolation.stencils(points), particles.field("c"));
    for (const auto& v : values) EXPECT_NEAR(v[0], 4.25, 1e-14);
}

// Vector fields: each component is interpolated with the same weights.
TEST(Interpolation, vectorComponents) {
    auto particles = jitteredLattice<2>(21, 0.1);
    auto& u = particles.vectorField("velocity");
    for (std::size_t i = 0; i < particles.size(); ++i)
        u[i] = Vector<2>(particles.position()[i](0), -2.0 * particles.position()[i](1));
    const Interpolation interpolation(dictionary("interpolation mls; h 0.065;"), particles);
    const auto values =
        Interpolation::apply(interpolation.stencils({{0.5, 0.4, 0.0}}), particles.field("velocity"));
    ASSERT_EQ(values[0].size(), 2u);
    EXPECT_NEAR(values[0][0], 0.5, 1e-12);
    EXPECT_NEAR(values[0][1], -0.8, 1e-12);
}

// Far from every particle: NaN and flagged.
TEST(Interpolation, noNeighboursGivesNaN) {
    const auto particles = jitteredLattice<2>(11, 0.1);
    const Interpolation interpolation(dictionary("interpolation mls; h 0.1;"), particles);
    const auto stencils = interpolation.stencils({{5.0, 5.0, 0.0}, {-0.5, 0.5, 0.0}});
    const auto values = Interpolation::apply(stencils, particles.field("f"));
    for (std::size_t p = 0; p < 2; ++p) {
        EXPECT_EQ(stencils[p].status, Interpolation::Status::noNeighbours);
        EXPECT_TRUE(std::isnan(values[p][0]));
    }
}

// MLS where the neighbours cannot fix a plane (one particle in reach) falls back to Shepard.
TEST(Interpolation, mlsFallsBackWhereUndetermined) {
    ParticleSet<2> particles(2);
    particles.position()[0] = Vector<2>(0.0, 0.0);
    particles.position()[1] = Vector<2>(10.0, 0.0);
    particles.scalarField("f") = {3.0, 7.0};
    const Interpolation interpolation(dictionary("interpolation mls; h 0.5;"), particles);
    const auto stencils = interpolation.stencils({{0.1, 0.1, 0.0}});
    EXPECT_EQ(stencils[0].status, Interpolation::Status::shepardFallback);
    EXPECT_DOUBLE_EQ(Interpolation::apply(stencils, particles.field("f"))[0][0], 3.0);
}

// The smoothing length from the particles' field, volumes from mass/density.
TEST(Interpolation, smoothingLengthFieldAndVolumes) {
    auto particles = jitteredLattice<2>(21, 0.1);
    auto& h = particles.scalarField("smoothingLength");
    std::fill(h.begin(), h.end(), 0.065);
    auto& m = particles.scalarField("mass");
    auto& rho = particles.scalarField("density");
    for (std::size_t i = 0; i < particles.size(); ++i) m[i] = 1.0 + 0.01 * double(i % 7), rho[i] = 1000.0;
    const Interpolation interpolation(dictionary("interpolation mls;"), particles);
    const auto values = Interpolation::apply(interpolation.stencils({{0.5, 0.5, 0.0}}), particles.field("f"));
    EXPECT_NEAR(values[0][0], 1.0 + 1.0 - 1.5, 1e-12);
}

TEST(Interpolation, errors) {
    const auto particles = jitteredLattice<2>(5, 0.0);
    EXPECT_THROW(Interpolation(dictionary("interpolation linear; h 0.1;"), particles), InputError);
    EXPECT_THROW(Interpolation(dictionary("interpolation mls;"), particles), InputError);  // no h anywhere
}

// MLS at the boundary and beyond it (one-sided neighbourhoods), with a smoothing length that
// varies by a factor 1.5 across the particles (scatter form: each particle's own h): still exact
// for a linear field, and the weights are a partition of unity. The linear fit of the shared
// LeastSquaresOperators (value form) is what makes this hold wherever the neighbours span the plane.
TEST(Interpolation, mlsExactAtTheBoundaryWithVariableSmoothingLength) {
    auto particles = jitteredLattice<2>(21, 0.1);
    auto& h = particles.scalarField("smoothingLength");
    for (std::size_t i = 0; i < particles.size(); ++i)
        h[i] = 0.065 * (1.0 + 0.5 * particles.position()[i](0));
    const Interpolation interpolation(dictionary("interpolation mls;"), particles);
    // Points within a quarter spacing of the edges, outside included, and the corners.
    std::vector<SamplePoint> points = randomPoints(2, 100, -0.0125, 1.0125);
    for (auto& x : points)
        x[std::size_t(&x - points.data()) % 2] = (&x - points.data()) % 4 < 2 ? -0.01 : 1.01;
    points.push_back({-0.01, -0.01, 0.0});
    points.push_back({1.01, 1.01, 0.0});
    const double error = maxError(interpolation, particles.field("f"), points, 2) / 3.0;
    std::printf("2D mls at the boundary, variable h: max relative error %.3g\n", error);
    EXPECT_LT(error, 1e-10);
    for (const auto& s : interpolation.stencils(points)) {
        double sum = 0.0;
        for (double w : s.weights) sum += w;
        EXPECT_NEAR(sum, 1.0, 1e-12);
    }
}
