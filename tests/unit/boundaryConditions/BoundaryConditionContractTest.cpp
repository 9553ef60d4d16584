// Family contract over every registered boundaryCondition type, in 1, 2 and 3 dimensions: it
// builds from a minimal dictionary through New, reports its type, and its hooks touch no particle
// outside its selection. A new type fails here until it is given a minimal dictionary below.
#include "BoundaryConditionTestTools.hpp"

#include <gtest/gtest.h>

#include <map>

using namespace mfdyn;
using mfdyn::test::condition;
using mfdyn::test::lattice;

namespace {

// Selections restricted to the particles with x < 0.25 (SHAPE, a box written for the dimension),
// so that the rest must stay as they were.
const std::map<std::string, std::string> minimalBody{
    {"free", "SHAPE"},
    {"fixed", "SHAPE"},
    {"prescribedVelocity", "SHAPE velocity (1 0 0);"},
    {"symmetryPlane", "SHAPE point (0.1 0 0); normal (1 0 0);"},
    {"rigidPlanarWall", "SHAPE point (0.1 0 0); normal (1 0 0);"},
    {"mirrorPlane", "SHAPE point (0 0 0); normal (1 0 0);"},
    {"skewSymmetricPlane", "SHAPE point (0.1 0 0); normal (1 0 0);"},
    {"prescribedTraction", "SHAPE traction (1 0 0); area 2;"},
    {"linearVelocity", "SHAPE gradient (2 0 0 0 0 0 0 0 0); velocity (1 0 0);"},
};

template <int Dim>
void checkContract(const std::string& type) {
    SCOPED_TRACE(type + " in " + std::to_string(Dim) + "D");
    const auto it = minimalBody.find(type);
    ASSERT_NE(it, minimalBody.end()) << "give the new type '" << type << "' a minimal dictionary here";
    auto p = lattice<Dim>(6, 0.1);
    p.scalarField("mass").assign(p.size(), 2.0);  // for the conditions that need volumes
    p.scalarField("density").assign(p.size(), 1000.0);
    const auto x0 = p.position();
    const auto v0 = p.vectorField("velocity");
    const auto a0 = p.vectorField("acceleration");
    std::string body = it->second;
    const std::string box = Dim == 1   ? "shape { type box; min (-1); max (0.25); }"
                            : Dim == 2 ? "shape { type box; min (-1 -1); max (0.25 2); }"
                                       : "shape { type box; min (-1 -1 -1); max (0.25 2 2); }";
    body.replace(body.find("SHAPE"), 5, box);
    auto bc = condition<Dim>("type " + type + "; " + body, p);
    EXPECT_EQ(bc->type(), type);
    EXPECT_EQ(bc->selection().size(), p.size() / 6 * 3);  // x = 0, 0.1, 0.2
    std::vector<Vector<Dim>> force(p.size(), Vector<Dim>::Zero());
    bc->addBoundaryForce(p, force, 0.0);
    bc->constrainAcceleration(p, p.vectorField("acceleration"), 0.0);
    bc->constrainVelocity(p, 0.0);
    bc->constrainPosition(p, 0.0);
    GhostBlock<Dim> ghosts;
    bc->appendGhosts(p, p.vectorField("velocity"), 0.1, 0.0, ghosts);
    EXPECT_EQ(ghosts.size(), ghosts.position.size());
    EXPECT_EQ(ghosts.size(), ghosts.velocity.size());
    EXPECT_EQ(ghosts.size(), ghosts.map.size());
    EXPECT_EQ(ghosts.size(), ghosts.parity.size());  // the reflections read it
    EXPECT_EQ(ghosts.empty(), !bc->makesGhosts());
    for (std::size_t i = 0; i < p.size(); ++i) {
        if (x0[i][0] < 0.25) continue;
        EXPECT_EQ(p.position()[i], x0[i]) << i;
        EXPECT_EQ(p.vectorField("velocity")[i], v0[i]) << i;
        EXPECT_EQ(p.vectorField("acceleration")[i], a0[i]) << i;
        EXPECT_TRUE(force[i].isZero()) << i;
    }
    for (auto s : ghosts.source) EXPECT_LT(x0[s][0], 0.25);
}

}  // namespace

TEST(BoundaryConditionContract, EveryTypeInEveryDimensionActsOnItsSelectionOnly) {
    const auto names = BoundaryCondition<1>::Selector::names();
    ASSERT_GE(names.size(), 8u);
    for (const auto& type : names) {
        checkContract<1>(type);
        checkContract<2>(type);
        checkContract<3>(type);
    }
}
