// The boundaryCondition family's keyword schemas: every type declares the selection keywords
// (regions, shape, all, reselect) and releaseTime after its own; the plane conditions declare
// point, normal and tolerance; prescribedVelocity and prescribedTraction their constant or table.
// Bad entries are InputErrors naming the entry, the bound or the valid form.
#include "boundaryConditions/Fixed.hpp"
#include "boundaryConditions/Free.hpp"
#include "boundaryConditions/MirrorPlane.hpp"
#include "boundaryConditions/PrescribedTraction.hpp"
#include "boundaryConditions/PrescribedVelocity.hpp"
#include "boundaryConditions/RigidPlanarWall.hpp"
#include "boundaryConditions/SkewSymmetricPlane.hpp"
#include "boundaryConditions/SymmetryPlane.hpp"

#include "../SchemaTestTools.hpp"
#include "BoundaryConditionTestTools.hpp"

#include <gtest/gtest.h>

#include <string>

using namespace mfdyn;

namespace {

std::string errorOf(const std::string& text) {
    auto p = test::lattice<2>(6, 0.1);
    p.scalarField("mass").assign(p.size(), 2.0);
    p.scalarField("density").assign(p.size(), 1000.0);
    return test::inputErrorOf([&] { test::condition<2>(text, p); }, text);
}

void expectMessage(const std::string& message, const std::string& part) {
    EXPECT_NE(message.find(part), std::string::npos) << "'" << part << "' not in: " << message;
}

}  // namespace

TEST(BoundaryConditionKeywords, EveryTypeDeclaresItsKeywordsThenTheCommonOnes) {
    const auto schemas = {Fixed<3>::keywords(),
                          Free<3>::keywords(),
                          MirrorPlane<3>::keywords(),
                          PrescribedTraction<3>::keywords(),
                          PrescribedVelocity<3>::keywords(),
                          RigidPlanarWall<3>::keywords(),
                          SkewSymmetricPlane<3>::keywords(),
                          SymmetryPlane<3>::keywords()};
    test::expectRegisteredSchemas("boundaryCondition", schemas, "libraries/boundaryConditions/");
    const KeywordSchema common = commonBoundaryConditionKeywords();
    for (const KeywordSchema& schema : schemas) {
        test::expectEndsWith(schema, common);
        const bool plane =
            schema.type().find("Plane") != std::string::npos || schema.type() == "rigidPlanarWall";
        for (const char* name : {"point", "normal", "tolerance"})
            EXPECT_EQ(schema.find(name) != nullptr, plane) << schema.type() << " " << name;
    }
    EXPECT_EQ(common.find("regions")->type, Keyword::Type::wordList);
    EXPECT_EQ(common.find("reselect")->kind, Keyword::Kind::optional);
    EXPECT_EQ(MirrorPlane<3>::keywords().find("thicknessFactor")->defaultValue, "3");
    EXPECT_EQ(PrescribedVelocity<3>::keywords().find("table")->type, Keyword::Type::table);
    EXPECT_EQ(PrescribedTraction<3>::keywords().find("area")->kind, Keyword::Kind::required);
    // The documentation excerpt shows a valid plane, not the zero normal of the default rule.
    EXPECT_EQ(planeKeywords().find("normal")->sampleValue(), "(1 0 0)");
    EXPECT_EQ(planeKeywords().find("point")->sampleValue(), "(0 0 0)");
}

TEST(BoundaryConditionKeywords, ValuesReadThroughTheSchema) {
    auto p = test::lattice<2>(6, 0.1);
    auto wall =
        test::condition<2>("type rigidPlanarWall; point (0 0.05 0); normal (0 2 0); releaseTime 1e-3;", p);
    EXPECT_EQ(wall->releaseTime(), 1e-3);
    auto* rigid = dynamic_cast<RigidPlanarWall<2>*>(wall.get());
    ASSERT_NE(rigid, nullptr);
    EXPECT_EQ(rigid->plane().normal(), Vector<2>(0, 1));  // normalised
    EXPECT_EQ(rigid->plane().point(), Vector<2>(0, 0.05));
    auto mirror = test::condition<2>("type mirrorPlane; point (0 0); normal (1 0); regions (wall);", p);
    auto* m = dynamic_cast<MirrorPlane<2>*>(mirror.get());
    ASSERT_NE(m, nullptr);
    EXPECT_EQ(m->thickness(0.5), 1.5);  // thicknessFactor 3 by default
    EXPECT_FALSE(m->noSlip());
    EXPECT_EQ(mirror->selection().size(), 12u);  // region wall: the rows y = 0 and 0.1
}

TEST(BoundaryConditionKeywords, BadEntriesNameTheEntry) {
    const std::string restitution =
        errorOf("type rigidPlanarWall; point (0 0); normal (0 1); restitution 2;");
    expectMessage(restitution, "keyword 'restitution'");
    expectMessage(restitution, "<= 1");
    const std::string release = errorOf("type fixed; all yes; releaseTime -1;");
    expectMessage(release, "keyword 'releaseTime'");
    const std::string point = errorOf("type symmetryPlane; point (0); normal (1 0);");
    expectMessage(point, "expected a list of 2 reals, found 1 values");
    const std::string extra = errorOf("type symmetryPlane; point (0 0 1); normal (1 0);");
    expectMessage(extra, "component 3 is non-zero");
    const std::string missing = errorOf("type mirrorPlane; normal (1 0);");
    expectMessage(missing, "missing keyword 'point'");
    const std::string both =
        errorOf("type mirrorPlane; point (0 0); normal (1 0); thickness 0.1; thicknessFactor 2;");
    expectMessage(both, "not both");
    const std::string regions = errorOf("type fixed; regions ();");
    expectMessage(regions, "expected at least one name");
    const std::string unknown = errorOf("type fixed; regions (wal);");
    expectMessage(unknown, "did you mean 'wall'");
    const std::string area = errorOf("type prescribedTraction; all yes; traction (1 0);");
    expectMessage(area, "missing keyword 'area'");
    const std::string table = errorOf("type prescribedVelocity; all yes; velocity (1 0); table ((0 (1 0)));");
    expectMessage(table, "give exactly one of");
    const std::string noSlip = errorOf("type mirrorPlane; point (0 0); normal (1 0); noSlip maybe;");
    expectMessage(noSlip, "noSlip");
}
