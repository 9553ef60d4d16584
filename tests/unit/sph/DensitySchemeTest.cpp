// The densityScheme family: the common keywords (form, gradH, omegaMin) with their defaults, the
// coefficients a, b, c of each measure (Zisis 2017 §3: mass, number, volume) and the errors of bad
// entries, including the volume scheme's summation form, which is implicit and refused.
#include "core/Dictionary.hpp"
#include "core/Error.hpp"
#include "core/Registry.hpp"
#include "sph/MassScheme.hpp"
#include "sph/NumberScheme.hpp"
#include "sph/VolumeScheme.hpp"

#include "../SchemaTestTools.hpp"

#include <gtest/gtest.h>

#include <string>

using namespace mfdyn;

namespace {

std::unique_ptr<DensityScheme> scheme(const std::string& text) {
    return DensityScheme::New(Dictionary::parse(text, "densityScheme"));
}

std::string errorOf(const std::string& text) {
    return test::inputErrorOf([&] { scheme(text); }, text);
}

}  // namespace

TEST(DensitySchemeContract, EveryTypeDeclaresTheCommonKeywords) {
    const auto schemas = {MassScheme::keywords(), NumberScheme::keywords(), VolumeScheme::keywords()};
    test::expectRegisteredSchemas(DensityScheme::familyName, schemas, "libraries/sph/");
    for (const KeywordSchema& schema : schemas) {
        for (const char* name : {"form", "gradH", "omegaMin"}) EXPECT_NE(schema.find(name), nullptr) << name;
    }
    const auto defaults = scheme("type number;");
    EXPECT_FALSE(defaults->summation());
    EXPECT_TRUE(defaults->gradH());
    EXPECT_EQ(defaults->omegaMin(), 0.5);
    const auto given = scheme("type mass; form summation; gradH no; omegaMin 0.8;");
    EXPECT_TRUE(given->summation());
    EXPECT_FALSE(given->gradH());
    EXPECT_EQ(given->omegaMin(), 0.8);
}

TEST(DensitySchemeContract, CoefficientsOfTheThreeMeasures) {
    const double m[] = {2.0}, rho[] = {4.0};
    double a[1], b[1], c[1];
    scheme("type mass;")->coefficients(1, m, rho, a, b, c);  // a = m/rho^2, b = m, c = 1
    EXPECT_DOUBLE_EQ(a[0], 0.125);
    EXPECT_DOUBLE_EQ(b[0], 2.0);
    EXPECT_DOUBLE_EQ(c[0], 1.0);
    scheme("type number;")->coefficients(1, m, rho, a, b, c);  // a = m^2/rho^2, b = 1, c = m
    EXPECT_DOUBLE_EQ(a[0], 0.25);
    EXPECT_DOUBLE_EQ(b[0], 1.0);
    EXPECT_DOUBLE_EQ(c[0], 2.0);
    const auto volume = scheme("type volume;");  // a = m/rho, b = m/rho, c = rho
    volume->coefficients(1, m, rho, a, b, c);
    EXPECT_DOUBLE_EQ(a[0], 0.5);
    EXPECT_DOUBLE_EQ(b[0], 0.5);
    EXPECT_DOUBLE_EQ(c[0], 4.0);
    EXPECT_FALSE(volume->explicitSummation());
}

TEST(DensitySchemeContract, BadEntriesNameTheEntry) {
    const std::string volume = errorOf("type volume; form summation;");
    EXPECT_NE(volume.find("implicit"), std::string::npos) << volume;
    const std::string form = errorOf("type mass; form sumation;");
    EXPECT_NE(form.find("did you mean 'summation'"), std::string::npos) << form;
    for (const char* floor : {"0", "1.5"}) {
        const std::string omega = errorOf(std::string("type number; omegaMin ") + floor + ";");
        EXPECT_NE(omega.find("keyword 'omegaMin'"), std::string::npos) << omega;
    }
}
