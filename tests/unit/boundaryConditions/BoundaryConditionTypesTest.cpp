// The velocity, acceleration and position constraints of free, fixed, prescribedVelocity,
// symmetryPlane and rigidPlanarWall, each built from its dictionary as a case writes it. The
// constraints are algebraic (assignments and projections), so results are exact up to round-off
// of one projection: tolerances are a few ulps of O(1) numbers.
#include "BoundaryConditionTestTools.hpp"
#include "boundaryConditions/PrescribedVelocity.hpp"

#include <gtest/gtest.h>

using namespace mfdyn;
using mfdyn::test::condition;
using mfdyn::test::inputErrorOf;
using mfdyn::test::lattice;

namespace {
constexpr double roundOff = 1e-14;
}

TEST(BoundaryConditionFamily, EveryTypeIsRegisteredAndAnUnknownOneListsThem) {
    const auto names = BoundaryCondition<3>::Selector::names();
    for (const char* type :
         {"free", "fixed", "prescribedVelocity", "symmetryPlane", "rigidPlanarWall", "mirrorPlane"})
        EXPECT_NE(std::find(names.begin(), names.end(), type), names.end()) << type;
    const auto p = lattice<2>();
    const std::string message = inputErrorOf([&] { condition<2>("type fixd; regions (wall);", p); });
    EXPECT_NE(message.find("fixed"), std::string::npos) << message;
    EXPECT_NE(message.find("mirrorPlane"), std::string::npos) << message;
}

TEST(BoundaryConditionFamily, NameTypeAndDescription) {
    const auto p = lattice<2>();
    const auto bc = condition<2>("type fixed; regions (wall);", p);
    EXPECT_EQ(bc->name(), "test");
    EXPECT_EQ(bc->type(), "fixed");
    EXPECT_EQ(bc->describe(), "test: fixed on regions (wall), 22 particles");
}

TEST(Free, ChangesNothing) {
    auto p = lattice<2>();
    const auto v0 = p.vectorField("velocity");
    const auto a0 = p.vectorField("acceleration");
    const auto x0 = p.position();
    auto bc = condition<2>("type free; regions (wall);", p);
    bc->constrainAcceleration(p, p.vectorField("acceleration"), 0.0);
    bc->constrainVelocity(p, 0.0);
    bc->constrainPosition(p, 0.0);
    EXPECT_EQ(p.vectorField("velocity"), v0);
    EXPECT_EQ(p.vectorField("acceleration"), a0);
    EXPECT_EQ(p.position(), x0);
    EXPECT_FALSE(bc->makesGhosts());
}

TEST(Fixed, ZeroesVelocityAndAccelerationOnItsRegionOnly) {
    auto p = lattice<2>();
    const auto v0 = p.vectorField("velocity");
    const auto a0 = p.vectorField("acceleration");
    auto bc = condition<2>("type fixed; regions (wall);", p);
    bc->constrainVelocity(p, 0.1);
    bc->constrainAcceleration(p, p.vectorField("acceleration"), 0.1);
    const auto& v = p.vectorField("velocity");
    const auto& a = p.vectorField("acceleration");
    for (std::size_t i = 0; i < p.size(); ++i) {
        if (p.region()[i] == 1) {
            EXPECT_EQ(v[i], Vector<2>::Zero());
            EXPECT_EQ(a[i], Vector<2>::Zero());
        } else {
            EXPECT_EQ(v[i], v0[i]);
            EXPECT_EQ(a[i], a0[i]);
        }
    }
}

TEST(Fixed, ReleaseTimeEndsTheConstraint) {
    auto p = lattice<2>();
    const auto v0 = p.vectorField("velocity");
    auto bc = condition<2>("type fixed; regions (wall); releaseTime 1e-3;", p);
    EXPECT_TRUE(bc->active(0.9e-3));
    bc->constrainVelocity(p, 1e-3);  // released: t >= releaseTime
    EXPECT_EQ(p.vectorField("velocity"), v0);
}

TEST(PrescribedVelocity, HoldsTheVelocityUntilReleaseThenLetsGo) {
    auto p = lattice<3>(5, 0.25);
    // The punch of doc/methods/tl-jst-sph.md 8.7: the mid quarter of the top face at -100 m/s until 7 ms.
    auto bc = condition<3>(
        "type prescribedVelocity; velocity (0 -100 0); releaseTime 0.007;"
        "shape { type box; min (0.2 0.9 0.2); max (0.8 1.1 0.8); }",
        p);
    EXPECT_EQ(bc->selection().size(), 3u * 3u);  // x, z in {0.25, 0.5, 0.75} on y = 1
    auto& v = p.vectorField("velocity");
    auto& a = p.vectorField("acceleration");
    const auto v0 = v;
    bc->constrainVelocity(p, 0.005);
    bc->constrainAcceleration(p, a, 0.005);
    const auto& idx = bc->selection().indices();
    for (std::size_t i = 0; i < p.size(); ++i) {
        const bool selected = std::find(idx.begin(), idx.end(), i) != idx.end();
        if (selected) {
            EXPECT_EQ(v[i], Vector<3>(0, -100, 0));
            EXPECT_EQ(a[i], Vector<3>::Zero());
        } else {
            EXPECT_EQ(v[i], v0[i]);
        }
    }
    // After release the punch keeps whatever velocity the solver gives it.
    for (auto i : idx) v[i] = Vector<3>(1, 2, 3);
    bc->constrainVelocity(p, 0.0071);
    for (auto i : idx) EXPECT_EQ(v[i], Vector<3>(1, 2, 3));
}

