// The smoothingLength family: each law's keyword schema, its defaults (η = 1.2, Zisis 2017 §4.1;
// the summation solver's tolerance 1e-4 and 30 iterations), the explicit laws' formulas (4.1),
// (4.2) and the fixed law's `h`, and the errors of bad entries.
#include "core/Dictionary.hpp"
#include "core/Error.hpp"
#include "core/Registry.hpp"
#include "sph/FixedSmoothingLength.hpp"
#include "sph/MassDensitySmoothingLength.hpp"
#include "sph/NumberDensitySmoothingLength.hpp"
#include "sph/SummationSmoothingLength.hpp"

#include "../SchemaTestTools.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

using namespace mfdyn;

namespace {

std::unique_ptr<SmoothingLengthLaw> law(const std::string& text) {
    return SmoothingLengthLaw::New(Dictionary::parse(text, "smoothingLength"));
}

std::string errorOf(const std::string& text) {
    return test::inputErrorOf([&] { law(text); }, text);
}

}  // namespace

TEST(SmoothingLengthContract, EveryTypeDeclaresAKeywordSchemaWithEta) {
    const auto schemas = {FixedSmoothingLength::keywords(), MassDensitySmoothingLength::keywords(),
                          NumberDensitySmoothingLength::keywords(), SummationSmoothingLength::keywords()};
    test::expectRegisteredSchemas(SmoothingLengthLaw::familyName, schemas, "libraries/sph/");
    for (const KeywordSchema& schema : schemas) {
        const Keyword* eta = schema.find("eta");
        ASSERT_NE(eta, nullptr) << schema.type();
        EXPECT_EQ(eta->defaultValue, "1.2");
        for (const Keyword& k : schema.keywords()) {
            EXPECT_NE(k.kind, Keyword::Kind::required) << schema.type() << " " << k.name;
        }
    }
}

TEST(SmoothingLengthContract, ExplicitLawsFollowTheirFormulas) {
    const double m[] = {2e-3, 8e-3}, rho[] = {1000.0, 500.0}, number[] = {4e4, 2.5e3};
    double h[2];
    law("type massDensity; eta 1.3;")->update(2, 2, m, rho, nullptr, h);
    EXPECT_DOUBLE_EQ(h[0], 1.3 * std::sqrt(2e-3 / 1000.0));  // (4.2) in 2D
    EXPECT_DOUBLE_EQ(h[1], 1.3 * std::sqrt(8e-3 / 500.0));
    const auto byNumber = law("type numberDensity;");
    EXPECT_TRUE(byNumber->needsNumberDensity());
    byNumber->update(3, 2, m, rho, number, h);
    EXPECT_DOUBLE_EQ(h[0], 1.2 / std::cbrt(4e4));  // (4.1) in 3D, default eta
    EXPECT_DOUBLE_EQ(h[1], 1.2 / std::cbrt(2.5e3));
    EXPECT_DOUBLE_EQ(law("type fixed; h 0.01;")->initial(2, 1.0, 1.0), 0.01);
    EXPECT_DOUBLE_EQ(law("type fixed; eta 2;")->initial(1, 1e-3, 1.0), 2e-3);
    const auto summation = law("type summation;");
    EXPECT_TRUE(summation->iterative());
    EXPECT_EQ(summation->tolerance(), 1e-4);
    EXPECT_EQ(summation->maxIterations(), 30);
    const auto tight = law("type summation; tolerance 1e-8; maxIterations 50;");
    EXPECT_EQ(tight->tolerance(), 1e-8);
    EXPECT_EQ(tight->maxIterations(), 50);
}

TEST(SmoothingLengthContract, BadEntriesNameTheEntry) {
    const std::string eta = errorOf("type massDensity; eta -1;");
    EXPECT_NE(eta.find("keyword 'eta'"), std::string::npos) << eta;
    EXPECT_NE(eta.find("> 0"), std::string::npos) << eta;
    const std::string iterations = errorOf("type summation; maxIterations 0;");
    EXPECT_NE(iterations.find("maxIterations"), std::string::npos) << iterations;
    const std::string h = errorOf("type fixed; h 0;");
    EXPECT_NE(h.find("keyword 'h'"), std::string::npos) << h;
    const std::string type = errorOf("type massDenstiy;");
    EXPECT_NE(type.find("did you mean 'massDensity'"), std::string::npos) << type;
}
