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
    EXPECT_TRUE(coefficientsOf<RiemannDissipation>("type riemann;").contactLimiter);
    EXPECT_FALSE(coefficientsOf<RiemannDissipation>("type riemann; densityLimiter none;").contactLimiter);
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
    const std::string limiter = errorOf("type riemann; densityLimiter contacts;");
    EXPECT_NE(limiter.find("densityLimiter"), std::string::npos) << limiter;
    EXPECT_NE(limiter.find("contact | none"), std::string::npos) << limiter;
    const std::string alpha = errorOf("type monaghanGingold; alpha -1;");
    EXPECT_NE(alpha.find("alpha"), std::string::npos) << alpha;
    const std::string type = errorOf("type monaghanGingol;");
    EXPECT_NE(type.find("did you mean 'monaghanGingold'"), std::string::npos) << type;
}

namespace {

// The mass flux riemann's pair term adds to dρ_i/dt for one 1D pair: i at x = 0 with (ρ_i, P_i), j at
// x = −0.01 with (ρ_j, P_j), unit masses, sound speeds 1, dW/dr = −1 with both h, approaching at
// v_ij·r̂ = vr (≤ 0).
double massFluxOf(const std::string& text, double rhoi, double Pi, double rhoj, double Pj, double vr) {
    const auto model = modelOf(text);
    const auto& riemann = dynamic_cast<const RiemannDissipation&>(*model);
    const double m[2] = {1, 1}, rho[2] = {rhoi, rhoj}, p[2] = {Pi, Pj}, c[2] = {1, 1}, e[2] = {0, 0};
    SphPairLoop<1> loop;
    loop.m = m, loop.rho = rho, loop.p = p, loop.c = c, loop.e = e;
    const Vector<1> rhat = Vector<1>::Constant(1.0);
    const SphPair<1> q{0,    1,   0.01 * rhat, 0.01, rhat, vr * rhat, vr, -1.0,
                       -1.0, 1.0, rhoi,        Pi,   1.0,  0.01,      0.0};
    SphPairSums<1> sums;
    riemann.pair(loop, q, sums);
    return sums.massFlux;
}

}  // namespace

// The published mass flux (Eq. 4.26): a_ρ m_j (P_i − P_j)/(ρ̄ v') F with v' = c̄ − b vr = 1 at rest.
TEST(RiemannMassFlux, NoneIsThePublishedTermOnEveryPressureJump) {
    EXPECT_DOUBLE_EQ(massFluxOf("type riemann; densityLimiter none;", 1, 1, 1, 0.5, 0),
                     0.5 * 0.5 / 1.0 * -1.0);
    EXPECT_DOUBLE_EQ(massFluxOf("type riemann; densityLimiter none;", 1, 0.31, 0.125, 0.3, 0),
                     0.5 * 0.01 / 0.5625 * -1.0);
}

// At rest across a density jump (a contact's pressure blip) the whole pressure jump is excess: the
// limited term is the published one where the contrast |ρ_i − ρ_j|/max is κ = 0.3 or more (Sod's 7/8),
// and that times contrast/κ below (0.15/0.3 = 1/2 between densities 1 and 0.85).
TEST(RiemannMassFlux, AtAContactAtRestItIsThePublishedTermScaledByTheContrastUpToKappa) {
    EXPECT_EQ(RiemannDissipation::contactContrast, 0.3);
    const double published = massFluxOf("type riemann; densityLimiter none;", 1, 0.31, 0.125, 0.3, 0);
    EXPECT_NEAR(massFluxOf("type riemann;", 1, 0.31, 0.125, 0.3, 0), published, 1e-15);
    const double weak = massFluxOf("type riemann; densityLimiter none;", 1, 0.31, 0.85, 0.3, 0);
    EXPECT_NEAR(massFluxOf("type riemann;", 1, 0.31, 0.85, 0.3, 0), 0.5 * weak, 1e-15);
    // The sign follows the pressure jump: the higher-pressure particle loses density.
    EXPECT_LT(massFluxOf("type riemann;", 1, 0.31, 0.125, 0.3, 0), 0);
    EXPECT_GT(massFluxOf("type riemann;", 1, 0.29, 0.125, 0.3, 0), 0);
}

// A shock's pair: ΔP = 0.9, ρ̄ = 1.5, approaching at 0.5: v' = c̄ − ½ b vr = 1.5, so the implied
// velocity jump 0.9/(1.5·1.5) = 0.4 is less than the approach speed and the limited term is zero,
// while the published one is a_ρ·0.9/(1.5·1.5)·F = −0.2. Between equal densities (a diaphragm), zero.
TEST(RiemannMassFlux, AShockOrADiaphragmBetweenEqualDensitiesGetsNone) {
    EXPECT_DOUBLE_EQ(massFluxOf("type riemann; densityLimiter none;", 2, 1, 1, 0.1, -0.5), -0.2);
    EXPECT_EQ(massFluxOf("type riemann;", 2, 1, 1, 0.1, -0.5), 0.0);
    EXPECT_NE(massFluxOf("type riemann; densityLimiter none;", 1, 1, 1, 1e-5, 0), 0.0);
    EXPECT_EQ(massFluxOf("type riemann;", 1, 1, 1, 1e-5, 0), 0.0);
    // A slower approach, 0.2: v' = 1.2, the implied jump 0.9/(1.5·1.2) = 0.5 exceeds it by 0.3; the
    // contrast 1/2 is above κ, so that times a_ρ m_j F = −0.5.
    EXPECT_NEAR(massFluxOf("type riemann;", 2, 1, 1, 0.1, -0.2), -0.5 * 0.3, 1e-15);
}
