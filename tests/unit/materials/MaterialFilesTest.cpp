// The material files of etc/materials through #includeEtc, as a case uses them.
#include "EquationOfStateTestTools.hpp"
#include "materials/equationOfState/EquationOfState.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace mfdyn {
namespace {

ReadOptions etc() {
    return ReadOptions{{MFDYN_TEST_ETC_DIR}};
}

TEST(MaterialFiles, MieGruneisenFromAl2) {
    const Dictionary top = Dictionary::parse(
        "materials { plate { #includeEtc \"materials/Al2\"\n equationOfState { type mieGruneisen; } } }",
        "test", etc());
    const Dictionary& plate = top.subDict("materials").subDict("plate");
    const auto eos = EquationOfState::New(plate.subDict("equationOfState"));
    EXPECT_EQ(eos->referenceDensity(), 2785.0);
    EXPECT_NEAR(eos->soundSpeedSquared(2785.0, 0.0), 5330.0 * 5330.0, 1e-12 * 5330.0 * 5330.0);
    EXPECT_EQ(plate.get<double>("yieldStress"), 0.265e9);
    EXPECT_EQ(plate.get<double>("shearModulus"), 27.1e9);
}

TEST(MaterialFiles, EveryTable61MaterialBuildsAMieGruneisen) {
    // Table 6.1 (doc/methods/sph-impact.md 5.3) in SI: rho0 [kg/m^3], c0 [m/s].
    const std::vector<std::tuple<std::string, double, double>> table = {
        {"Al1", 2710, 5300}, {"Al2", 2785, 5330},   {"Pb", 11360, 2030},
        {"Cu", 8930, 3900},  {"epoxy", 2280, 2930}, {"homogenized", 2659, 4730}};
    for (const auto& [name, rho0, c0] : table) {
        const Dictionary top = Dictionary::parse(
            "m { #includeEtc \"materials/" + name + "\"\n equationOfState { type mieGruneisen; } }", "test",
            etc());
        const auto eos = EquationOfState::New(top.subDict("m").subDict("equationOfState"));
        EXPECT_EQ(eos->referenceDensity(), rho0) << name;
        EXPECT_NEAR(std::sqrt(eos->soundSpeedSquared(rho0, 0.0)), c0, 1e-9 * c0) << name;
        for (const char* key : {"shearModulus", "yieldStress"})
            EXPECT_TRUE(top.subDict("m").found(key)) << name;
    }
}

TEST(MaterialFiles, TillotsonSetsBuild) {
    for (const auto& [name, rho0] : {std::pair{"tillotsonAluminium", 2700.0}, {"tillotsonIron", 7800.0}}) {
        const Dictionary top = Dictionary::parse(
            std::string("m { #includeEtc \"materials/") + name + "\"\n equationOfState { type tillotson; } }",
            "test", etc());
        const auto eos = EquationOfState::New(top.subDict("m").subDict("equationOfState"));
        EXPECT_EQ(eos->referenceDensity(), rho0) << name;
        EXPECT_NEAR(eos->pressure(rho0, 0.0), 0.0, 1e-3) << name;
        EXPECT_GT(eos->soundSpeedSquared(rho0, 0.0), 0.0) << name;
    }
}

TEST(MaterialFiles, CopperTaylorBarModuliAreConsistent) {
    const Dictionary d = Dictionary::parse("#includeEtc \"materials/copperTaylorBar\"\n", "test", etc());
    const double E = d.get<double>("youngsModulus"), nu = d.get<double>("poissonRatio");
    EXPECT_EQ(E, 117e9);
    EXPECT_EQ(d.get<double>("yieldStress"), 0.4e9);
    EXPECT_EQ(d.get<double>("hardeningModulus"), 0.1e9);
    // The derived entries are written to 5-8 significant digits.
    EXPECT_NEAR(d.get<double>("shearModulus"), E / (2 * (1 + nu)), 1e-7 * E);
    EXPECT_NEAR(d.get<double>("bulkModulus"), E / (3 * (1 - 2 * nu)), 1e-7 * E);
    EXPECT_NEAR(d.get<double>("c0"), std::sqrt(d.get<double>("bulkModulus") / d.get<double>("rho0")), 0.1);
}

}  // namespace
}  // namespace mfdyn
