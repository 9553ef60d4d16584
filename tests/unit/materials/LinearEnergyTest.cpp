// linearEnergy (von Nida 2005 Eq. 7.1): P, c^2 = dP/drho|_s and g by hand, the sign of the thesis's
// bracket rho c^2 + g p / rho (Eq. 7.2) at its setting 4, the barotropic case g = 0, and bad input.
#include "EquationOfStateTestTools.hpp"

#include <gtest/gtest.h>

#include <string>

namespace mfdyn {
namespace {

using test::makeEos;

TEST(LinearEnergy, ValuesByHand) {
    // A water-like setting: c = 1480 m/s, g = 1000 kg/m^3, rho0 = 1000 kg/m^3, p0 = 1e5 Pa.
    const auto eos = makeEos("type linearEnergy; c 1480; g 1000; rho0 1000; p0 1e5;");
    EXPECT_TRUE(eos->needsEnergy());
    EXPECT_EQ(eos->referenceDensity(), 1000.0);
    const double c2 = 1480.0 * 1480.0;
    for (auto [rho, e] : {std::pair{1000.0, 0.0}, {1100.0, 1e4}, {950.0, 2e3}, {1000.0, -50.0}}) {
        const double p = 1e5 + c2 * (rho - 1000.0) + 1000.0 * e;
        // A few operations on numbers of size c^2 rho0 ~ 2e9: 1e-15 of that.
        EXPECT_NEAR(eos->pressure(rho, e), p, 1e-15 * c2 * 1000.0) << rho << " " << e;
        EXPECT_NEAR(eos->soundSpeedSquared(rho, e), c2 + p * 1000.0 / (rho * rho), 1e-15 * c2)
            << rho << " " << e;
        EXPECT_EQ(eos->energyDerivative(rho, e), 1000.0);
        // The thesis's c^2 is dP/drho|_e.
        EXPECT_NEAR(eos->densityDerivative(rho, e), c2, 1e-15 * c2) << rho << " " << e;
    }
    // p0 defaults to 0.
    EXPECT_EQ(makeEos("type linearEnergy; c 4; g 1; rho0 1;")->pressure(1.0, 0.0), 0.0);
}

// Setting 4 of the thesis (Table 7.1): c = 1, g = 1, rho0 = 1, p0 = 0. At rho = rho0, P = e and the
// bracket of Eq. 7.2 is rho c^2 + g P / rho = 1 + P = rho c_s^2: positive with the outer pressure
// p_o = 10 of Remark 7.1, zero at P = -1, negative below, where c_s^2 is returned as is.
TEST(LinearEnergy, BracketSignAtSettingFour) {
    const auto eos = makeEos("type linearEnergy; c 1; g 1; rho0 1;");
    for (auto [e, bracket] : {std::pair{10.0, 11.0}, {0.0, 1.0}, {-1.0, 0.0}, {-2.0, -1.0}}) {
        const double p = eos->pressure(1.0, e);
        EXPECT_EQ(p, e);
        // Exact in binary: sums of small integers.
        EXPECT_EQ(1.0 * eos->soundSpeedSquared(1.0, e), bracket) << e;
        EXPECT_EQ(1.0 * 1.0 + 1.0 * p / 1.0, bracket) << e;
    }
    EXPECT_LT(eos->soundSpeedSquared(1.0, -2.0), 0.0);
    // Off rho0: rho = 0.9, e = 0 gives P = -0.1 and rho c_s^2 = 0.9 - 0.1/0.9 > 0.
    EXPECT_NEAR(0.9 * eos->soundSpeedSquared(0.9, 0.0), 0.9 - 0.1 / 0.9, 1e-15);
}

TEST(LinearEnergy, ZeroGIsBarotropic) {
    const auto eos = makeEos("type linearEnergy; c 20; g 0; rho0 1000;");
    EXPECT_FALSE(eos->needsEnergy());
    EXPECT_EQ(eos->energyDerivative(1100.0, 0.0), 0.0);
    EXPECT_EQ(eos->soundSpeedSquared(1100.0, 0.0), 400.0);
    // The linearBarotropic model, to round-off.
    const auto linear = makeEos("type linearBarotropic; c0 20; rho0 1000;");
    EXPECT_EQ(eos->pressure(1100.0, 0.0), linear->pressure(1100.0, 0.0));
    std::vector<double> rho = {900.0, 1100.0}, p(2), c(2);
    eos->evaluate(2, rho.data(), nullptr, p.data(), c.data());
    EXPECT_EQ(p[1], 400.0 * 100.0);
    EXPECT_EQ(c[0], 20.0);
}

// Bad input is an InputError at the file and line of the entry, naming the keyword.
TEST(LinearEnergy, BadInput) {
    auto expectError = [](const std::string& text, const std::string& key) {
        try {
            makeEos(text);
            ADD_FAILURE() << "accepted: " << text;
        } catch (const InputError& error) {
            const std::string what = error.what();
            EXPECT_NE(what.find(key), std::string::npos) << what;
            EXPECT_NE(what.find("test:2"), std::string::npos) << what;
        }
    };
    expectError("type linearEnergy;\nc -1; g 1; rho0 1;", "'c'");
    expectError("type linearEnergy;\nc 0; g 1; rho0 1;", "'c'");
    expectError("type linearEnergy;\nc 1; g -1; rho0 1;", "'g'");
    expectError("type linearEnergy;\nc 1; g 1; rho0 0;", "'rho0'");
    EXPECT_THROW(makeEos("type linearEnergy; g 1; rho0 1;"), InputError);  // no c
    EXPECT_THROW(makeEos("type linearEnergy; c 1; rho0 1;"), InputError);  // no g
}

}  // namespace
}  // namespace mfdyn
