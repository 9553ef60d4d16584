// MaterialSet: each material's models built as its dictionary names them, a fluid next to a solid,
// the fields the set says the models need, and the errors for a model the method does not take
// or a required one that is missing (at the entry's file and line).
#include "materials/MaterialSet.hpp"

#include "core/Dictionary.hpp"

#include <gtest/gtest.h>

namespace mfdyn {
namespace {

const char* fluidAndSolid = R"(
materials
{
    water { equationOfState { type tait; rho0 1000; B 3e8; gamma 7; } }
    plate
    {
        rho0 2785; c0 5330; s 1.338; gamma0 2.0; shearModulus 27.1e9; yieldStress 0.265e9;
        equationOfState { type mieGruneisen; }
        strength        { type vonMises; }
    }
    air { equationOfState { type idealGas; gamma 1.4; } strength { type none; } }
}
)";

MaterialModels sphLike() {
    return {"impactSph", ModelUse::required, ModelUse::optional, ModelUse::refused};
}

TEST(MaterialSet, BuildsEachMaterialAsItsDictionaryNamesIt) {
    const Dictionary dict = Dictionary::parse(fluidAndSolid, "materialProperties");
    const MaterialSet<2> set(dict, sphLike());
    ASSERT_EQ(set.size(), 3u);
    EXPECT_EQ(set.names(), (std::vector<std::string>{"water", "plate", "air"}));
    EXPECT_EQ(set[0].eos->type(), "tait");
    EXPECT_EQ(set[0].strength, nullptr);  // a fluid
    EXPECT_EQ(set[1].eos->type(), "mieGruneisen");
    ASSERT_NE(set[1].strength, nullptr);
    EXPECT_EQ(set[1].strength->type(), "vonMises");
    // `strength none` carries no deviatoric stress: no law is kept, so no stress field for it.
    EXPECT_EQ(set[2].strength, nullptr);
    EXPECT_EQ(set[2].constitutiveLaw, nullptr);
    // Tait depends on rho only, the other two on e: the energy field is needed.
    EXPECT_TRUE(set.needsEnergy());
    EXPECT_TRUE(set.anyStrength());
    EXPECT_TRUE(set.usesPlasticStrain());  // von Mises accumulates the equivalent plastic strain
    EXPECT_FALSE(set.usesTemperature());
    EXPECT_FALSE(set.usesPlasticState());
}

TEST(MaterialSet, AFluidAloneNeedsNoEnergyAndNoStress) {
    const Dictionary dict =
        Dictionary::parse("materials { water { equationOfState { type tait; rho0 1000; B 3e8; gamma 7; } } }",
                          "materialProperties");
    const MaterialSet<3> set(dict, sphLike());
    EXPECT_FALSE(set.needsEnergy());
    EXPECT_FALSE(set.anyStrength());
    EXPECT_FALSE(set.usesPlasticStrain());
}

TEST(MaterialSet, AModelTheMethodDoesNotTakeIsAnErrorAtItsEntry) {
    const Dictionary dict = Dictionary::parse(
        "materials {\n rubber {\n equationOfState { type tait; rho0 1000; B 3e8; gamma 7; }\n"
        " constitutiveLaw { type neoHookean; rho0 1100; shearModulus 5e6; bulkModulus 5e7; }\n } }",
        "materialProperties");
    try {
        MaterialSet<3> set(dict, sphLike());
        FAIL() << "a constitutive law was accepted by a method that refuses it";
    } catch (const InputError& e) {
        const std::string what = e.what();
        EXPECT_NE(what.find("materialProperties:4:"), std::string::npos) << what;  // file:line of the entry
        EXPECT_NE(what.find("impactSph takes no constitutiveLaw"), std::string::npos) << what;
        EXPECT_NE(what.find("equationOfState"), std::string::npos) << what;  // what it takes
    }
}

TEST(MaterialSet, AMissingRequiredModelIsAnErrorNamingTheMaterial) {
    const Dictionary dict =
        Dictionary::parse("materials { rubber { strength { type none; } } }", "materialProperties");
    try {
        MaterialSet<2> set(dict, sphLike());
        FAIL() << "a material without an equation of state was accepted";
    } catch (const InputError& e) {
        const std::string what = e.what();
        EXPECT_NE(what.find("material 'rubber' names no equationOfState"), std::string::npos) << what;
        EXPECT_EQ(what.find("keyword ''"), std::string::npos) << what;  // located at the material, not a key
    }
}

TEST(MaterialSet, AFluidBesideAConstitutiveSolidWhereEitherIsAllowed) {
    const MaterialModels mpmLike{"mpmFsi", ModelUse::optional, ModelUse::refused, ModelUse::optional, true};
    const Dictionary dict = Dictionary::parse(
        "materials { water { equationOfState { type tait; rho0 1000; B 3e8; gamma 7; } }\n"
        " rubber { constitutiveLaw { type neoHookean; rho0 1100; shearModulus 5e6; bulkModulus 5e7; } } }",
        "materialProperties");
    const MaterialSet<2> set(dict, mpmLike);
    ASSERT_EQ(set.size(), 2u);
    EXPECT_NE(set[0].eos, nullptr);
    EXPECT_EQ(set[0].constitutiveLaw, nullptr);
    EXPECT_EQ(set[1].eos, nullptr);
    ASSERT_NE(set[1].constitutiveLaw, nullptr);
    EXPECT_DOUBLE_EQ(set[1].constitutiveLaw->referenceDensity(), 1100.0);

    const Dictionary neither = Dictionary::parse("materials { ghost { } }", "materialProperties");
    EXPECT_THROW(MaterialSet<2>(neither, mpmLike), InputError);
}

}  // namespace
}  // namespace mfdyn
