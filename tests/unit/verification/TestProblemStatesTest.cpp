// The analytic initial states of the test problems, kept with the references (issue 15): the
// twisting column's velocity (Lee et al. 2016 8.9) and the cantilever's first bending mode (Gray,
// Monaghan & Swift 2001), checked against their formulas and their boundary values.
#include "core/Error.hpp"
#include "verification/CantileverModeShape.hpp"
#include "verification/TwistingColumnMotion.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

using namespace mfdyn;

TEST(TwistingColumnMotion, twistGrowsFromTheBaseToOmegaAtTheTop) {
    const TwistingColumnMotion twist(105, 6, 1, Vector<3>::Zero());
    // top, s = L: omega = (0, 105, 0), v = omega x X = (0, 0, -52.5) at X = (0.5, 6, 0)
    EXPECT_TRUE(twist.velocity(Vector<3>(0.5, 6.0, 0.0)).isApprox(Vector<3>(0, 0, -52.5), 1e-15));
    // s = L/2: omega = 105 sin(pi/4)
    const double w = 105 * std::sin(std::numbers::pi / 4);
    EXPECT_TRUE(twist.velocity(Vector<3>(0.0, 3.0, 0.5)).isApprox(Vector<3>(w * 0.5, 0, 0), 1e-15));
    EXPECT_EQ(twist.velocity(Vector<3>(0.5, 0, 0.5)), Vector<3>::Zero());  // the clamped base
    // A twist about its axis: v is normal to the axis and to the radius everywhere.
    const Vector<3> X(0.3, 4.1, -0.2);
    const Vector<3> v = twist.velocity(X);
    EXPECT_EQ(v(1), 0.0);
    EXPECT_NEAR(v(0) * X(0) + v(2) * X(2), 0.0, 1e-13);
}

TEST(TwistingColumnMotion, otherAxisAndCentre) {
    // Axis Z about c = (1, 1, 0): at s = L the top turns at Omega about the line through c.
    const TwistingColumnMotion twist(2.0, 4.0, 2, Vector<3>(1, 1, 0));
    EXPECT_TRUE(twist.velocity(Vector<3>(2, 1, 4)).isApprox(Vector<3>(0, 2.0, 0), 1e-15));
    EXPECT_THROW(TwistingColumnMotion(1, 0, 1, Vector<3>::Zero()), Error);
    EXPECT_THROW(TwistingColumnMotion(1, 1, 3, Vector<3>::Zero()), Error);
}

TEST(CantileverModeShape, clampedAtZeroTipVelocityAtTheFreeEnd) {
    const double L = 0.2, V = 0.05, kL = 1.875;
    const CantileverModeShape mode(L, V, kL);
    EXPECT_NEAR(mode.transverseVelocity(L), V, 1e-15);
    EXPECT_EQ(mode.transverseVelocity(0.0), 0.0);
    EXPECT_EQ(mode.transverseVelocity(-0.01), 0.0);  // inside the clamp
    // f(L) = 2 (cos kL sinh kL - sin kL cosh kL), the normalisation PySPH writes out
    EXPECT_NEAR(mode.shape(L), 2 * (std::cos(kL) * std::sinh(kL) - std::sin(kL) * std::cosh(kL)),
                1e-13 * std::abs(mode.shape(L)));
    // zero slope at the clamp: f ~ s^2 there
    EXPECT_LT(std::abs(mode.transverseVelocity(1e-4)), V * 1e-5);
    // kL = 1.875 is near the first root of 1 + cos kL cosh kL = 0 (1.8751): the free end carries
    // no moment, f''(L) ~ 0 relative to f''(0)
    const double h = 1e-4;
    const double f2L = (mode.shape(L) - 2 * mode.shape(L - h) + mode.shape(L - 2 * h)) / (h * h);
    const double f20 = (mode.shape(2 * h) - 2 * mode.shape(h) + mode.shape(0)) / (h * h);
    EXPECT_LT(std::abs(f2L), 2e-3 * std::abs(f20));
    EXPECT_THROW(CantileverModeShape(0, V), Error);
    EXPECT_THROW(CantileverModeShape(L, V, 0), Error);
    EXPECT_THROW(CantileverModeShape(L, std::nan("")), Error);
}