TEST(PrescribedVelocity, TableIsPiecewiseLinearWithItsSlopeAsAcceleration) {
    const auto p = lattice<2>();
    const auto bc =
        condition<2>("type prescribedVelocity; regions (wall); table ((0 (0 0)) (2e-3 (0 -100)));", p);
    const auto& pv = dynamic_cast<const PrescribedVelocity<2>&>(*bc);
    EXPECT_NEAR(pv.velocity(1e-3)[1], -50.0, 50 * roundOff);
    EXPECT_NEAR(pv.acceleration(1e-3)[1], -5e4, 5e4 * roundOff);
    EXPECT_EQ(pv.velocity(5e-3), Vector<2>(0, -100));  // held after the last time
    EXPECT_EQ(pv.acceleration(5e-3), Vector<2>::Zero());
    EXPECT_EQ(pv.velocity(-1.0), Vector<2>::Zero());
}

TEST(PrescribedVelocity, NeedsExactlyOneOfVelocityAndTable) {
    const auto p = lattice<2>();
    EXPECT_THROW(condition<2>("type prescribedVelocity; regions (wall);", p), InputError);
    EXPECT_THROW(
        condition<2>("type prescribedVelocity; regions (wall); velocity (1 0); table ((0 (1 0)));", p),
        InputError);
    EXPECT_THROW(condition<2>("type prescribedVelocity; regions (wall); table ((1 (1 0)) (0 (1 0)));", p),
                 InputError);
    // A 3-vector with a non-zero z in a 2D case is a mistake, not something to drop silently.
    EXPECT_THROW(condition<2>("type prescribedVelocity; regions (wall); velocity (1 0 5);", p), InputError);
    EXPECT_THROW(condition<2>("type prescribedVelocity; regions (wall); velocity (1 0); releaseTime -1;", p),
                 InputError);
}

TEST(SymmetryPlane, RemovesOnlyTheNormalComponentOnThePlane) {
    auto p = lattice<2>();
    const auto v0 = p.vectorField("velocity");
    const auto a0 = p.vectorField("acceleration");
    auto bc = condition<2>("type symmetryPlane; point (0 0); normal (2 0);", p);  // x = 0, normalised
    bc->constrainVelocity(p, 0.0);
    bc->constrainAcceleration(p, p.vectorField("acceleration"), 0.0);
    const auto& v = p.vectorField("velocity");
    const auto& a = p.vectorField("acceleration");
    std::size_t onPlane = 0;
    for (std::size_t i = 0; i < p.size(); ++i) {
        if (p.position()[i][0] == 0.0) {
            ++onPlane;
            EXPECT_EQ(v[i][0], 0.0);
            EXPECT_EQ(v[i][1], v0[i][1]);
            EXPECT_EQ(a[i][0], 0.0);
            EXPECT_EQ(a[i][1], a0[i][1]);
        } else {
            EXPECT_EQ(v[i], v0[i]);
            EXPECT_EQ(a[i], a0[i]);
        }
    }
    EXPECT_EQ(onPlane, 11u);
}

TEST(SymmetryPlane, ObliquePlaneKeepsTheTangentialVelocity) {
    auto p = lattice<3>(4, 0.1);
    const Vector<3> n = Vector<3>(1, 1, 0).normalized();
    // The plane x + y = 0.1 through lattice points: (0, 0.1, z) and (0.1, 0, z).
    auto bc = condition<3>("type symmetryPlane; point (0.1 0 0); normal (1 1 0);", p);
    const auto v0 = p.vectorField("velocity");
    bc->constrainVelocity(p, 0.0);
    const auto& v = p.vectorField("velocity");
    std::size_t constrained = 0;
    for (std::size_t i = 0; i < p.size(); ++i) {
        const double d = (p.position()[i] - Vector<3>(0.1, 0, 0)).dot(n);
        if (d <= 1e-12) {
            ++constrained;
            EXPECT_NEAR(v[i].dot(n), 0.0, roundOff);
            const Vector<3> tangential0 = v0[i] - v0[i].dot(n) * n;
            EXPECT_NEAR((v[i] - tangential0).norm(), 0.0, roundOff);
        } else {
            EXPECT_EQ(v[i], v0[i]);
        }
    }
    EXPECT_EQ(constrained, 3u * 4u);  // (0,0), (0,0.1), (0.1,0) in x-y, times 4 in z
}

