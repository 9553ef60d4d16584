// The reference images a total-Lagrangian method (tlSph) mirrors once through the symmetryPlane
// (parity +1) and skewSymmetricPlane (parity -1) conditions: which conditions mirror, the images
// of images at a corner, and the parity maps of GhostBlock.
#include "BoundaryConditionTestTools.hpp"

#include <gtest/gtest.h>

using namespace mfdyn;
using mfdyn::test::conditions;
using mfdyn::test::lattice;

namespace {

// A 5 x 5 lattice, spacing 0.1, on [0, 0.4]^2: a roller on x = 0 and a skew-symmetric plane on
// y = 0.4 (normal into the material, -y); a fixed wall and a mirrorPlane that must not mirror.
const char* text =
    "boundaryConditions {"
    "  roller { type symmetryPlane; point (0 0); normal (1 0); }"
    "  base   { type fixed; regions (wall); }"
    "  skew   { type skewSymmetricPlane; point (0 0.4); normal (0 -1); }"
    "  wall   { type mirrorPlane; point (0 0); normal (0 1); }"
    "}";

}  // namespace

TEST(ReferenceImages, onlySymmetryAndSkewSymmetricPlanesMirrorInTheOrderWritten) {
    auto p = lattice<2>(5, 0.1);
    const auto bcs = conditions<2>(text, p);
    const auto mirrors = bcs.referenceMirrors();
    ASSERT_EQ(mirrors.size(), 2u);
    EXPECT_EQ(mirrors[0].parity, 1.0);
    EXPECT_EQ(mirrors[0].plane->normal(), Vector<2>(1, 0));
    EXPECT_EQ(mirrors[1].parity, -1.0);
    EXPECT_EQ(mirrors[1].plane->normal(), Vector<2>(0, -1));
}

TEST(ReferenceImages, imagesOfImagesMakeTheCornerWithComposedMapsAndParities) {
    auto p = lattice<2>(5, 0.1);
    const auto bcs = conditions<2>(text, p);
    // depth 0.25: the columns x = 0.1, 0.2 (x = 0 is on the plane, its own image) and the rows
    // y = 0.3, 0.2 of the real particles and of the first plane's images.
    const auto block = bcs.referenceImages(p.position(), 0.25);
    ASSERT_EQ(block.size(), 10u + 10u + 4u);
    ASSERT_EQ(block.position.size(), block.size());
    ASSERT_EQ(block.map.size(), block.size());
    ASSERT_EQ(block.parity.size(), block.size());
    EXPECT_TRUE(block.velocity.empty());  // reference images: the method maps its own fields
    const auto& X = p.position();
    for (std::size_t g = 0; g < block.size(); ++g) {
        SCOPED_TRACE(g);
        const Vector<2> x = X[block.source[g]];
        const Vector<2> image = block.position[g];
        if (g < 10) {  // across x = 0
            EXPECT_NEAR(image[0], -x[0], 1e-15);
            EXPECT_EQ(image[1], x[1]);
            EXPECT_EQ(block.parity[g], 1.0);
            EXPECT_EQ(block.map[g], Tensor<2>(Eigen::Vector2d(-1, 1).asDiagonal()));
        } else if (g < 20) {  // across y = 0.4
            EXPECT_EQ(image[0], x[0]);
            EXPECT_NEAR(image[1], 0.8 - x[1], 1e-15);
            EXPECT_EQ(block.parity[g], -1.0);
            EXPECT_EQ(block.map[g], Tensor<2>(Eigen::Vector2d(1, -1).asDiagonal()));
        } else {  // the corner: both reflections, parity (+1)(-1)
            EXPECT_NEAR(image[0], -x[0], 1e-15);
            EXPECT_NEAR(image[1], 0.8 - x[1], 1e-15);
            EXPECT_EQ(block.parity[g], -1.0);
            EXPECT_EQ(block.map[g], Tensor<2>(-Tensor<2>::Identity()));
        }
    }
}

TEST(ReferenceImages, parityMapsVectorsTensorsAndDeformationsAsTheOddExtension) {
    GhostBlock<2> block;
    const std::vector<Vector<2>> real{Vector<2>(0.3, 0.1)};
    // A skew-symmetric plane x = 0.4 with the normal into the material (-x): image (0.5, 0.1).
    block.referenceImagesAcross(real, Plane<2>(Vector<2>(0.4, 0), Vector<2>(-1, 0)), -1.0, 0.25);
    ASSERT_EQ(block.size(), 1u);
    EXPECT_NEAR(block.position[0][0], 0.5, 1e-15);
    const Vector<2> a(2, 3);
    // Q = diag(-1, 1), s = -1: s Q a = (2, -3). The odd extension: the tangential component
    // changes sign across the plane, the normal one does not (v = (v.n) n on the plane).
    EXPECT_EQ(block.reflectVector(0, a), Vector<2>(2, -3));
    Tensor<2> T;
    T << 1, 2, 3, 4;
    Tensor<2> expected;
    expected << -1, 2, 3, -4;  // s Q T Q^T
    EXPECT_EQ(block.reflectTensor(0, T), expected);
    EXPECT_EQ(block.reflectScalar(0, 7.0), -7.0);
    // F = I + A maps to I + s Q A Q^T; the identity (no deformation) to itself.
    EXPECT_EQ(block.reflectDeformation(0, Tensor<2>::Identity()), Tensor<2>(Tensor<2>::Identity()));
    Tensor<2> F = Tensor<2>::Identity() + 0.25 * T;
    Tensor<2> FImage = Tensor<2>::Identity() + 0.25 * expected;
    EXPECT_TRUE(block.reflectDeformation(0, F).isApprox(FImage, 1e-15));
    EXPECT_EQ(block.reflectJacobian(0, 1.0), 1.0);
    EXPECT_EQ(block.reflectJacobian(0, 1.5), 0.5);
    // A point on the plane or beyond the depth makes no image.
    GhostBlock<2> none;
    none.referenceImagesAcross({Vector<2>(0.4, 0.0), Vector<2>(0.1, 0.0)},
                               Plane<2>(Vector<2>(0.4, 0), Vector<2>(-1, 0), 1e-9), -1.0, 0.25);
    EXPECT_TRUE(none.empty());
}

TEST(ReferenceImages, mirrorPlaneGhostsCarryParityOneSoTheirMapsAreUnchanged) {
    auto p = lattice<2>(5, 0.1, 0.5);
    const auto bcs =
        conditions<2>("boundaryConditions { wall { type mirrorPlane; point (0 0); normal (0 1); } }", p);
    const auto block = bcs.ghosts(p, p.vectorField("velocity"), 0.1, 0.0);
    ASSERT_FALSE(block.empty());
    ASSERT_EQ(block.parity.size(), block.size());
    for (std::size_t g = 0; g < block.size(); ++g) {
        EXPECT_EQ(block.parity[g], 1.0);
        const Vector<2> a(2, 3);
        EXPECT_EQ(block.reflectVector(g, a), Vector<2>(2, -3));  // Q a, Q = diag(1, -1)
    }
}
