// The dissipation family: every type reads its dictionary through a keyword schema; the defaults
// are the thesis's (Zisis 2017 §4.2: a_v = 1, a_rho = 0.5, a_e = 0.1, b = 2) and Monaghan's
// (alpha 1, beta 2); bad entries are InputErrors naming the entry.
#include "core/Dictionary.hpp"
#include "core/Error.hpp"
#include "core/Registry.hpp"
#include "sph/MonaghanGingoldViscosity.hpp"
#include "sph/NoDissipation.hpp"
#include "sph/RiemannDissipation.hpp"

#include "../SchemaTestTools.hpp"

#include <gtest/gtest.h>

#include <string>

using namespace mfdyn;

namespace {

std::unique_ptr<Dissipation> modelOf(const std::string& text) {
    return Dissipation::New(Dictionary::parse(text, "dissipation"));
}

// The coefficients a model of type M read from `text` (a test failure if it is another type).
template <class M>
typename M::Coefficients coefficientsOf(const std::string& text) {
    const auto model = modelOf(text);
    const auto* m = dynamic_cast<const M*>(model.get());
    EXPECT_NE(m, nullptr) << text;
    return m ? m->coefficients() : typename M::Coefficients{};
}

// The message of the InputError that `text` raises ("" and a test failure if none).
std::string errorOf(const std::string& text) {
    return test::inputErrorOf([&] { modelOf(text); }, text);
}

}  // namespace

TEST(DissipationContract, EveryTypeDeclaresAKeywordSchema) {
    // Named here so that the library, and its registrations, are linked.
    const auto schemas = {RiemannDissipation::keywords(), MonaghanGingoldViscosity::keywords(),
                          NoDissipation::keywords()};
    test::expectRegisteredSchemas(Dissipation::familyName, schemas, "libraries/sph/",
                                  Dissipation::methodName);
    // Every keyword has a default: `dissipation { type <name>; }` is a whole model.
    for (const KeywordSchema& schema : schemas)
        for (const Keyword& k : schema.keywords())
            EXPECT_EQ(k.kind, Keyword::Kind::defaulted) << schema.type() << " " << k.name;
}

TEST(DissipationContract, DefaultsAreTheThesisAndMonaghanValues) {
    const auto r = coefficientsOf<RiemannDissipation>("type riemann;");
    EXPECT_EQ(r.av, 1.0);
    EXPECT_EQ(r.bv, 2.0);
    EXPECT_EQ(r.arho, 0.5);
    EXPECT_EQ(r.brho, 2.0);
    EXPECT_EQ(r.ae, 0.1);
    EXPECT_EQ(r.be, 2.0);
    EXPECT_FALSE(r.alternativeSignal);
    EXPECT_FALSE(r.allPairs);
    const auto m = coefficientsOf<MonaghanGingoldViscosity>("type monaghanGingold;");
    EXPECT_EQ(m.alpha, 1.0);
    EXPECT_EQ(m.beta, 2.0);
    EXPECT_FALSE(m.balsara);
    EXPECT_EQ(m.arho, 0.0);
    EXPECT_EQ(m.brho, 0.0);
    EXPECT_NE(dynamic_cast<const NoDissipation*>(modelOf("type none;").get()), nullptr);
}

TEST(DissipationContract, GivenValuesAreRead) {
    const auto r = coefficientsOf<RiemannDissipation>(
        "type riemann; velocity (0.5 1); density (0 0); energy (0.2 3); signal alternative; pairs all;");
    EXPECT_EQ(r.av, 0.5);
    EXPECT_EQ(r.bv, 1.0);
    EXPECT_EQ(r.arho, 0.0);
    EXPECT_EQ(r.ae, 0.2);
    EXPECT_EQ(r.be, 3.0);
    EXPECT_TRUE(r.alternativeSignal);
    EXPECT_TRUE(r.allPairs);
    const auto m = coefficientsOf<MonaghanGingoldViscosity>(
        "type monaghanGingold; alpha 0.5; beta 1; balsara yes; density (0.5 0);");
    EXPECT_EQ(m.alpha, 0.5);
    EXPECT_EQ(m.beta, 1.0);
    EXPECT_TRUE(m.balsara);
    EXPECT_EQ(m.arho, 0.5);
}

TEST(DissipationContract, BadEntriesNameTheEntryAndTheValidChoices) {
    const std::string length = errorOf("type riemann; velocity (1 2 3);");
    EXPECT_NE(length.find("velocity"), std::string::npos) << length;
    EXPECT_NE(length.find("expected 2 values"), std::string::npos) << length;
    const std::string negative = errorOf("type riemann; energy (-0.1 2);");
    EXPECT_NE(negative.find("energy"), std::string::npos) << negative;
    EXPECT_NE(negative.find(">= 0"), std::string::npos) << negative;
    const std::string signal = errorOf("type riemann; signal riemman;");
    EXPECT_NE(signal.find("riemann | alternative"), std::string::npos) << signal;
    EXPECT_NE(signal.find("did you mean 'riemann'"), std::string::npos) << signal;
    const std::string alpha = errorOf("type monaghanGingold; alpha -1;");
    EXPECT_NE(alpha.find("alpha"), std::string::npos) << alpha;
    const std::string type = errorOf("type monaghanGingol;");
    EXPECT_NE(type.find("did you mean 'monaghanGingold'"), std::string::npos) << type;
}
