// Mirror ghosts: which particles make them (the layer), where they are (the exact image), their
// velocity (free-slip or no-slip) and the index of their source particle.
#include "BoundaryConditionTestTools.hpp"
#include "boundaryConditions/MirrorPlane.hpp"

#include <gtest/gtest.h>

using namespace mfdyn;
using mfdyn::test::condition;
using mfdyn::test::conditions;
using mfdyn::test::lattice;

namespace {
// Mirroring is x - 2 d n with |x| = O(1): a few ulps.
constexpr double roundOff = 1e-14;

const MirrorPlane<3>& mirror(const BoundaryCondition<3>& bc) {
    return dynamic_cast<const MirrorPlane<3>&>(bc);
}
}  // namespace

TEST(MirrorPlane, LayerOf3HmaxInACellCentredLattice) {
    // Cell-centred lattice x = 0.05, 0.15, ...: with h_max = 0.1 the layer 0 < x < 0.3 holds three
    // columns of 11, and the column at 0.35 is outside.
    const auto p = lattice<2>(11, 0.1, 0.5);
    const auto bc = condition<2>("type mirrorPlane; point (0 0); normal (1 0);", p);
    const auto& m = dynamic_cast<const MirrorPlane<2>&>(*bc);
    EXPECT_TRUE(bc->makesGhosts());
    EXPECT_DOUBLE_EQ(m.thickness(0.1), 0.3);
    const auto g = m.ghosts(p, p.requireField<Vector<2>>("velocity"), 0.1);
    ASSERT_EQ(g.size(), 33u);
    EXPECT_EQ(g.position.size(), 33u);
    EXPECT_EQ(g.velocity.size(), 33u);
    for (std::size_t k = 0; k < g.size(); ++k) {
        const auto& x = p.position()[g.source[k]];
        EXPECT_LT(x[0], 0.3);
        EXPECT_NEAR(g.position[k][0], -x[0], roundOff);
        EXPECT_EQ(g.position[k][1], x[1]);
        if (k) {
            EXPECT_LT(g.source[k - 1], g.source[k]);
        }
    }
}

TEST(MirrorPlane, ObliquePlaneImagesAreExactAndTheLayerIsRespected) {
    const auto p = lattice<3>(8, 0.1, 0.5);
    const Vector<3> point(0.3, 0.1, 0.2), n = Vector<3>(1, 2, -0.5).normalized();
    auto bc = condition<3>("type mirrorPlane; point (0.3 0.1 0.2); normal (1 2 -0.5); thickness 0.25;", p);
    const auto& v = p.requireField<Vector<3>>("velocity");
    const auto g = mirror(*bc).ghosts(p, v, 123.0);  // h_max is not used when thickness is given
    std::size_t expected = 0;
    for (const auto& x : p.position()) {
        const double d = (x - point).dot(n);
        expected += d > 1e-9 && d < 0.25;
    }
    ASSERT_EQ(g.size(), expected);
    ASSERT_GT(expected, 20u);
    for (std::size_t k = 0; k < g.size(); ++k) {
        const Vector<3>& x = p.position()[g.source[k]];
        const double d = (x - point).dot(n);
        EXPECT_GT(d, 0.0);
        EXPECT_LT(d, 0.25);
        // The midpoint lies on the plane and the segment is along n: the mirror image.
        EXPECT_NEAR((0.5 * (x + g.position[k]) - point).dot(n), 0.0, roundOff);
        EXPECT_NEAR(((g.position[k] - x) - (g.position[k] - x).dot(n) * n).norm(), 0.0, roundOff);
        EXPECT_NEAR((g.position[k] - point).dot(n), -d, roundOff);
        // Free slip: the normal velocity reverses, the tangential one is kept.
        const Vector<3>& vs = v[g.source[k]];
        EXPECT_NEAR(g.velocity[k].dot(n), -vs.dot(n), roundOff);
        EXPECT_NEAR(((g.velocity[k] - vs) - (g.velocity[k] - vs).dot(n) * n).norm(), 0.0, roundOff);
        EXPECT_LT((g.map[k] - (Tensor<3>::Identity() - 2.0 * n * n.transpose())).norm(), roundOff);
    }
}

TEST(MirrorPlane, NoSlipReversesTheWholeVelocity) {
    const auto p = lattice<3>(6, 0.1, 0.5);
    const auto& v = p.requireField<Vector<3>>("velocity");
    auto bc = condition<3>("type mirrorPlane; point (0 0 0); normal (0 0 1); noSlip yes;", p);
    const auto g = mirror(*bc).ghosts(p, v, 0.1);
    ASSERT_EQ(g.size(), 3u * 36u);
    for (std::size_t k = 0; k < g.size(); ++k) EXPECT_EQ(g.velocity[k], Vector<3>(-v[g.source[k]]));
}

TEST(MirrorPlane, ThicknessFactorAndParticlesOnThePlane) {
    // Vertex lattice: the column x = 0 lies on the plane and makes no ghost (it would sit on its
    // source); with factor 2 and h_max = 0.1 the layer 0 < x < 0.2 holds the column x = 0.1 only.
    const auto p = lattice<2>(11, 0.1, 0.0);
    auto bc = condition<2>("type mirrorPlane; point (0 0); normal (1 0); thicknessFactor 2;", p);
    const auto g =
        dynamic_cast<const MirrorPlane<2>&>(*bc).ghosts(p, p.requireField<Vector<2>>("velocity"), 0.1);
    EXPECT_EQ(g.size(), 11u);
    for (auto s : g.source) EXPECT_NEAR(p.position()[s][0], 0.1, roundOff);
    EXPECT_THROW(
        condition<2>("type mirrorPlane; point (0 0); normal (1 0); thickness 0.1; thicknessFactor 2;", p),
        InputError);
}

