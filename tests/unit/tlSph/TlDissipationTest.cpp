// The tlDissipation family: every type reads through a keyword schema; jst defaults to the paper's
// coefficients (Lee et al. 2016: eps_p = (0 1/8), eps_J = (0 0)); artificialViscosity needs its
// mu_vis; bad entries are InputErrors naming the entry.
#include "core/Dictionary.hpp"
#include "core/Error.hpp"
#include "core/Registry.hpp"
#include "tlSph/ArtificialViscosity.hpp"
#include "tlSph/JstDissipation.hpp"
#include "tlSph/NoTlDissipation.hpp"

#include "../SchemaTestTools.hpp"

#include <gtest/gtest.h>

#include <string>

using namespace mfdyn;

namespace {

TlDissipationCoefficients coefficientsOf(const std::string& text) {
    return TlDissipation::New(Dictionary::parse(text, "dissipation"))->coefficients();
}

std::string errorOf(const std::string& text) {
    return test::inputErrorOf([&] { coefficientsOf(text); }, text);
}

}  // namespace

TEST(TlDissipationContract, EveryTypeDeclaresAKeywordSchema) {
    test::expectRegisteredSchemas(
        TlDissipation::familyName,
        {JstDissipation::keywords(), ArtificialViscosity::keywords(), NoTlDissipation::keywords()},
        "libraries/tlSph/");
}

TEST(TlDissipationContract, DefaultsAndGivenValues) {
    const TlDissipationCoefficients paper = coefficientsOf("type jst;");
    EXPECT_EQ(paper.momentum2, 0.0);
    EXPECT_EQ(paper.momentum4, 0.125);
    EXPECT_EQ(paper.jacobian2, 0.0);
    EXPECT_EQ(paper.jacobian4, 0.0);
    EXPECT_TRUE(paper.needsBiLaplacian());
    const TlDissipationCoefficients given =
        coefficientsOf("type jst; momentum (0.125 0.0625); jacobian (0.1 0);");
    EXPECT_EQ(given.momentum2, 0.125);
    EXPECT_EQ(given.momentum4, 0.0625);
    EXPECT_EQ(given.jacobian2, 0.1);
    EXPECT_EQ(coefficientsOf("type artificialViscosity; viscosity 50;").viscosity, 50.0);
    EXPECT_FALSE(coefficientsOf("type none;").any());
}

TEST(TlDissipationContract, BadEntriesNameTheEntry) {
    const std::string length = errorOf("type jst; momentum (0 0.125 1);");
    EXPECT_NE(length.find("momentum"), std::string::npos) << length;
    EXPECT_NE(length.find("expected 2 values"), std::string::npos) << length;
    const std::string negative = errorOf("type jst; jacobian (0 -1);");
    EXPECT_NE(negative.find(">= 0"), std::string::npos) << negative;
    const std::string missing = errorOf("type artificialViscosity;");
    EXPECT_NE(missing.find("missing keyword 'viscosity'"), std::string::npos) << missing;
}
