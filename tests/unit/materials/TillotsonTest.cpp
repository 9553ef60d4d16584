// Tillotson closed forms and continuity: the cold compression curve, the expanded branch by hand,
// the blend, and continuity of P across e = Eiv, e = Ecv and rho = rho0.
#include "EquationOfStateTestTools.hpp"
#include "materials/equationOfState/Tillotson.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <utility>
#include <vector>

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

// g = dP/de|_rho in closed form (Tillotson.cpp): rho (a + b/omega^2) on P_c, rho (a + G b/omega^2),
// G = exp(-alpha x^2), on P_e; the blend's carries (P_e - P_c)/(Ecv - Eiv).
TEST(Tillotson, EnergyDerivativeClosedForm) {
    const auto eos = makeTillotson();
    auto omega = [](double rho, double e) { return e / (E0 * (rho / rho0) * (rho / rho0)) + 1; };
    // A few operations on numbers of size rho a: 1e-14 relative.
    for (auto [rho, e] : {std::pair{3000.0, 2e6}, {2500.0, 1e6}, {2700.0, 0.0}}) {
        const double w = omega(rho, e), g = rho * (a + b / (w * w));
        EXPECT_NEAR(eos->energyDerivative(rho, e), g, 1e-14 * g) << rho << " " << e;
    }
    for (auto [rho, e] : {std::pair{2000.0, 2e7}, {1000.0, 5e7}}) {
        const double w = omega(rho, e), x = rho0 / rho - 1, G = std::exp(-alpha * x * x);
        const double g = rho * (a + G * b / (w * w));
        EXPECT_NEAR(eos->energyDerivative(rho, e), g, 1e-14 * g) << rho << " " << e;
    }
    const double rho = 2400.0, e = Eiv + 0.25 * (Ecv - Eiv);
    const double w = omega(rho, e), x = rho0 / rho - 1, G = std::exp(-alpha * x * x);
    const double g = 0.25 * rho * (a + G * b / (w * w)) + 0.75 * rho * (a + b / (w * w)) +
                     (expandedByHand(rho, e) - compressedByHand(rho, e)) / (Ecv - Eiv);
    // The blend's last term is a difference of pressures of size A over Ecv - Eiv: 1e-12 relative.
    EXPECT_NEAR(eos->energyDerivative(rho, e), g, 1e-12 * std::abs(g));
}

// `branch compressed`: P_c everywhere (von Nida 2005 Eq. 2.9), without the expanded branch's
// constants; the default stays `full`.
TEST(Tillotson, CompressedBranchEverywhere) {
    const auto partial = test::makeEos(
        "type tillotson; branch compressed; rho0 2700; A 75.2e9; B 65e9; a 0.5; b 1.63; E0 5e6;");
    const auto full = makeTillotson();
    EXPECT_EQ(dynamic_cast<const Tillotson&>(*partial).branch(), Tillotson::Branch::compressed);
    EXPECT_EQ(full->branch(), Tillotson::Branch::full);
    // States of the three regions of the full model (expanded, blend, cold expanded, compressed).
    for (auto [rho, e] :
         {std::pair{2000.0, 2e7}, {1000.0, 5e7}, {2400.0, 5e6}, {2500.0, 1e6}, {3000.0, 2e6}}) {
        EXPECT_NEAR(partial->pressure(rho, e), compressedByHand(rho, e), 1e-12 * A) << rho << " " << e;
        const double eta = rho / rho0, w = e / (E0 * eta * eta) + 1, g = rho * (a + b / (w * w));
        EXPECT_NEAR(partial->energyDerivative(rho, e), g, 1e-14 * g) << rho << " " << e;
        // c^2 = dP_c/drho|_e + P_c g / rho^2, dP_c/drho|_e = (a + b/omega) e + 2 b e (omega - 1)/omega^2
        // + (A + 2 B mu)/rho0 (doc/methods/fpm.md section 1): round-off of sums of size A/rho0.
        const double mu = eta - 1;
        const double c2 = (a + b / w) * e + 2 * b * e * (w - 1) / (w * w) + (A + 2 * B * mu) / rho0 +
                          compressedByHand(rho, e) * g / (rho * rho);
        EXPECT_NEAR(partial->soundSpeedSquared(rho, e), c2, 1e-12 * A / rho0) << rho << " " << e;
    }
    // Where the full model is compressed, the two agree exactly.
    EXPECT_EQ(partial->pressure(3000.0, 2e6), full->pressure(3000.0, 2e6));
    EXPECT_NE(partial->pressure(2000.0, 2e7), full->pressure(2000.0, 2e7));
    // The thesis's check: c = sqrt(A/rho0) and g = rho0 (a + b) at rho0, e = 0.
    EXPECT_NEAR(partial->soundSpeedSquared(rho0, 0.0), A / rho0, 1e-14 * A / rho0);
    EXPECT_NEAR(partial->energyDerivative(rho0, 0.0), rho0 * (a + b), 1e-14 * rho0 * (a + b));
    EXPECT_THROW(test::makeEos("type tillotson; branch partial; rho0 2700; A 75.2e9; B 65e9; a 0.5; b 1.63; "
                               "E0 5e6;"),
                 InputError);
}

// With branch full (the default) alpha, beta, Eiv and Ecv are required; the error names each.
TEST(Tillotson, FullBranchNeedsTheExpandedConstants) {
    const std::vector<std::pair<std::string, std::string>> expandedKeys = {
        {"alpha", "5"}, {"beta", "5"}, {"Eiv", "3e6"}, {"Ecv", "13.9e6"}};
    for (const auto& [missing, unused] : expandedKeys) {
        std::string text = "type tillotson; rho0 2700; A 75.2e9; B 65e9; a 0.5; b 1.63; E0 5e6;";
        for (const auto& [k, v] : expandedKeys)
            if (k != missing) text += " " + k + " " + v + ";";
        for (const std::string& branch : {std::string(), std::string(" branch full;")}) {
            try {
                test::makeEos(text + branch);
                ADD_FAILURE() << "built without '" << missing << "'";
            } catch (const InputError& error) {
                const std::string what = error.what();
                EXPECT_NE(what.find("missing keyword '" + missing + "'"), std::string::npos) << what;
                EXPECT_NE(what.find("branch full"), std::string::npos) << what;
            }
        }
        EXPECT_NO_THROW(test::makeEos(text + " branch compressed;")) << missing;
    }
}

TEST(Tillotson, EcvMustExceedEiv) {
    EXPECT_THROW(test::makeEos("type tillotson; rho0 2700; A 75.2e9; B 65e9; a 0.5; b 1.63; alpha 5; beta 5; "
                               "E0 5e6; Eiv 3e6; Ecv 2e6;"),
                 InputError);
}

}  // namespace
}  // namespace mfdyn
