// skewSymmetricPlane: v <- (v·n) n and a <- (a·n) n on the particles picked on the plane when
// the condition is built; they stay picked after moving off it and through reorders. The
// constraint is one projection: exact for an axis-aligned normal, a few ulps for an oblique one.
#include "BoundaryConditionTestTools.hpp"
#include "boundaryConditions/SkewSymmetricPlane.hpp"

#include <gtest/gtest.h>

#include <set>

using namespace mfdyn;
using mfdyn::test::condition;
using mfdyn::test::conditions;
using mfdyn::test::inputErrorOf;
using mfdyn::test::lattice;

namespace {
constexpr double roundOff = 1e-14;
}

TEST(SkewSymmetricPlane, ZeroesTheTangentialComponentsAndKeepsTheNormalOne) {
    auto p = lattice<3>(5, 0.25);  // the unit cube, nodes on its faces
    const auto v0 = p.vectorField("velocity");
    const auto a0 = p.vectorField("acceleration");
    auto bc = condition<3>("type skewSymmetricPlane; point (1 0 0); normal (-1 0 0);", p);  // X = 1
    bc->constrainVelocity(p, 0.0);
    bc->constrainAcceleration(p, p.vectorField("acceleration"), 0.0);
    const auto& v = p.vectorField("velocity");
    const auto& a = p.vectorField("acceleration");
    std::size_t onPlane = 0;
    for (std::size_t i = 0; i < p.size(); ++i) {
        if (p.position()[i][0] == 1.0) {
            ++onPlane;
            EXPECT_EQ(v[i], Vector<3>(v0[i][0], 0, 0)) << i;
            EXPECT_EQ(a[i], Vector<3>(a0[i][0], 0, 0)) << i;
        } else {
            EXPECT_EQ(v[i], v0[i]) << i;
            EXPECT_EQ(a[i], a0[i]) << i;
        }
    }
    EXPECT_EQ(onPlane, 25u);
    const auto& skew = dynamic_cast<const SkewSymmetricPlane<3>&>(*bc);
    EXPECT_EQ(skew.onPlane().size(), 25u);
    EXPECT_EQ(bc->describe(), "test: skewSymmetricPlane on all particles, 125 particles, 25 on the plane");
}

TEST(SkewSymmetricPlane, ObliquePlaneKeepsOnlyTheNormalComponent) {
    auto p = lattice<2>(11, 0.1);
    const Vector<2> n = Vector<2>(1, 1).normalized();
    auto bc = condition<2>("type skewSymmetricPlane; point (0.5 0); normal (1 1);", p);  // x + y = 0.5
    const auto v0 = p.vectorField("velocity");
    bc->constrainVelocity(p, 0.0);
    const auto& v = p.vectorField("velocity");
    std::size_t constrained = 0;
    for (std::size_t i = 0; i < p.size(); ++i) {
        const double d = (p.position()[i] - Vector<2>(0.5, 0)).dot(n);
        if (std::abs(d) <= 1e-12) {
            ++constrained;
            EXPECT_NEAR((v[i] - v0[i].dot(n) * n).norm(), 0.0, roundOff) << i;
        } else {
            EXPECT_EQ(v[i], v0[i]) << i;
        }
    }
    EXPECT_EQ(constrained, 6u);  // (0, 0.5) ... (0.5, 0)
}

TEST(SkewSymmetricPlane, ParticlesStayPickedAfterMovingOffThePlaneAndThroughAReorder) {
    auto p = lattice<2>(11, 0.1);
    auto bcs = conditions<2>(
        "boundaryConditions { face { type skewSymmetricPlane; point (1 0); normal (-1 0); } }", p);
    std::set<std::int64_t> picked;
    for (std::size_t i = 0; i < p.size(); ++i)
        if (p.position()[i][0] == 1.0) picked.insert(p.globalId()[i]);
    ASSERT_EQ(picked.size(), 11u);
    // The face moves outward along its normal (the swinging cube's X = 1 face), by far more than
    // the tolerance, and other particles move onto x = 1.
    for (auto& x : p.position()) x[0] = x[0] == 1.0 ? 1.05 : x[0] == 0.9 ? 1.0 : x[0];
    // A reorder: reversed.
    std::vector<std::size_t> order(p.size());
    for (std::size_t i = 0; i < order.size(); ++i) order[i] = order.size() - 1 - i;
    p.reorder(order);
    bcs.updateSelections(p);
    const auto v0 = p.vectorField("velocity");
    bcs.constrainVelocity(p, 0.0);
    const auto& v = p.vectorField("velocity");
    for (std::size_t i = 0; i < p.size(); ++i) {
        if (picked.contains(p.globalId()[i])) {
            EXPECT_EQ(p.position()[i][0], 1.05);
            EXPECT_EQ(v[i], Vector<2>(v0[i][0], 0.0)) << i;
        } else {
            EXPECT_EQ(v[i], v0[i]) << i;
        }
    }
}

TEST(SkewSymmetricPlane, SelectionRegionsAndToleranceAndReleaseTime) {
    auto p = lattice<2>(11, 0.1);
    // Only the wall region (y < 0.15) on x = 1: two particles.
    auto wall = condition<2>("type skewSymmetricPlane; point (1 0); normal (1 0); regions (wall);", p);
    EXPECT_EQ(dynamic_cast<const SkewSymmetricPlane<2>&>(*wall).onPlane().size(), 2u);
    // A tolerance of 0.15 takes x = 0.9 and x = 1.
    auto thick = condition<2>("type skewSymmetricPlane; point (1 0); normal (1 0); tolerance 0.15;", p);
    EXPECT_EQ(dynamic_cast<const SkewSymmetricPlane<2>&>(*thick).onPlane().size(), 22u);
    auto released = condition<2>("type skewSymmetricPlane; point (1 0); normal (1 0); releaseTime 1;", p);
    const auto v0 = p.vectorField("velocity");
    released->constrainVelocity(p, 1.0);
    EXPECT_EQ(p.vectorField("velocity"), v0);
}

TEST(SkewSymmetricPlane, InputErrors) {
    const auto p = lattice<2>(11, 0.1);
    EXPECT_THROW(condition<2>("type skewSymmetricPlane; point (1 0); normal (0 0);", p), InputError);
    EXPECT_THROW(condition<2>("type skewSymmetricPlane; normal (1 0);", p), InputError);
    EXPECT_THROW(condition<2>("type skewSymmetricPlane; point (1 0);", p), InputError);
    const std::string message =
        inputErrorOf([&] { condition<2>("type skewSymmetricPlane; point (1.05 0); normal (1 0);", p); });
    EXPECT_NE(message.find("no selected particle lies on the plane"), std::string::npos) << message;
}
