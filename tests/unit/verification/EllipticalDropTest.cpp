// The elliptical drop ODE of doc/methods/sph-impact.md 8.1 against the note's [C] values (5 digits printed).
#include <gtest/gtest.h>

#include "core/Error.hpp"
#include "verification/EllipticalDrop.hpp"

namespace mfdyn {
namespace {

TEST(EllipticalDrop, semiAxesMatchNote) {
    const EllipticalDrop drop(100.0);
    const auto s1 = drop.state(0.0076);
    EXPECT_NEAR(s1.b, 1.9445, 0.5e-4);
    EXPECT_NEAR(s1.A, 70.31, 0.5e-2);
    EXPECT_NEAR(s1.a * s1.b, 1.0, 1e-10);
    const auto s2 = drop.state(0.01);
    EXPECT_NEAR(s2.b, 2.2755, 0.5e-4);
    EXPECT_NEAR(s2.a * s2.b, 1.0, 1e-10);
}

// RK4 at the default step is converged: halving the step changes b by < 1e-12.
TEST(EllipticalDrop, converged) {
    const double coarse = EllipticalDrop(100.0).state(0.01).b;
    const double fine = EllipticalDrop(100.0, 2e4).state(0.01).b;
    EXPECT_NEAR(coarse, fine, 1e-12);
}

TEST(EllipticalDrop, velocityField) {
    const EllipticalDrop drop(100.0);
    const auto v0 = drop.velocity(0.5, -0.25, 0.0);
    EXPECT_DOUBLE_EQ(v0[0], -50.0);
    EXPECT_DOUBLE_EQ(v0[1], -25.0);
    // v = (a'/a x, b'/b y): a point on the boundary stays on it; check by a finite difference of b.
    const double t = 0.005, h = 1e-7;
    const double bDot = (drop.state(t + h).b - drop.state(t - h).b) / (2.0 * h);
    const auto s = drop.state(t);
    EXPECT_NEAR(drop.velocity(0.0, s.b, t)[1], bDot, 1e-6 * bDot);
    EXPECT_TRUE(drop.inside(0.0, 0.999 * s.b, t));
    EXPECT_FALSE(drop.inside(0.0, 1.001 * s.b, t));
    EXPECT_THROW(drop.state(-1.0), Error);
}

}  // namespace
}  // namespace mfdyn
