// Exact Riemann solutions against the [C] values of doc/methods/sph-impact.md 8.3-8.4 (Zisis 2017, computed
// for the note by bisection to 1e-12). The note prints 5 significant digits (4 decimals for wave
// positions), so each value is checked to half a unit in its last printed digit.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "core/Error.hpp"
#include "verification/RiemannSolver.hpp"
#include "verification/ShockTubeSolution.hpp"

namespace mfdyn {
namespace {

// The note's value as printed: the tolerance is half a unit in its last printed decimal.
void expectPrinted(double computed, const char* printed) {
    const std::string text(printed);
    const auto dot = text.find('.');
    const int decimals = dot == std::string::npos ? 0 : int(text.size() - dot - 1);
    EXPECT_NEAR(computed, std::stod(text), 0.5 * std::pow(10.0, -decimals) + 1e-14)
        << "note prints " << printed;
}

ShockTubeSolution sod(double gamma) {
    const auto gas = RiemannEquationOfState::idealGas(gamma);
    return ShockTubeSolution(0.5, {1.0, 0.0, 1.0}, gas, {0.125, 0.0, 0.1}, gas);
}

TEST(RiemannSolver, sodGamma14) {
    const auto tube = sod(1.4);
    const auto& rs = tube.solver();
    expectPrinted(rs.starPressure(), "0.30313");
    expectPrinted(rs.starVelocity(), "0.92745");
    expectPrinted(rs.starDensityLeft(), "0.42632");
    expectPrinted(rs.starDensityRight(), "0.26557");
    EXPECT_EQ(rs.leftWave().kind, RiemannSolver::WaveKind::rarefaction);
    EXPECT_EQ(rs.rightWave().kind, RiemannSolver::WaveKind::shock);
    const auto w = tube.wavePositions(0.2);
    expectPrinted(w.leftHead, "0.2634");
    // The note prints 0.4860; the exact tail is 0.5 + 0.2 (u* - c*L) = 0.485945, which rounds to
    // 0.4859 (the note's digit comes from rounding twice). Checked to one unit in the 4th decimal.
    EXPECT_NEAR(w.leftTail, 0.4860, 1e-4);
    expectPrinted(w.leftTail, "0.48595");
    expectPrinted(w.contact, "0.6855");
    expectPrinted(w.rightHead, "0.8504");
}

TEST(RiemannSolver, sodGamma53) {
    const auto tube = sod(5.0 / 3.0);
    const auto& rs = tube.solver();
    expectPrinted(rs.starPressure(), "0.29395");
    expectPrinted(rs.starVelocity(), "0.84119");
    expectPrinted(rs.starDensityLeft(), "0.47969");
    expectPrinted(rs.starDensityRight(), "0.22981");
    const auto w = tube.wavePositions(0.2);
    expectPrinted(w.leftHead, "0.2418");
    expectPrinted(w.leftTail, "0.4661");
    expectPrinted(w.contact, "0.6682");
    expectPrinted(w.rightHead, "0.8689");
}

// Toro 2009 Table 4.3, test 1 is Sod with u = 0 (also rho*L = 0.42632): the fan is continuous at
// both edges and obeys the isentrope P/rho^gamma = const, and sampled states match the star values.
TEST(RiemannSolver, sodProfileIsConsistent) {
    const auto tube = sod(1.4);
    const auto& rs = tube.solver();
    const auto w = tube.wavePositions(0.2);
    const double eps = 1e-12;
    const auto head = tube.state(w.leftHead + eps, 0.2), tail = tube.state(w.leftTail - eps, 0.2);
    EXPECT_NEAR(head.density, 1.0, 1e-10);
    EXPECT_NEAR(tail.density, rs.starDensityLeft(), 1e-10);
    EXPECT_NEAR(tail.pressure, rs.starPressure(), 1e-10);
    for (double x = w.leftHead; x < w.leftTail; x += 0.01) {
        const auto s = tube.state(x, 0.2);
        EXPECT_NEAR(s.pressure / std::pow(s.density, 1.4), 1.0, 1e-12);
        EXPECT_NEAR(s.velocity - std::sqrt(1.4 * s.pressure / s.density), (x - 0.5) / 0.2, 1e-12);
    }
    const auto star = tube.state(0.6, 0.2);
    EXPECT_NEAR(star.internalEnergy, rs.starPressure() / (0.4 * rs.starDensityLeft()), 1e-14);
    EXPECT_DOUBLE_EQ(tube.state(0.9, 0.2).density, 0.125);
    EXPECT_DOUBLE_EQ(tube.state(0.1, 0.2).pressure, 1.0);
}

// 8.3, three rows: [0, 0.5) rho = rho0 = c0 = 1, v = 1; [0.5, 1] rho = rho0R, c0R, at rest.
struct AsymmetricRow {
    double rho0R, c0R;
    const char *pStar, *vStar, *rhoL, *rhoR, *sL, *sR, *xL, *xC, *xR;
};

class AsymmetricImpact : public ::testing::TestWithParam<AsymmetricRow> {};

TEST_P(AsymmetricImpact, matchesNote) {
    const auto row = GetParam();
    const auto leftEos = RiemannEquationOfState::linearBarotropic(1.0, 1.0);
    const auto rightEos = RiemannEquationOfState::linearBarotropic(row.rho0R, row.c0R);
    const ShockTubeSolution tube(0.5, {1.0, 1.0, 0.0}, leftEos, {row.rho0R, 0.0, 0.0}, rightEos);
    const auto& rs = tube.solver();
    expectPrinted(rs.starPressure(), row.pStar);
    expectPrinted(rs.starVelocity(), row.vStar);
    expectPrinted(rs.starDensityLeft(), row.rhoL);
    expectPrinted(rs.starDensityRight(), row.rhoR);
    ASSERT_EQ(rs.leftWave().kind, RiemannSolver::WaveKind::shock);
    ASSERT_EQ(rs.rightWave().kind, RiemannSolver::WaveKind::shock);
    expectPrinted(rs.leftWave().headSpeed, row.sL);
    expectPrinted(rs.rightWave().headSpeed, row.sR);
    const auto w = tube.wavePositions(0.3);
    expectPrinted(w.leftHead, row.xL);
    expectPrinted(w.contact, row.xC);
    expectPrinted(w.rightHead, row.xR);
    // Barotropic materials have no energy equation: e is NaN by contract.
    EXPECT_TRUE(std::isnan(rs.starLeft().internalEnergy));
}

INSTANTIATE_TEST_SUITE_P(
    RiemannSolver, AsymmetricImpact,
    ::testing::Values(AsymmetricRow{0.25, 0.5, "0.21142", "0.80791", "1.21142", "1.09568", "-0.10065",
                                    "1.04675", "0.4698", "0.7424", "0.8140"},
                      AsymmetricRow{0.5, 0.5, "0.34056", "0.70586", "1.34056", "1.86224", "-0.15783",
                                    "0.96494", "0.4527", "0.7118", "0.7895"},
                      AsymmetricRow{0.25, 0.25, "0.18623", "0.82901", "1.18623", "3.22969", "-0.08914",
                                    "0.89857", "0.4733", "0.7487", "0.7696"}));

// 8.2, first impact: {1, 1} against {1, 0}, rho0 = c0 = 1 on both sides.
TEST(RiemannSolver, isothermalShockBarFirstImpact) {
    const auto eos = RiemannEquationOfState::linearBarotropic(1.0, 1.0);
    const RiemannSolver rs({1.0, 1.0, 0.0}, eos, {1.0, 0.0, 0.0}, eos);
    expectPrinted(rs.starPressure(), "0.64039");
    EXPECT_NEAR(rs.starVelocity(), 0.5, 1e-12);  // symmetric impact
    expectPrinted(rs.starDensityLeft(), "1.64039");
    expectPrinted(rs.starDensityRight(), "1.64039");
    expectPrinted(rs.leftWave().headSpeed, "-0.28078");
    expectPrinted(rs.rightWave().headSpeed, "1.28078");
    // Closed form: P*^2 - P*/4 - 1/4 = 0 for this symmetric impact.
    EXPECT_NEAR(rs.starPressure(), (0.25 + std::sqrt(0.0625 + 1.0)) / 2.0, 1e-12);
}

// 8.4(c): liquid rho = 1, v = 0, P = 1, pRef = 0.6, gamma = 4.4 against gas rho = 0.05, P = 0.01,
// gamma = 1.4 (Table 5.1 rows 5-6: density ratio 1/20, pressure ratio 1/100 as the note states).
TEST(RiemannSolver, liquidGasStarState) {
    const ShockTubeSolution tube(0.0, {1.0, 0.0, 1.0}, RiemannEquationOfState::stiffenedGas(4.4, 0.6),
                                 {0.05, 0.0, 0.01}, RiemannEquationOfState::idealGas(1.4));
    const auto& rs = tube.solver();
    // The note prints P* = 0.030814; the root of f_L + f_R = 0 for these data is 0.0308104926
    // (this solver, and an independent 30-digit bisection), 1.1e-4 relative below the note, while
    // every other printed value of the row (u*, rho*, e*, speeds, all functions of P*) agrees to its
    // last digit. The note's 5th digit of P* is taken as a slip; the test checks the correct root
    // and that the note's value is within 1.2e-4 relative.
    EXPECT_NEAR(rs.starPressure(), 0.0308104926, 1e-10);
    EXPECT_NEAR(rs.starPressure(), 0.030814, 1.2e-4 * 0.030814);
    expectPrinted(rs.starVelocity(), "0.47143");
    expectPrinted(rs.starDensityLeft(), "0.80934");
    expectPrinted(rs.starDensityRight(), "0.10729");
    expectPrinted(rs.starLeft().internalEnergy, "0.9706");
    expectPrinted(rs.starRight().internalEnergy, "0.7179");
    EXPECT_EQ(rs.leftWave().kind, RiemannSolver::WaveKind::rarefaction);
    expectPrinted(rs.leftWave().headSpeed, "-2.6533");
    expectPrinted(rs.leftWave().tailSpeed, "-1.3804");
    expectPrinted(rs.contactSpeed(), "0.4714");
    expectPrinted(rs.rightWave().headSpeed, "0.8829");
}

// Toro 2009 Table 4.3 test 2 (the 123 problem) is near vacuum but not vacuum; doubling the
// velocities opens a vacuum (Toro 4.40: 2cL/(g-1) + 2cR/(g-1) = 7.48 < 8).
TEST(RiemannSolver, vacuumIsAnError) {
    const auto gas = RiemannEquationOfState::idealGas(1.4);
    const RiemannSolver nearVacuum({1.0, -2.0, 0.4}, gas, {1.0, 2.0, 0.4}, gas);
    EXPECT_NEAR(nearVacuum.starPressure(), 0.00189, 0.5e-5);  // Toro Table 4.3, test 2
    EXPECT_NEAR(nearVacuum.starVelocity(), 0.0, 1e-12);
    EXPECT_THROW(RiemannSolver({1.0, -4.0, 0.4}, gas, {1.0, 4.0, 0.4}, gas), Error);
    try {
        RiemannSolver({1.0, -4.0, 0.4}, gas, {1.0, 4.0, 0.4}, gas);
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("vacuum"), std::string::npos) << e.what();
    }
    // A barotropic pair never cavitates: it goes into tension instead.
    const auto water = RiemannEquationOfState::linearBarotropic(1.0, 1.0);
    const RiemannSolver tension({1.0, -1.0, 0.0}, water, {1.0, 1.0, 0.0}, water);
    EXPECT_LT(tension.starPressure(), 0.0);
    EXPECT_NEAR(tension.starDensityLeft(), std::exp(-1.0), 1e-12);  // v* + ln rho* = v_L + ln rho_L
}

// Toro 2009 Table 4.3 tests 3-5 (star pressure and velocity printed there to 5-6 digits).
TEST(RiemannSolver, toroTests) {
    const auto gas = RiemannEquationOfState::idealGas(1.4);
    const RiemannSolver t3({1.0, 0.0, 1000.0}, gas, {1.0, 0.0, 0.01}, gas);
    EXPECT_NEAR(t3.starPressure(), 460.894, 0.5e-3);
    EXPECT_NEAR(t3.starVelocity(), 19.5975, 0.5e-4);
    const RiemannSolver t5({5.99924, 19.5975, 460.894}, gas, {5.99242, -6.19633, 46.0950}, gas);
    // Test 5's inputs are test 3's star states rounded to 6 digits; Toro's table matches our root
    // to 5e-6 relative only (1691.6470, 8.689774 here, confirmed by a 30-digit bisection).
    EXPECT_NEAR(t5.starPressure(), 1691.64, 1e-5 * 1691.64);
    EXPECT_NEAR(t5.starVelocity(), 8.68975, 1e-5 * 8.68975);
}

TEST(RiemannSolver, inadmissibleStatesAreErrors) {
    const auto gas = RiemannEquationOfState::idealGas(1.4);
    EXPECT_THROW(RiemannSolver({-1.0, 0.0, 1.0}, gas, {1.0, 0.0, 1.0}, gas), Error);
    EXPECT_THROW(RiemannSolver({1.0, 0.0, -1.0}, gas, {1.0, 0.0, 1.0}, gas), Error);
    const auto water = RiemannEquationOfState::linearBarotropic(1.0, 2.0);
    // P must equal c0^2 (rho - rho0) = 0.4 at rho = 1.1.
    EXPECT_THROW(RiemannSolver({1.1, 0.0, 0.3}, water, {1.0, 0.0, 0.0}, water), Error);
    EXPECT_THROW(RiemannEquationOfState::idealGas(1.0), Error);
    EXPECT_THROW(RiemannEquationOfState::linearBarotropic(0.0, 1.0), Error);
}

// The exact solution conserves mass, momentum and energy: over [a, b], with no wave at a or b,
// int U(t) dx = int U(0) dx - t [F(U(b)) - F(U(a))]. Fans are integrated by Gauss-Legendre (exact
// for the polynomial gamma = 1.4 fan), so the balance holds to the 1e-12 relative tolerance of the
// star pressure; the tolerance allows 1e-11. This checks the star state and wave speeds together
// (Rankine-Hugoniot).
TEST(RiemannSolver, conservationSod) {
    const auto tube = sod(1.4);
    const double a = 0.0, b = 1.0, t = 0.2;
    const auto now = tube.integrate(a, b, t), then = tube.integrate(a, b, 0.0);
    const auto fa = tube.flux(tube.state(a, t)), fb = tube.flux(tube.state(b, t));
    EXPECT_NEAR(now.mass, then.mass - t * (fb.mass - fa.mass), 1e-12);
    EXPECT_NEAR(now.momentum, then.momentum - t * (fb.momentum - fa.momentum), 1e-12);
    EXPECT_NEAR(now.energy, then.energy - t * (fb.energy - fa.energy), 1e-11);
    EXPECT_NEAR(then.mass, 0.5625, 1e-14);
}

TEST(RiemannSolver, conservationLiquidGas) {
    const ShockTubeSolution tube(0.0, {1.0, 0.0, 1.0}, RiemannEquationOfState::stiffenedGas(4.4, 0.6),
                                 {0.05, 0.0, 0.01}, RiemannEquationOfState::idealGas(1.4));
    const double a = -3.0, b = 1.0, t = 1.0;
    const auto now = tube.integrate(a, b, t), then = tube.integrate(a, b, 0.0);
    const auto fa = tube.flux(tube.state(a, t)), fb = tube.flux(tube.state(b, t));
    // gamma = 4.4 makes the fan non-polynomial; 64 x 5-point Gauss still gives ~1e-13.
    EXPECT_NEAR(now.mass, then.mass - t * (fb.mass - fa.mass), 1e-11);
    EXPECT_NEAR(now.momentum, then.momentum - t * (fb.momentum - fa.momentum), 1e-11);
    EXPECT_NEAR(now.energy, then.energy - t * (fb.energy - fa.energy), 1e-11);
}

// Barotropic: mass and momentum only (no energy equation); a rarefaction and a shock together.
TEST(RiemannSolver, conservationBarotropic) {
    const ShockTubeSolution tube(0.0, {2.0, 0.0, 1.0}, RiemannEquationOfState::linearBarotropic(1.0, 1.0),
                                 {0.3, 0.0, 0.05}, RiemannEquationOfState::linearBarotropic(0.25, 1.0));
    ASSERT_EQ(tube.solver().leftWave().kind, RiemannSolver::WaveKind::rarefaction);
    ASSERT_EQ(tube.solver().rightWave().kind, RiemannSolver::WaveKind::shock);
    const double a = -2.0, b = 2.0, t = 0.8;
    const auto now = tube.integrate(a, b, t), then = tube.integrate(a, b, 0.0);
    const auto fa = tube.flux(tube.state(a, t)), fb = tube.flux(tube.state(b, t));
    EXPECT_NEAR(now.mass, then.mass - t * (fb.mass - fa.mass), 1e-12);
    EXPECT_NEAR(now.momentum, then.momentum - t * (fb.momentum - fa.momentum), 1e-12);
    EXPECT_TRUE(std::isnan(now.energy));
}

}  // namespace
}  // namespace mfdyn
