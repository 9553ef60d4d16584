// The bodyForce family reads through keyword schemas: every registered type declares one, and each
// required keyword, removed from a valid dictionary, is named in the error.
#include "core/Application.hpp"
#include "solver/BodyForce.hpp"

#include <gtest/gtest.h>

#include <map>

namespace mfdyn {
namespace {

// A valid dictionary body per type (without `type`).
const std::map<std::string, std::string> samples{{"uniformGravity", "g (0 -9.81 0);"}};

TEST(BodyForceKeywords, EveryTypeDeclaresAKeywordSchema) {
    loadToolkitLibraries();  // the registrations of libmfdyn_solver
    const RegistryFamily* family = RegistryIndex::global().findFamily(BodyForce::familyName);
    ASSERT_NE(family, nullptr);
    for (const auto& type : family->names()) {
        const RegistryItem* item = family->find(type);
        if (item->library.rfind("libmfdyn_", 0) != 0) continue;  // user libraries
        ASSERT_NE(item->keywords, nullptr) << type << " declares no keyword schema";
        ASSERT_TRUE(samples.count(type)) << "no sample dictionary for " << type;
        const KeywordSchema schema = item->keywords();
        EXPECT_NE(BodyForce::New(Dictionary::parse("type " + type + "; " + samples.at(type), "test"), 3),
                  nullptr);
        for (const Keyword& k : schema.keywords()) {
            if (k.kind != Keyword::Kind::required) continue;
            try {
                BodyForce::New(Dictionary::parse("type " + type + ";", "test"), 3);
                ADD_FAILURE() << type << " built without required " << k.name;
            } catch (const InputError& e) {
                EXPECT_NE(std::string(e.what()).find("missing keyword '" + k.name + "'"), std::string::npos)
                    << e.what();
            }
        }
    }
}

TEST(BodyForceKeywords, UniformGravityChecksItsVector) {
    loadToolkitLibraries();
    EXPECT_THROW(BodyForce::New(Dictionary::parse("type uniformGravity; g (0 -9.81);", "test"), 3),
                 InputError);
    EXPECT_THROW(BodyForce::New(Dictionary::parse("type uniformGravity; g (0 -9.81 1);", "test"), 2),
                 InputError);
    EXPECT_THROW(BodyForce::New(Dictionary::parse("type uniformGravity; g 9.81;", "test"), 1), InputError);
}

}  // namespace
}  // namespace mfdyn