TEST(SymmetryPlane, PutsParticlesThatCrossedBackOnThePlane) {
    auto p = lattice<2>();
    auto bc = condition<2>("type symmetryPlane; point (0 0); normal (1 0);", p);
    p.position()[0] = Vector<2>(-0.01, 0.3);
    bc->constrainPosition(p, 0.0);
    EXPECT_EQ(p.position()[0], Vector<2>(0.0, 0.3));
}

TEST(RigidPlanarWall, StopsApproachingParticlesOnly) {
    auto p = lattice<2>();
    auto& v = p.vectorField("velocity");
    auto bc = condition<2>("type rigidPlanarWall; point (0 0); normal (0 1);", p);  // the floor y = 0
    // Particles 0 and 1 lie on the floor; 11 is one row up.
    v[0] = Vector<2>(0.5, -2.0);   // approaching: stopped
    v[1] = Vector<2>(0.5, 3.0);    // receding: free to leave
    v[11] = Vector<2>(0.5, -2.0);  // above the floor: not in contact yet
    bc->constrainVelocity(p, 0.0);
    EXPECT_EQ(v[0], Vector<2>(0.5, 0.0));
    EXPECT_EQ(v[1], Vector<2>(0.5, 3.0));
    EXPECT_EQ(v[11], Vector<2>(0.5, -2.0));
}

TEST(RigidPlanarWall, RestitutionOneReflects) {
    auto p = lattice<2>();
    auto& v = p.vectorField("velocity");
    auto bc = condition<2>("type rigidPlanarWall; point (0 0); normal (0 1); restitution 1;", p);
    v[0] = Vector<2>(0.5, -2.0);
    bc->constrainVelocity(p, 0.0);
    EXPECT_EQ(v[0], Vector<2>(0.5, 2.0));
    EXPECT_THROW(condition<2>("type rigidPlanarWall; point (0 0); normal (0 1); restitution 2;", p),
                 InputError);
}

TEST(RigidPlanarWall, ProjectsParticlesThatCrossedOntoThePlane) {
    auto p = lattice<2>();
    auto& v = p.vectorField("velocity");
    auto bc = condition<2>("type rigidPlanarWall; point (0 0.05); normal (0 1);", p);  // y = 0.05
    // The velocity hook alone puts the crossed row back and stops it ...
    for (std::size_t i = 0; i < 11; ++i) v[i] = Vector<2>(1.0, -1.0);
    bc->constrainVelocity(p, 0.0);
    for (std::size_t i = 0; i < 11; ++i) {
        EXPECT_NEAR(p.position()[i][1], 0.05, roundOff);
        EXPECT_NEAR(p.position()[i][0], 0.1 * double(i), roundOff);  // tangential position kept
        EXPECT_EQ(v[i], Vector<2>(1.0, 0.0));
    }
    // ... and so does the position hook after a drift.
    p.position()[3][1] = -0.2;
    bc->constrainPosition(p, 0.0);
    EXPECT_NEAR(p.position()[3][1], 0.05, roundOff);
    EXPECT_NEAR(p.position()[12][1], 0.1, 0.0);  // in front of the wall: untouched
}

TEST(RigidPlanarWall, SupportsOnlyAccelerationIntoTheWall) {
    auto p = lattice<2>();
    auto& a = p.vectorField("acceleration");
    auto bc = condition<2>("type rigidPlanarWall; point (0 0); normal (0 1);", p);
    a[0] = Vector<2>(1.0, -9.81);
    a[1] = Vector<2>(1.0, 9.81);
    a[11] = Vector<2>(1.0, -9.81);
    bc->constrainAcceleration(p, a, 0.0);
    EXPECT_EQ(a[0], Vector<2>(1.0, 0.0));
    EXPECT_EQ(a[1], Vector<2>(1.0, 9.81));
    EXPECT_EQ(a[11], Vector<2>(1.0, -9.81));
}

TEST(PlaneConditions, ZeroNormalIsAnInputError) {
    const auto p = lattice<2>();
    for (const char* type : {"symmetryPlane", "rigidPlanarWall", "mirrorPlane"})
        EXPECT_THROW(condition<2>(std::string("type ") + type + "; point (0 0); normal (0 0);", p),
                     InputError)
            << type;
}

TEST(PlaneConditions, OneDimensionalWall) {
    auto p = lattice<1>(5, 0.1);
    auto& v = p.vectorField("velocity");
    v[4] = Vector<1>(2.0);
    auto bc = condition<1>("type rigidPlanarWall; point (0.4); normal (-1);", p);  // right end
    bc->constrainVelocity(p, 0.0);
    EXPECT_EQ(v[4][0], 0.0);
}
