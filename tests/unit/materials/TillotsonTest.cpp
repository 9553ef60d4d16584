// Tillotson closed forms and continuity: the cold compression curve, the expanded branch by hand,
// the blend, and continuity of P across e = Eiv, e = Ecv and rho = rho0.
#include "EquationOfStateTestTools.hpp"
#include "materials/equationOfState/Tillotson.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace mfdyn {
namespace {

// Aluminium, Tillotson 1962 as tabulated by Melosh 1989 Table AII.3 (etc/materials/tillotsonAluminium).
constexpr double rho0 = 2700.0, A = 75.2e9, B = 65e9, a = 0.5, b = 1.63, alpha = 5.0, beta = 5.0, E0 = 5e6,
                 Eiv = 3e6, Ecv = 13.9e6;
const std::string al =
    "type tillotson; rho0 2700; A 75.2e9; B 65e9; a 0.5; b 1.63; alpha 5; beta 5; E0 5e6; Eiv 3e6; Ecv "
    "13.9e6;";

std::unique_ptr<Tillotson> makeTillotson() {
    auto eos = test::makeEos(al);
    return std::unique_ptr<Tillotson>(dynamic_cast<Tillotson*>(eos.release()));
}

// Both branches written out again from Melosh 1989 AII.1-AII.2, for comparison.
double compressedByHand(double rho, double e) {
    const double eta = rho / rho0, mu = eta - 1, omega = e / (E0 * eta * eta) + 1;
    return (a + b / omega) * rho * e + A * mu + B * mu * mu;
}
double expandedByHand(double rho, double e) {
    const double eta = rho / rho0, mu = eta - 1, x = rho0 / rho - 1, omega = e / (E0 * eta * eta) + 1;
    return a * rho * e + (b * rho * e / omega + A * mu * std::exp(-beta * x)) * std::exp(-alpha * x * x);
}

TEST(Tillotson, BranchesMatchThePublishedFormulas) {
    const auto eos = makeTillotson();
    ASSERT_TRUE(eos);
    // Cold compression: P = A mu + B mu^2.
    EXPECT_NEAR(eos->pressure(1.1 * rho0, 0.0), A * 0.1 + B * 0.01, 1e-12 * A);
    for (auto [rho, e] : {std::pair{3000.0, 2e6}, {2500.0, 1e6}, {3500.0, 2e7}})  // compressed region
        EXPECT_NEAR(eos->pressure(rho, e), compressedByHand(rho, e), 1e-12 * A) << rho << " " << e;
    for (auto [rho, e] : {std::pair{2000.0, 2e7}, {1000.0, 5e7}, {2600.0, 1.4e7}})  // expanded region
        EXPECT_NEAR(eos->pressure(rho, e), expandedByHand(rho, e), 1e-12 * A) << rho << " " << e;
    // The blend at a quarter of the way from Eiv to Ecv.
    const double rho = 2400.0, e = Eiv + 0.25 * (Ecv - Eiv);
    EXPECT_NEAR(eos->pressure(rho, e), 0.25 * expandedByHand(rho, e) + 0.75 * compressedByHand(rho, e),
                1e-12 * A);
}

TEST(Tillotson, PressureIsContinuousAcrossTheBranchLines) {
    const auto eos = makeTillotson();
    // A step of 1e-9 relative across each line: P is continuous, so the jump is the step times the
    // derivative, |dP/dx| dx <~ (A + rho0 e) 1e-9 relative to A; a jump of a branch mismatch would
    // be O(0.1 A). Tolerance 1e-7 A.
    const double d = 1e-9;
    for (double rho : {2000.0, 2400.0, 2650.0}) {
        EXPECT_NEAR(eos->pressure(rho, Eiv * (1 - d)), eos->pressure(rho, Eiv * (1 + d)), 1e-7 * A) << rho;
        EXPECT_NEAR(eos->pressure(rho, Ecv * (1 - d)), eos->pressure(rho, Ecv * (1 + d)), 1e-7 * A) << rho;
    }
    for (double e : {1e6, 5e6, 2e7})
        EXPECT_NEAR(eos->pressure(rho0 * (1 - d), e), eos->pressure(rho0 * (1 + d), e), 1e-7 * A) << e;
    // On the lines themselves the branches agree exactly up to rounding.
    double pc, pe, dummy1, dummy2;
    for (double e : {1e6, 5e6, 2e7}) {
        eos->compressed(rho0, e, pc, dummy1, dummy2);
        eos->expanded(rho0, e, pe, dummy1, dummy2);
        EXPECT_NEAR(pc, pe, 1e-13 * A) << e;
    }
}

TEST(Tillotson, EcvMustExceedEiv) {
    EXPECT_THROW(test::makeEos("type tillotson; rho0 2700; A 75.2e9; B 65e9; a 0.5; b 1.63; alpha 5; beta 5; "
                               "E0 5e6; Eiv 3e6; Ecv 2e6;"),
                 InputError);
}

}  // namespace
}  // namespace mfdyn
