// The constitutiveLaw family reads through keyword schemas (core/KeywordSchema.hpp): every
// registered type declares one, with rho0 and the elastic constants of
// ConstitutiveLaw::elasticKeywords(); its defaults read back; each required keyword, removed from a
// valid material, is named in the error; a value outside a keyword's bounds is an error at that
// keyword; and the elastic constants keep their rule of exactly one pair.
#include "materials/constitutive/ConstitutiveLaw.hpp"

#include <gtest/gtest.h>

#include <map>
#include <set>
#include <string>
#include <vector>

namespace mfdyn {
namespace {

struct Entry {
    std::string key, value;
    bool inLaw = false;  // in the law's dictionary, else in the material's
};

// A valid material per type, written as a user writes it (constants in the material, the law's own
// parameters in the law's dictionary).
const std::map<std::string, std::vector<Entry>>& samples() {
    static const std::map<std::string, std::vector<Entry>> s{
        {"linearElastic", {{"rho0", "7000"}, {"youngsModulus", "21e9"}, {"poissonRatio", "0.3"}}},
        {"neoHookean", {{"rho0", "1100"}, {"youngsModulus", "17e6"}, {"poissonRatio", "0.45"}}},
        {"stVenantKirchhoff", {{"rho0", "1500"}, {"youngsModulus", "1e5"}, {"poissonRatio", "0"}}},
        {"neoHookeanLogJ", {{"rho0", "1500"}, {"youngsModulus", "1e5"}, {"poissonRatio", "0.3"}}},
        {"mooneyRivlin",
         {{"rho0", "1100"}, {"youngsModulus", "17e6"}, {"poissonRatio", "0.495"}, {"zeta", "2e6", true}}},
        {"j2Plasticity",
         {{"rho0", "2700"},
          {"shearModulus", "26e9"},
          {"bulkModulus", "70e9"},
          {"yieldStress", "250e6"},
          {"hardeningModulus", "700e6", true}}},
    };
    return s;
}

// The sample of `type` without `without`, with `extra` added to (or replacing one of) the law's
// keywords.
std::unique_ptr<ConstitutiveLaw> build(const std::string& type, const std::string& without = "",
                                       const Entry& extra = {}) {
    std::string material, law = "type " + type + ";";
    for (const Entry& e : samples().at(type)) {
        if (e.key == without || e.key == extra.key) continue;
        (e.inLaw ? law : material) += " " + e.key + " " + e.value + ";";
    }
    if (!extra.key.empty()) law += " " + extra.key + " " + extra.value + ";";
    const Dictionary materials =
        Dictionary::parse("solid { " + material + " constitutiveLaw { " + law + " } }", "test");
    return ConstitutiveLaw::New(materials.subDict("solid").subDict("constitutiveLaw"));
}

std::vector<std::string> registeredTypes() {
    build("neoHookean");  // registrations are made when the library loads; New makes sure it did
    return ConstitutiveLaw::Selector::names();
}

KeywordSchema schemaOf(const std::string& type) {
    const RegistryFamily* family = RegistryIndex::global().findFamily(ConstitutiveLaw::familyName);
    const RegistryItem* item = family ? family->find(type) : nullptr;
    if (!item || !item->keywords) {
        ADD_FAILURE() << "constitutiveLaw type " << type << " declares no keyword schema";
        return {};
    }
    EXPECT_EQ(item->sourceFile.rfind("libraries/materials/constitutive/", 0), 0u) << item->sourceFile;
    return item->keywords();
}

void expectInputError(const std::string& type, const std::string& without, const Entry& extra,
                      const std::vector<std::string>& words) {
    try {
        build(type, without, extra);
        ADD_FAILURE() << type << " built without '" << without << "', with " << extra.key << " "
                      << extra.value;
    } catch (const InputError& e) {
        const std::string what = e.what();
        for (const auto& w : words) EXPECT_NE(what.find(w), std::string::npos) << type << ": " << what;
    }
}

TEST(ConstitutiveLawSchema, EveryTypeDeclaresAKeywordSchema) {
    const auto names = registeredTypes();
    const std::set<std::string> found(names.begin(), names.end());
    for (const char* t : {"linearElastic", "neoHookean", "mooneyRivlin", "j2Plasticity"})
        EXPECT_TRUE(found.count(t)) << t;
    const KeywordSchema elastic = ConstitutiveLaw::elasticKeywords();
    ASSERT_FALSE(elastic.empty());
    for (const auto& type : names) {
        ASSERT_TRUE(samples().count(type)) << "no sample material for " << type;
        const KeywordSchema schema = schemaOf(type);
        EXPECT_FALSE(schema.empty()) << type;
        EXPECT_EQ(schema.family(), "constitutiveLaw");
        EXPECT_EQ(schema.type(), type);
        for (const Keyword& k : schema.keywords()) {
            EXPECT_FALSE(k.meaning.empty()) << type << " " << k.name;
            EXPECT_FALSE(k.unit.empty()) << type << " " << k.name;
        }
        // rho0 and the elastic constants, shared: the same declaration in every law.
        for (const Keyword& k : elastic.keywords()) {
            const Keyword* own = schema.find(k.name);
            ASSERT_NE(own, nullptr) << type << " lacks " << k.name;
            EXPECT_EQ(own->kindText(), k.kindText()) << type << " " << k.name;
            EXPECT_EQ(own->boundsText(), k.boundsText()) << type << " " << k.name;
            EXPECT_TRUE(own->orEnclosing) << type << " " << k.name;
        }
        // Every keyword the sample gives is declared, and the sample builds.
        for (const Entry& e : samples().at(type))
            EXPECT_NE(schema.find(e.key), nullptr) << type << " " << e.key;
        EXPECT_EQ(build(type)->type(), type);
    }
}

// Each default lies inside its bounds and is what a dictionary without the keyword reads.
TEST(ConstitutiveLawSchema, DefaultsReadBack) {
    for (const auto& type : registeredTypes()) {
        const KeywordSchema schema = schemaOf(type);
        for (const Keyword& k : schema.keywords()) {
            if (k.kind != Keyword::Kind::defaulted) continue;
            std::string law = "type " + type + ";";
            for (const Entry& e : samples().at(type))
                if (e.key != k.name) law += " " + e.key + " " + e.value + ";";
            const Dictionary dict = Dictionary::parse(law, "test");
            const KeywordValues v = schema.read(dict);
            EXPECT_FALSE(v.given(k.name)) << type << " " << k.name;
            switch (k.type) {
                case Keyword::Type::scalar: {
                    const double x = v.scalar(k.name);
                    EXPECT_EQ(x, k.defaultNumber) << type << " " << k.name;
                    EXPECT_TRUE((!k.lower || (k.lower->open ? x > k.lower->value : x >= k.lower->value)) &&
                                (!k.upper || (k.upper->open ? x < k.upper->value : x <= k.upper->value)))
                        << type << " " << k.name;
                    break;
                }
                case Keyword::Type::switchValue:
                    EXPECT_EQ(v.flag(k.name), k.defaultValue == "yes") << type << " " << k.name;
                    break;
                case Keyword::Type::word:
                    EXPECT_EQ(v.word(k.name), k.defaultValue) << type << " " << k.name;
                    break;
                default:
                    ADD_FAILURE() << type << " " << k.name << ": a default of an unexpected type";
            }
            EXPECT_NO_THROW(build(type, k.name)) << type << " without " << k.name;
        }
    }
}

TEST(ConstitutiveLawSchema, RequiredKeywordsAreNamedWhenMissing) {
    for (const auto& type : registeredTypes()) {
        const KeywordSchema schema = schemaOf(type);
        int required = 0;
        for (const Keyword& k : schema.keywords()) {
            if (k.kind != Keyword::Kind::required) continue;
            ++required;
            expectInputError(type, k.name, {}, {"missing keyword '" + k.name + "'", "solid"});
        }
        EXPECT_GE(required, 1) << type << ": rho0 at least";
    }
}

// A value at an open bound, or beyond a closed one, is an error at the keyword.
TEST(ConstitutiveLawSchema, ValuesOutsideTheBoundsAreNamed) {
    for (const auto& type : registeredTypes()) {
        const KeywordSchema schema = schemaOf(type);
        for (const Keyword& k : schema.keywords()) {
            if (k.type != Keyword::Type::scalar) continue;
            std::vector<double> outside;
            if (k.lower) outside.push_back(k.lower->open ? k.lower->value : k.lower->value - 1.0);
            if (k.upper) outside.push_back(k.upper->open ? k.upper->value : k.upper->value + 1.0);
            for (double x : outside)
                expectInputError(type, "", {k.name, formatKeywordNumber(x), true},
                                 {"keyword '" + k.name + "'"});
        }
    }
}

// The elastic constants stay optional keywords with a rule across them: exactly one of the pairs
// (youngsModulus, poissonRatio), (shearModulus, bulkModulus).
TEST(ConstitutiveLawSchema, ExactlyOnePairOfElasticConstants) {
    for (const auto& type : registeredTypes()) {
        bool engineering = false;  // the sample gives youngsModulus and poissonRatio
        for (const Entry& e : samples().at(type)) engineering = engineering || e.key == "youngsModulus";
        const std::string half = engineering ? "poissonRatio" : "bulkModulus";
        const std::string kept = engineering ? "youngsModulus" : "shearModulus";
        expectInputError(type, half, {}, {"inconsistent elastic constants", "'" + kept + "'", "solid"});
        const Entry other =
            engineering ? Entry{"shearModulus", "6e6", true} : Entry{"youngsModulus", "7e10", true};
        expectInputError(type, "", other, {"inconsistent elastic constants", "'" + other.key + "'"});
    }
}

}  // namespace
}  // namespace mfdyn
