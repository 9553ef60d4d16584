#pragma once
// Shared by the keyword-schema contract tests of the model families (tests/unit/<library>/):
// the message of the InputError a construction raises, and the checks every family's schemas
// pass (registered with the family, declared in the library's sources, every keyword explained).
#include "core/Error.hpp"
#include "core/KeywordSchema.hpp"
#include "core/Registry.hpp"

#include <gtest/gtest.h>

#include <functional>
#include <initializer_list>
#include <string>

namespace mfdyn::test {

// The message of the InputError that `construct` raises; "" and a test failure if none.
inline std::string inputErrorOf(const std::function<void()>& construct, const std::string& what) {
    try {
        construct();
    } catch (const InputError& error) {
        return error.what();
    }
    ADD_FAILURE() << "accepted: " << what;
    return "";
}

// Each schema is the one registered for its type in `family`, from a source file under
// `sourceDirectory` (e.g. "libraries/sph/"), and every keyword has a meaning and a unit. `method`:
// the methodName of a method-scoped family ("" for a shared one).
inline void expectRegisteredSchemas(const char* family, std::initializer_list<KeywordSchema> schemas,
                                    const std::string& sourceDirectory, const char* method = "") {
    const RegistryFamily* registered = RegistryIndex::global().findFamily(family, method);
    ASSERT_NE(registered, nullptr) << family;
    for (const KeywordSchema& schema : schemas) {
        EXPECT_EQ(schema.family(), family);
        const RegistryItem* item = registered->find(schema.type());
        ASSERT_NE(item, nullptr) << schema.type();
        ASSERT_NE(item->keywords, nullptr) << schema.type() << " declares no keyword schema";
        EXPECT_EQ(item->keywords().keywords().size(), schema.keywords().size()) << schema.type();
        EXPECT_EQ(item->sourceFile.rfind(sourceDirectory, 0), 0u) << item->sourceFile;
        for (const Keyword& k : schema.keywords()) {
            EXPECT_FALSE(k.meaning.empty()) << schema.type() << " " << k.name;
            EXPECT_FALSE(k.unit.empty()) << schema.type() << " " << k.name;
        }
    }
}

// `schema` ends with the keywords of `common`, in their order (a family's shared keywords appended
// after each type's own).
inline void expectEndsWith(const KeywordSchema& schema, const KeywordSchema& common) {
    SCOPED_TRACE(schema.type());
    const auto& k = schema.keywords();
    ASSERT_GE(k.size(), common.keywords().size());
    const std::size_t own = k.size() - common.keywords().size();
    for (std::size_t i = 0; i < common.keywords().size(); ++i)
        EXPECT_EQ(k[own + i].name, common.keywords()[i].name);
}

}  // namespace mfdyn::test