TEST(MirrorPlane, GatherCopiesScalarsAndReflectTurnsVectorsAndTensors) {
    const auto p = lattice<2>(11, 0.1, 0.5);
    auto bc = condition<2>("type mirrorPlane; point (0 0); normal (1 0);", p);
    const auto g =
        dynamic_cast<const MirrorPlane<2>&>(*bc).ghosts(p, p.requireField<Vector<2>>("velocity"), 0.1);
    std::vector<double> rho(p.size());
    for (std::size_t i = 0; i < rho.size(); ++i) rho[i] = 1000.0 + double(i);
    const auto rhoGhost = g.gather(rho);
    for (std::size_t k = 0; k < g.size(); ++k) EXPECT_EQ(rhoGhost[k], rho[g.source[k]]);
    EXPECT_EQ(g.reflectVector(0, Vector<2>(1, 2)), Vector<2>(-1, 2));
    Tensor<2> s;
    s << 1, 2, 2, 3;  // a shear stress changes sign under the mirror, normal stresses do not
    Tensor<2> expected;
    expected << 1, -2, -2, 3;
    EXPECT_EQ(g.reflectTensor(0, s), expected);
}

TEST(BoundaryConditionList, GhostsOfAllMirrorPlanesInOneBlock) {
    const auto p = lattice<2>(11, 0.1, 0.5);  // 0.05 ... 1.05
    auto bcs = conditions<2>(
        "boundaryConditions { left { type mirrorPlane; point (0 0); normal (1 0); }"
        " right { type mirrorPlane; point (1.1 0); normal (-1 0); } walls { type fixed; regions (wall); } }",
        p);
    EXPECT_TRUE(bcs.makesGhosts());
    const auto g = bcs.ghosts(p, p.requireField<Vector<2>>("velocity"), 0.1, 0.0);
    EXPECT_EQ(g.size(), 66u);
    EXPECT_NEAR(g.position[0][0], -0.05, roundOff);
    EXPECT_NEAR(g.position[33][0], 1.1 + 0.25, roundOff);  // source 0.85, 0.25 inside the wall
}

TEST(BoundaryConditionList, PerpendicularMirrorPlanesMakeTheCornerImages) {
    // Planes x = 0 and y = 0 written in that order: the second also mirrors the first's ghosts, so
    // the quadrant x < 0, y < 0 holds the images of images (the body turned by 180 degrees), with
    // the velocity and the map composed. A third plane z = 0 then fills the octants.
    const auto p = lattice<3>(6, 0.1, 0.5);  // 0.05 ... 0.55 on each axis
    auto& v = const_cast<std::vector<Vector<3>>&>(p.requireField<Vector<3>>("velocity"));
    for (std::size_t i = 0; i < p.size(); ++i) v[i] = Vector<3>(1.0 + double(i), 2.0, 3.0 - double(i));
    auto bcs = conditions<3>(
        "boundaryConditions { x { type mirrorPlane; point (0 0 0); normal (1 0 0); }"
        " y { type mirrorPlane; point (0 0 0); normal (0 1 0); noSlip yes; }"
        " z { type mirrorPlane; point (0 0 0); normal (0 0 1); thickness 0.1; } }",
        p);
    const auto g = bcs.ghosts(p, v, 0.1, 0.0);
    // Layer 0.3 (3 columns) for x and y, 0.1 (one column) for z:
    //   x: 3*6*6 = 108; y: 108 of the real particles + 3*3*6 = 54 of x's; z: 36 + 18 + 18 + 9.
    ASSERT_EQ(g.size(), 108u + 108u + 54u + 36u + 18u + 18u + 9u);
    std::size_t corners = 0, octants = 0;
    for (std::size_t k = 0; k < g.size(); ++k) {
        const Vector<3>& x = p.position()[g.source[k]];
        const Vector<3>& y = g.position[k];
        // Every image is the source with some coordinates negated, and the map says which.
        Tensor<3> expected = Tensor<3>::Identity();
        for (int c = 0; c < 3; ++c)
            if (y[c] < 0.0) expected(c, c) = -1.0;
        EXPECT_EQ(g.map[k], expected) << k;
        EXPECT_LT((y - expected * x).norm(), roundOff) << k;
        EXPECT_LT((g.reflectVector(k, x) - y).norm(), roundOff) << k;
        // Velocity: reflected across x and z (free slip), reversed across y (no slip).
        Vector<3> image = v[g.source[k]];
        if (y[0] < 0.0) image[0] = -image[0];
        if (y[1] < 0.0) image = -image;
        if (y[2] < 0.0) image[2] = -image[2];
        EXPECT_EQ(g.velocity[k], image) << k;
        corners += y[0] < 0.0 && y[1] < 0.0;
        octants += y[0] < 0.0 && y[1] < 0.0 && y[2] < 0.0;
    }
    EXPECT_EQ(corners, 54u + 9u);
    EXPECT_EQ(octants, 9u);
}
