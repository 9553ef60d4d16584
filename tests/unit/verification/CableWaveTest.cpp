// The cable's d'Alembert solution (doc/methods/tl-jst-sph.md 8.1) against the figures of the note and its
// own wave equation: L = 10 m, c = 5000 m/s, v0 = 5 m/s on X <= 2.5 m.
#include "verification/CableWave.hpp"

#include <gtest/gtest.h>

#include <cmath>

using namespace mfdyn;

namespace {
CableWave paperCable() {
    return CableWave(10.0, 5000.0, 5.0, 2.5);
}
}  // namespace

TEST(CableWave, tipVelocityHistory) {
    const auto cable = paperCable();
    // +5 on (1.5, 2.0) ms, -5 on (2.0, 2.5) ms, 0 until -5 on (5.5, 6.0) and +5 on (6.0, 6.5) ms.
    for (double t : {1.55e-3, 1.75e-3, 1.95e-3}) EXPECT_DOUBLE_EQ(cable.velocity(10, t), 5.0) << t;
    for (double t : {2.05e-3, 2.25e-3, 2.45e-3}) EXPECT_DOUBLE_EQ(cable.velocity(10, t), -5.0) << t;
    for (double t : {0.0, 1.0e-3, 1.45e-3, 2.55e-3, 4.0e-3, 5.45e-3, 6.55e-3, 7.9e-3})
        EXPECT_DOUBLE_EQ(cable.velocity(10, t), 0.0) << t;
    for (double t : {5.55e-3, 5.95e-3}) EXPECT_DOUBLE_EQ(cable.velocity(10, t), -5.0) << t;
    for (double t : {6.05e-3, 6.45e-3}) EXPECT_DOUBLE_EQ(cable.velocity(10, t), 5.0) << t;
    EXPECT_DOUBLE_EQ(cable.period(), 8e-3);
    EXPECT_DOUBLE_EQ(cable.velocity(10, 1.75e-3 + 8e-3), 5.0);
}

TEST(CableWave, tipDisplacementPeaks) {
    const auto cable = paperCable();
    EXPECT_NEAR(cable.displacement(10, 2.0e-3), 2.5e-3, 1e-15);
    EXPECT_NEAR(cable.displacement(10, 6.0e-3), -2.5e-3, 1e-15);
    EXPECT_NEAR(cable.displacement(10, 1.5e-3), 0.0, 1e-15);
    EXPECT_NEAR(cable.displacement(10, 1.75e-3), 1.25e-3, 1e-15);  // the triangle's flank
    EXPECT_NEAR(cable.displacement(10, 4.0e-3), 0.0, 1e-15);
    // The peak is the largest value over a period.
    double largest = 0;
    for (int k = 0; k <= 800; ++k) largest = std::max(largest, std::abs(cable.displacement(10, k * 1e-5)));
    EXPECT_NEAR(largest, 2.5e-3, 1e-15);
}

// The closed-form displacement is the time integral of the velocity (midpoint rule, 20000 steps
// over 1.1 periods: the velocity is piecewise constant, so the error is about v0 dt per jump).
TEST(CableWave, displacementIsIntegralOfVelocity) {
    const auto cable = paperCable();
    for (double X : {0.0, 1.0, 2.5, 4.0, 7.3, 10.0}) {
        const int n = 20000;
        const double T = 1.1 * cable.period(), dt = T / n;
        double u = 0, worst = 0;
        for (int k = 0; k < n; ++k) {
            u += cable.velocity(X, (k + 0.5) * dt) * dt;
            worst = std::max(worst, std::abs(u - cable.displacement(X, (k + 1) * dt)));
        }
        EXPECT_LT(worst, 4 * 5.0 * dt) << "X = " << X;
    }
}

// Boundary conditions, the strain as du/dX and the bulk state behind the first fronts.
TEST(CableWave, boundaryConditionsAndStrain) {
    const auto cable = paperCable();
    for (int k = 0; k < 200; ++k) {
        const double t = k * 5.3e-5;
        EXPECT_EQ(cable.displacement(0, t), 0.0) << t;
        EXPECT_EQ(cable.velocity(0, t), 0.0) << t;
        EXPECT_EQ(cable.strain(10, t), 0.0) << t;
        for (double X : {1.1, 3.7, 6.2, 8.9}) {
            const double h = 1e-6;
            const double fd = (cable.displacement(X + h, t) - cable.displacement(X - h, t)) / (2 * h);
            // Away from the fronts (where the strain jumps) the difference is exact to round-off.
            if (std::abs(cable.strain(X + h, t) - cable.strain(X - h, t)) == 0) {
                EXPECT_NEAR(fd, cable.strain(X, t), 1e-9) << X << " " << t;
            }
        }
    }
    // At t = 0.2 ms the fronts have moved 1 m: X in (2.5, 3.5) carries v0/2 and strain -v0/(2c)
    // (compression ahead of the right-going half).
    EXPECT_DOUBLE_EQ(cable.velocity(3.0, 0.2e-3), 2.5);
    EXPECT_DOUBLE_EQ(cable.strain(3.0, 0.2e-3), -5.0 / (2 * 5000.0));
    // X < 1 m: the half reflected at the fixed end has stopped the cable and stretched it by v0/c.
    EXPECT_DOUBLE_EQ(cable.velocity(0.5, 0.2e-3), 0.0);
    EXPECT_DOUBLE_EQ(cable.strain(0.5, 0.2e-3), 5.0 / 5000.0);
}

TEST(CableWave, rejectsBadParameters) {
    EXPECT_THROW(CableWave(10, 5000, 5, 11), std::exception);
    EXPECT_THROW(CableWave(10, 0, 5, 2.5), std::exception);
}
