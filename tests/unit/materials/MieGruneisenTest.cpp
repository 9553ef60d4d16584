// Mie-Grueneisen closed forms: the Hugoniot of Us = c0 + s up, the cubic reference of the thesis,
// the tension branch, the cut-off, and parameters read from the enclosing material dictionary.
#include "EquationOfStateTestTools.hpp"
#include "materials/equationOfState/MieGruneisen.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace mfdyn {
namespace {

using test::makeEos;

// Al2 of Table 6.1.
constexpr double rho0 = 2785.0, c0 = 5330.0, s = 1.338, gamma0 = 2.0;
const std::string al2 = "type mieGruneisen; rho0 2785; c0 5330; s 1.338; gamma0 2.0;";

struct HugoniotState {
    double rho, e, p;
};

// The shocked state for particle velocity up from rest at rho0, P = 0, e = 0 (note 1.9-1.12):
// mass and momentum give rho1 = rho0 Us/(Us - up) and P = rho0 Us up; energy e = up^2/2.
HugoniotState hugoniot(double up) {
    const double us = c0 + s * up;
    return {rho0 * us / (us - up), 0.5 * up * up, rho0 * us * up};
}

TEST(MieGruneisen, LinearUsUpReproducesTheHugoniot) {
    const auto eos = makeEos(al2 + " hugoniot linearUsUp;");
    for (double up : {10.0, 100.0, 500.0, 1000.0, 2000.0, 4000.0}) {
        const auto h = hugoniot(up);
        // Exact algebraically (MieGruneisen.cpp); a few roundings of O(1) terms: 1e-10 is generous.
        EXPECT_NEAR(eos->pressure(h.rho, h.e), h.p, 1e-10 * h.p) << "up " << up;
    }
}

TEST(MieGruneisen, CubicIsTheThesisPolynomial) {
    // The note's form (6.11-6.13) is the O(mu^3) Taylor expansion of the Hugoniot, so it does not
    // reproduce rho0 Us up exactly: P(rho1, e_H) - P_H = (1 - Gamma0 mu/2)(P_cubic - P_H).
    const auto eos = makeEos(al2);
    const double A = rho0 * c0 * c0, B = A * (1 + 2 * (s - 1)), C = A * (2 * (s - 1) + 3 * (s - 1) * (s - 1));
    for (double up : {10.0, 100.0, 500.0, 1000.0, 2000.0}) {
        const auto h = hugoniot(up);
        const double mu = h.rho / rho0 - 1.0;
        const double cubic = A * mu + B * mu * mu + C * mu * mu * mu;
        const double expected = h.p + (1.0 - 0.5 * gamma0 * mu) * (cubic - h.p);
        EXPECT_NEAR(eos->pressure(h.rho, h.e), expected, 1e-10 * h.p) << "up " << up;
        // The truncation: the next term of A mu (1 + mu)/(1 - (s-1) mu)^2 is
        // A (s-1)^2 (4 (s-1) + 3) mu^4 ... so the relative gap is O(mu^3), below 1% for mu < 0.1.
        if (mu < 0.1) {
            EXPECT_LT(std::abs(eos->pressure(h.rho, h.e) - h.p), 1e-2 * h.p) << "up " << up;
        }
    }
    // e = 0 on the cubic: P = (1 - Gamma0 mu/2)(A mu + B mu^2 + C mu^3), evaluated by hand at mu = 0.2.
    const double mu = 0.2;
    EXPECT_NEAR(eos->pressure(rho0 * 1.2, 0.0), (1 - 0.2) * (A * mu + B * mu * mu + C * mu * mu * mu),
                1e-12 * A);
}

TEST(MieGruneisen, TensionBranchAndSoundSpeedAtRest) {
    const auto eos = makeEos(al2);
    const double A = rho0 * c0 * c0;
    // mu = -0.1: P_H = A mu, P = (1 + 0.1)(-0.1 A) + Gamma0 rho e.
    const double rho = 0.9 * rho0, e = 1e5;
    EXPECT_NEAR(eos->pressure(rho, e), 1.1 * (-0.1 * A) + gamma0 * rho * e, 1e-12 * A);
    // At rest c^2 = A/rho0 = c0^2.
    EXPECT_NEAR(eos->soundSpeedSquared(rho0, 0.0), c0 * c0, 1e-12 * c0 * c0);
}

TEST(MieGruneisen, MinimumPressureCutsTension) {
    const auto eos = makeEos(al2 + " minimumPressure -1e9;");
    const auto uncut = makeEos(al2);
    EXPECT_DOUBLE_EQ(eos->pressure(0.9 * rho0, 0.0), -1e9);  // -3.1 GPa uncut
    EXPECT_DOUBLE_EQ(eos->pressure(1.1 * rho0, 0.0), uncut->pressure(1.1 * rho0, 0.0));
    // The sound speed is the uncut one (MieGruneisen.cpp).
    EXPECT_DOUBLE_EQ(eos->soundSpeedSquared(0.9 * rho0, 0.0), uncut->soundSpeedSquared(0.9 * rho0, 0.0));
    EXPECT_THROW(makeEos(al2 + " minimumPressure 1e9;"), InputError);
}

TEST(MieGruneisen, ParametersFromTheEnclosingMaterial) {
    const Dictionary top = Dictionary::parse(
        "materials { al { rho0 2785; c0 5330; s 1.338; gamma0 2.0; equationOfState { type mieGruneisen; } }"
        "            cu { rho0 8930; c0 3900; s 1.5; gamma0 2.0;"
        "                 equationOfState { type mieGruneisen; c0 4000; } } }",
        "test");
    const Dictionary& al = top.subDict("materials").subDict("al");
    const auto eos = EquationOfState::New(al.subDict("equationOfState"));
    EXPECT_EQ(eos->referenceDensity(), rho0);
    EXPECT_NEAR(eos->soundSpeedSquared(rho0, 0.0), c0 * c0, 1e-12 * c0 * c0);
    // The material's entries were read, so they are not reported unused.
    for (const auto& unused : al.unusedEntries()) ADD_FAILURE() << "unused " << unused.scopedKey;
    // An entry in the equationOfState dictionary wins over the material's.
    const auto cu = EquationOfState::New(top.subDict("materials").subDict("cu").subDict("equationOfState"));
    EXPECT_NEAR(cu->soundSpeedSquared(8930.0, 0.0), 4000.0 * 4000.0, 1e-12 * 1.6e7);
}

TEST(MieGruneisen, MissingKeywordNamesBothScopes) {
    const Dictionary top = Dictionary::parse(
        "materials { al { rho0 2785; s 1.338; gamma0 2; equationOfState { type mieGruneisen; } } }", "test");
    try {
        EquationOfState::New(top.subDict("materials").subDict("al").subDict("equationOfState"));
        FAIL() << "built without c0";
    } catch (const InputError& error) {
        const std::string what = error.what();
        EXPECT_NE(what.find("'c0'"), std::string::npos) << what;
        EXPECT_NE(what.find("materials/al/equationOfState"), std::string::npos) << what;
        EXPECT_NE(what.find("enclosing 'materials/al'"), std::string::npos) << what;
    }
    EXPECT_THROW(makeEos(al2 + " hugoniot quadratic;"), InputError);
    EXPECT_THROW(makeEos("type mieGruneisen; rho0 -1; c0 5330; s 1.338; gamma0 2;"), InputError);
}

}  // namespace
}  // namespace mfdyn
