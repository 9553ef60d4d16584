// constant/boundaryConditions read as a whole: construction order, look-up, hooks forwarded in
// order, and the errors a user meets.
#include "BoundaryConditionTestTools.hpp"

#include <gtest/gtest.h>

using namespace mfdyn;
using mfdyn::test::conditions;
using mfdyn::test::inputErrorOf;
using mfdyn::test::lattice;

TEST(BoundaryConditionList, BuildsEveryConditionInOrder) {
    const auto p = lattice<2>();
    const auto bcs = conditions<2>(R"(
        boundaryConditions
        {
            chamber   { type fixed;              regions (wall); }
            xSymmetry { type symmetryPlane;      point (0 0); normal (1 0); }
            lid       { type prescribedVelocity; shape { type box; min (-1 0.95); max (2 2); }
                        velocity (1 0); releaseTime 0.5; }
        })",
                                   p);
    ASSERT_EQ(bcs.size(), 3u);
    EXPECT_EQ(bcs[0].name(), "chamber");
    EXPECT_EQ(bcs[1].type(), "symmetryPlane");
    EXPECT_EQ(bcs[2].selection().size(), 11u);
    ASSERT_NE(bcs.find("lid"), nullptr);
    EXPECT_EQ(bcs.find("lid")->releaseTime(), 0.5);
    EXPECT_EQ(bcs.find("nothing"), nullptr);
    EXPECT_FALSE(bcs.makesGhosts());
    EXPECT_NE(bcs.summary().find("chamber: fixed on regions (wall), 22 particles"), std::string::npos);
}

TEST(BoundaryConditionList, HooksApplyInTheOrderWritten) {
    auto p = lattice<2>();
    // The corner particle (0, 0) is in the wall region and on the symmetry plane: the later
    // prescribedVelocity on the same region overrides the fixed one, and the symmetry plane after
    // it removes the x component there.
    auto bcs = conditions<2>(R"(
        boundaryConditions
        {
            chamber { type fixed; regions (wall); }
            belt    { type prescribedVelocity; regions (wall); velocity (3 4); }
            sym     { type symmetryPlane; point (0 0); normal (1 0); }
        })",
                             p);
    bcs.constrainVelocity(p, 0.0);
    const auto& v = p.vectorField("velocity");
    EXPECT_EQ(v[0], Vector<2>(0, 4));
    EXPECT_EQ(v[1], Vector<2>(3, 4));
}

TEST(BoundaryConditionList, EmptyOrMissingListIsNoConditions) {
    auto p = lattice<2>();
    const auto v0 = p.vectorField("velocity");
    auto bcs = conditions<2>("boundaryConditions { }", p);
    EXPECT_TRUE(bcs.empty());
    bcs.constrainVelocity(p, 0.0);
    EXPECT_EQ(p.vectorField("velocity"), v0);
    EXPECT_TRUE(BoundaryConditionList<2>().ghosts(p, v0, 0.1, 0.0).empty());
}

TEST(BoundaryConditionList, UpdateSelectionsFollowsAReorder) {
    auto p = lattice<2>();
    auto bcs = conditions<2>("boundaryConditions { chamber { type fixed; regions (wall); } }", p);
    std::vector<std::size_t> order(p.size());
    for (std::size_t i = 0; i < order.size(); ++i) order[i] = order.size() - 1 - i;
    p.reorder(order);
    bcs.updateSelections(p);
    bcs.constrainVelocity(p, 0.0);
    const auto& v = p.vectorField("velocity");
    for (std::size_t i = 0; i < p.size(); ++i) EXPECT_EQ(v[i].isZero(), p.region()[i] == 1) << i;
}

TEST(BoundaryConditionList, PlainEntryAndMissingTypeAreInputErrors) {
    const auto p = lattice<2>();
    std::string message = inputErrorOf([&] { conditions<2>("boundaryConditions { wall fixed; }", p); });
    EXPECT_NE(message.find("wall"), std::string::npos) << message;
    message = inputErrorOf([&] { conditions<2>("boundaryConditions { wall { regions (wall); } }", p); });
    EXPECT_NE(message.find("type"), std::string::npos) << message;
    EXPECT_NE(message.find("rigidPlanarWall"), std::string::npos) << message;
}
