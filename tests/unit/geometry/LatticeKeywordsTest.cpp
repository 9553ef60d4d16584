// The lattice family's keyword schemas: every type declares spacing, jitter and seed (nodal also
// points, with spacing optional); defaults jitter 0 and seed 1; a jitter of half a spacing or more
// (points could swap places) and a spacing <= 0 are InputErrors naming the entry.
#include "core/Dictionary.hpp"
#include "core/Error.hpp"
#include "core/Registry.hpp"
#include "geometry/CubicLattice.hpp"
#include "geometry/HcpLattice.hpp"
#include "geometry/HexagonalLattice.hpp"
#include "geometry/MaterialPointLattice.hpp"
#include "geometry/NodalLattice.hpp"

#include "../SchemaTestTools.hpp"

#include <gtest/gtest.h>

#include <string>

using namespace mfdyn;

namespace {

std::string errorOf(const std::string& text, int dimension) {
    return test::inputErrorOf([&] { Lattice::New(Dictionary::parse(text, "lattice"), dimension); }, text);
}

}  // namespace

TEST(LatticeKeywords, EveryTypeDeclaresSpacingJitterAndSeed) {
    const auto schemas = {CubicLattice::keywords(), HexagonalLattice::keywords(), HcpLattice::keywords(),
                          NodalLattice::keywords(), MaterialPointLattice::keywords()};
    test::expectRegisteredSchemas(Lattice::familyName, schemas, "libraries/geometry/");
    for (const KeywordSchema& schema : schemas) {
        for (const char* name : {"spacing", "jitter", "seed"}) ASSERT_NE(schema.find(name), nullptr) << name;
        EXPECT_EQ(schema.find("spacing")->kind, schema.type() == "nodal" || schema.type() == "materialPoints"
                                                    ? Keyword::Kind::optional
                                                    : Keyword::Kind::required);
        EXPECT_EQ(schema.find("jitter")->defaultValue, "0");
        EXPECT_EQ(schema.find("seed")->defaultValue, "1");
    }
    EXPECT_NE(NodalLattice::keywords().find("points"), nullptr);
    const auto cubic = Lattice::New(Dictionary::parse("type cubic; spacing 0.1;", "lattice"), 2);
    EXPECT_EQ(cubic->spacing(), 0.1);
    EXPECT_EQ(cubic->jitter(), 0.0);
}

TEST(LatticeKeywords, BadEntriesNameTheEntry) {
    const std::string jitter = errorOf("type cubic; spacing 0.1; jitter 0.5;", 2);
    EXPECT_NE(jitter.find("keyword 'jitter'"), std::string::npos) << jitter;
    EXPECT_NE(jitter.find("< 0.5"), std::string::npos) << jitter;
    const std::string spacing = errorOf("type hcp; spacing 0;", 3);
    EXPECT_NE(spacing.find("keyword 'spacing'"), std::string::npos) << spacing;
    const std::string missing = errorOf("type hexagonal;", 2);
    EXPECT_NE(missing.find("missing keyword 'spacing'"), std::string::npos) << missing;
    const std::string dimension = errorOf("type hexagonal; spacing 0.1;", 3);
    EXPECT_NE(dimension.find("2D"), std::string::npos) << dimension;
}
