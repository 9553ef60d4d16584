// The isothermal shock-bar of doc/methods/sph-impact.md 8.2 against the note's [C] profile at t = 0.4
// (5 significant digits printed: checked to half a unit in the last digit).
#include <gtest/gtest.h>

#include <cmath>

#include "core/Error.hpp"
#include "verification/IsothermalShockBar.hpp"

namespace mfdyn {
namespace {

constexpr double half5 = 0.5e-5;

TEST(IsothermalShockBar, wavesMatchNote) {
    const auto bar = IsothermalShockBar::zisis2017();
    EXPECT_NEAR(bar.impact().starPressure(), 0.64039, half5);
    EXPECT_NEAR(bar.transmissionTime(), 0.15616, half5);
    const auto& rs = bar.transmission();
    ASSERT_EQ(rs.leftWave().kind, RiemannSolver::WaveKind::rarefaction);
    ASSERT_EQ(rs.rightWave().kind, RiemannSolver::WaveKind::shock);
    EXPECT_NEAR(rs.leftWave().headSpeed, -0.5, 1e-12);
    EXPECT_NEAR(rs.leftWave().tailSpeed, -0.19562, half5);
    EXPECT_NEAR(rs.starPressure(), 0.20992, half5);
    EXPECT_NEAR(rs.starVelocity(), 0.80438, half5);
    EXPECT_NEAR(rs.starDensityLeft(), 1.20992, half5);
    EXPECT_NEAR(rs.starDensityRight(), 1.08967, half5);
    EXPECT_NEAR(rs.rightWave().headSpeed, 1.04387, half5);
    // The transmitted shock reaches x = 1.2 at t = 0.5393 (4 digits printed), ending the construction.
    EXPECT_NEAR(bar.validUntil(), 0.5393, 0.5e-4);
}

TEST(IsothermalShockBar, profileAtT04) {
    const auto bar = IsothermalShockBar::zisis2017();
    const double t = 0.4, t1 = bar.transmissionTime();
    // Fronts printed by the note, each computed from the wave speeds.
    const double leftShock = 0.6 + bar.impact().leftWave().headSpeed * t;
    const double fanHead = 0.8 + bar.transmission().leftWave().headSpeed * (t - t1);
    const double fanTail = 0.8 + bar.transmission().leftWave().tailSpeed * (t - t1);
    const double interface = 0.8 + bar.transmission().contactSpeed() * (t - t1);
    const double rightShock = 0.8 + bar.transmission().rightWave().headSpeed * (t - t1);
    EXPECT_NEAR(leftShock, 0.48769, half5);
    EXPECT_NEAR(fanHead, 0.67808, half5);
    EXPECT_NEAR(fanTail, 0.75230, half5);
    EXPECT_NEAR(interface, 0.99614, half5);
    EXPECT_NEAR(rightShock, 1.05454, half5);

    auto expectState = [&](double x, double rho, double v, double p) {
        const auto s = bar.state(x, t);
        EXPECT_NEAR(s.density, rho, half5) << "x = " << x;
        EXPECT_NEAR(s.velocity, v, half5) << "x = " << x;
        EXPECT_NEAR(s.pressure, p, half5) << "x = " << x;
    };
    const double eps = 1e-9;
    expectState(0.3, 1.0, 1.0, 0.0);
    expectState(leftShock - eps, 1.0, 1.0, 0.0);
    expectState(leftShock + eps, 1.64039, 0.5, 0.64039);
    expectState(0.6, 1.64039, 0.5, 0.64039);  // the trivial contact between bars 1 and 2
    expectState(fanHead - eps, 1.64039, 0.5, 0.64039);
    expectState(fanTail + eps, 1.20992, 0.80438, 0.20992);
    expectState(interface - eps, 1.20992, 0.80438, 0.20992);
    expectState(interface + eps, 1.08967, 0.80438, 0.20992);
    expectState(rightShock - eps, 1.08967, 0.80438, 0.20992);
    expectState(rightShock + eps, 0.25, 0.0, 0.0);
    expectState(1.3, 1.0, 0.0, 0.0);
    // In the fan: v = 1 + (x - 0.8)/(t - 0.15616), rho = 1.64039 exp(-(v - 0.5)), P = rho - 1.
    for (double x = fanHead + 0.005; x < fanTail; x += 0.01) {
        const double v = 1.0 + (x - 0.8) / (t - 0.15616);
        const double rho = 1.64039 * std::exp(-(v - 0.5));
        const auto s = bar.state(x, t);
        EXPECT_NEAR(s.velocity, v, 1e-4) << "x = " << x;  // 0.15616 is rounded: 1e-5 in t, /0.24
        EXPECT_NEAR(s.density, rho, 1e-4) << "x = " << x;
        EXPECT_NEAR(s.pressure, s.density - 1.0, 1e-14);
        // Exactly: the fan's own characteristic v - c0 = (x - 0.8)/(t - t1), and the invariant.
        EXPECT_NEAR(s.velocity - 1.0, (x - 0.8) / (t - t1), 1e-12);
        EXPECT_NEAR(s.velocity + std::log(s.density), 0.5 + std::log(bar.impact().starDensityRight()), 1e-12);
    }
}

TEST(IsothermalShockBar, beforeTransmissionAndLimits) {
    const auto bar = IsothermalShockBar::zisis2017();
    // At t = 0.1 the impact's right shock is at 0.6 + 0.128078 < 0.8; bar 3 is undisturbed.
    EXPECT_NEAR(bar.state(0.72, 0.1).density, 1.64039, half5);
    EXPECT_NEAR(bar.state(0.75, 0.1).density, 1.0, 1e-14);
    EXPECT_NEAR(bar.state(0.9, 0.1).density, 0.25, 1e-14);
    EXPECT_NEAR(bar.state(0.5, 0.0).velocity, 1.0, 1e-14);
    EXPECT_THROW(bar.state(0.5, 0.6), Error);
    EXPECT_THROW(bar.state(0.5, -1.0), Error);
    // A nontrivial contact between bars 1 and 2 (different materials) is rejected.
    const auto m1 = RiemannEquationOfState::linearBarotropic(1.0, 1.0);
    const auto m2 = RiemannEquationOfState::linearBarotropic(0.25, 0.5);
    EXPECT_THROW(IsothermalShockBar(0.6, 0.8, 1.2, {{1.0, 1.0, 0.0}, m1}, {{0.25, 0.0, 0.0}, m2},
                                    {{1.0, 0.0, 0.0}, m1}, {{1.0, 0.0, 0.0}, m1}),
                 Error);
}

}  // namespace
}  // namespace mfdyn
