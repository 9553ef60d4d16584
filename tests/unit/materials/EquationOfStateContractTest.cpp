// The family contract (EquationOfState.hpp) for every registered type, each with a sample
// parameter set: reference pressure, c^2 > 0 and c^2 = dP/drho|_s, g = dP/de|_rho and
// dP/drho|_e against differences of P, the block form equal to the scalar one, and an error naming
// each missing required keyword.
#include "EquationOfStateTestTools.hpp"
#include "materials/equationOfState/EquationOfState.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>

namespace mfdyn {
namespace {

using test::dictionaryText;
using test::eosSamples;
using test::makeEos;

TEST(EquationOfStateContract, EveryRegisteredTypeHasASample) {
    std::set<std::string> sampled;
    for (const auto& s : eosSamples()) sampled.insert(s.type);
    // New once first, so that the library is loaded and its registrations made.
    makeEos("type idealGas; gamma 1.4;");
    for (const auto& name : EquationOfState::Selector::names())
        EXPECT_TRUE(sampled.count(name)) << "no contract sample for registered type " << name;
    EXPECT_EQ(sampled.size(), 9u);
}

TEST(EquationOfStateContract, ReferencePressure) {
    for (const auto& s : eosSamples()) {
        const auto eos = makeEos(dictionaryText(s));
        EXPECT_EQ(eos->type(), s.type);
        // Round-off of a few operations on numbers of size rho0 c0^2 (or the pressure itself).
        const double scale = std::max({std::abs(s.referencePressure), 1.0});
        EXPECT_NEAR(eos->pressure(eos->referenceDensity(), 0.0), s.referencePressure, 1e-12 * scale)
            << s.type;
    }
}

TEST(EquationOfStateContract, SoundSpeedIsPositiveAndIsentropic) {
    for (const auto& s : eosSamples()) {
        const auto eos = makeEos(dictionaryText(s));
        for (const auto& [rho, e] : s.states) {
            const double c2 = eos->soundSpeedSquared(rho, e);
            EXPECT_GT(c2, 0.0) << s.type << " at rho " << rho << ", e " << e;
            // h = 1e-4 rho: truncation (h/rho)^2 ~ 1e-8 times O(10) derivative ratios, round-off
            // 2e-16 |P| / (h c^2) below 1e-10 for these states; 1e-6 leaves room for both.
            const double numeric = test::isentropicDerivative(*eos, rho, e, 1e-4 * rho);
            EXPECT_NEAR(c2, numeric, 1e-6 * std::abs(numeric)) << s.type << " at rho " << rho << ", e " << e;
        }
    }
}

// g = energyDerivative against a central difference of P in e, dP/drho|_e = densityDerivative
// against one in rho, and the identity c^2 = dP/drho|_e + P g / rho^2.
TEST(EquationOfStateContract, PartialDerivativesMatchDifferencesOfPressure) {
    for (const auto& s : eosSamples()) {
        const auto eos = makeEos(dictionaryText(s));
        for (const auto& [rho, e] : s.states) {
            const double p = eos->pressure(rho, e), c2 = eos->soundSpeedSquared(rho, e);
            const double g = eos->energyDerivative(rho, e), pRho = eos->densityDerivative(rho, e);
            if (!eos->needsEnergy()) {
                EXPECT_EQ(g, 0.0) << s.type;
            }
            // Step in e: 1e-4 of |e| or, at e = 0, of c^2 (an energy per mass of the state's scale).
            // Truncation (h/e)^2 e^2 P_eee / P_e ~ 1e-8 (P is linear in e except for tillotson's
            // omega, whose scale is E0 >= e), plus the round-off bound: 1e-6 leaves room for both.
            const double hE = 1e-4 * std::max(std::abs(e), c2);
            const auto dE = test::energyDifference(*eos, rho, e, hE);
            EXPECT_NEAR(g, dE.value, 1e-6 * std::abs(dE.value) + dE.roundOff)
                << s.type << " at rho " << rho << ", e " << e;
            // Step in rho 1e-4 rho, as for the isentropic derivative.
            const auto dRho = test::densityDifference(*eos, rho, e, 1e-4 * rho);
            EXPECT_NEAR(pRho, dRho.value, 1e-6 * std::abs(dRho.value) + dRho.roundOff)
                << s.type << " at rho " << rho << ", e " << e;
            // The identity: densityDerivative is c^2 - P g / rho^2, so this is the round-off of one
            // subtraction and one addition on numbers of size c^2 and |P g| / rho^2.
            const double pg = p * g / (rho * rho);
            EXPECT_NEAR(pRho + pg, c2, 4e-16 * (std::abs(c2) + std::abs(pg)))
                << s.type << " at rho " << rho << ", e " << e;
        }
    }
}

// Where a tension cut-off holds P at pMin, P does not depend on e: g = 0 there, and
// densityDerivative is the uncut c^2 (EquationOfState.hpp).
TEST(EquationOfStateContract, EnergyDerivativeIsZeroWherePressureIsCut) {
    const std::string al2 = "type mieGruneisen; rho0 2785; c0 5330; s 1.338; gamma0 2; ";
    const std::string tillotson =
        "type tillotson; rho0 2700; A 75.2e9; B 65e9; a 0.5; b 1.63; alpha 5; beta 5; E0 5e6; Eiv 3e6; "
        "Ecv 13.9e6; ";
    for (const std::string& model : {al2, tillotson}) {
        const auto cut = makeEos(model + "minimumPressure -1e9;");
        const auto uncut = makeEos(model);
        // Cold tension of 10%: P_uncut ~ -7e9 Pa, well below the cut-off.
        const double rho = 0.9 * cut->referenceDensity(), e = 1e4;
        ASSERT_LT(uncut->pressure(rho, e), -1e9);
        EXPECT_EQ(cut->pressure(rho, e), -1e9);
        EXPECT_EQ(cut->energyDerivative(rho, e), 0.0) << model;
        EXPECT_EQ(test::energyDifference(*cut, rho, e, 1e2).value, 0.0) << model;
        EXPECT_EQ(cut->soundSpeedSquared(rho, e), uncut->soundSpeedSquared(rho, e)) << model;
        EXPECT_EQ(cut->densityDerivative(rho, e), uncut->soundSpeedSquared(rho, e)) << model;
        EXPECT_GT(uncut->energyDerivative(rho, e), 0.0) << model;
        // In compression the cut-off changes nothing.
        const double rhoC = 1.1 * cut->referenceDensity();
        EXPECT_EQ(cut->energyDerivative(rhoC, e), uncut->energyDerivative(rhoC, e)) << model;
    }
}

TEST(EquationOfStateContract, BlockFormEqualsScalarForm) {
    for (const auto& s : eosSamples()) {
        const auto eos = makeEos(dictionaryText(s));
        std::vector<double> rho, e;
        for (const auto& [r, en] : s.states) rho.push_back(r), e.push_back(en);
        std::vector<double> p(rho.size()), c(rho.size());
        eos->evaluate(rho.size(), rho.data(), e.data(), p.data(), c.data());
        for (std::size_t i = 0; i < rho.size(); ++i) {
            // The same formulas, possibly inlined differently: equal to a few ulps.
            EXPECT_NEAR(p[i], eos->pressure(rho[i], e[i]), 1e-14 * std::abs(p[i]) + 1e-300) << s.type;
            EXPECT_NEAR(c[i], std::sqrt(eos->soundSpeedSquared(rho[i], e[i])), 1e-14 * c[i]) << s.type;
        }
        if (!eos->needsEnergy()) {
            // Barotropic models accept e = nullptr.
            eos->evaluate(rho.size(), rho.data(), nullptr, p.data(), c.data());
            for (std::size_t i = 0; i < rho.size(); ++i)
                EXPECT_NEAR(p[i], eos->pressure(rho[i], 0.0), 1e-14 * std::abs(p[i])) << s.type;
        }
    }
}

TEST(EquationOfStateContract, BarotropicModelsNeedNoEnergy) {
    for (const auto& s : eosSamples()) {
        const bool barotropic = s.type == "linearBarotropic" || s.type == "tait" || s.type == "polytropic";
        EXPECT_EQ(makeEos(dictionaryText(s))->needsEnergy(), !barotropic) << s.type;
    }
}

TEST(EquationOfStateContract, MissingRequiredKeywordIsNamed) {
    for (const auto& s : eosSamples()) {
        for (const auto& key : s.required) {
            try {
                makeEos(dictionaryText(s, key));
                ADD_FAILURE() << s.type << " built without required '" << key << "'";
            } catch (const InputError& error) {
                EXPECT_NE(std::string(error.what()).find("'" + key + "'"), std::string::npos)
                    << s.type << ": " << error.what();
            }
        }
    }
}

// Every type reads through a keyword schema (core/KeywordSchema.hpp) registered with it; the
// schema's required keywords are the sample's, and each, removed, is named in the error.
TEST(EquationOfStateContract, EveryTypeDeclaresAKeywordSchema) {
    makeEos("type idealGas; gamma 1.4;");
    const RegistryFamily* family = RegistryIndex::global().findFamily(EquationOfState::familyName);
    ASSERT_NE(family, nullptr);
    for (const auto& s : eosSamples()) {
        const RegistryItem* item = family->find(s.type);
        ASSERT_NE(item, nullptr) << s.type;
        ASSERT_NE(item->keywords, nullptr) << s.type << " declares no keyword schema";
        const KeywordSchema schema = item->keywords();
        EXPECT_EQ(schema.family(), "equationOfState");
        EXPECT_EQ(schema.type(), s.type);
        EXPECT_EQ(item->sourceFile.rfind("libraries/materials/equationOfState/", 0), 0u) << item->sourceFile;
        std::set<std::string> required, sampled(s.required.begin(), s.required.end());
        for (const Keyword& k : schema.keywords()) {
            EXPECT_FALSE(k.meaning.empty()) << s.type << " " << k.name;
            EXPECT_FALSE(k.unit.empty()) << s.type << " " << k.name;
            if (k.kind != Keyword::Kind::required) continue;
            required.insert(k.name);
            try {
                makeEos(dictionaryText(s, k.name));
                ADD_FAILURE() << s.type << " built without required '" << k.name << "'";
            } catch (const InputError& error) {
                EXPECT_NE(std::string(error.what()).find("missing keyword '" + k.name + "'"),
                          std::string::npos)
                    << s.type << ": " << error.what();
            }
        }
        EXPECT_EQ(required, sampled) << s.type;
        // Every keyword the sample gives is declared.
        for (const auto& [key, value] : s.keywords)
            EXPECT_NE(schema.find(key), nullptr) << s.type << " " << key;
    }
}

TEST(EquationOfStateContract, UnknownTypeListsTheValidOnes) {
    try {
        makeEos("type mieGrunesen; rho0 2785; c0 5330; s 1.338; gamma0 2;");
        FAIL() << "unknown type accepted";
    } catch (const InputError& error) {
        const std::string what = error.what();
        EXPECT_NE(what.find("did you mean 'mieGruneisen'"), std::string::npos) << what;
        for (const auto& s : eosSamples()) EXPECT_NE(what.find(s.type), std::string::npos) << what;
    }
    EXPECT_THROW(makeEos("rho0 1000; c0 10;"), InputError);  // no type at all
}

}  // namespace
}  // namespace mfdyn
