// Lattices built through Lattice::New: volume per point, filling, jitter determinism.
#include "GeometryTestUtils.hpp"

#include <gtest/gtest.h>

#include <cmath>

using namespace mfdyn;
using mfdyn::test::fill;
using mfdyn::test::lattice;
using mfdyn::test::shape;

TEST(Lattice, PointVolumes) {
    EXPECT_DOUBLE_EQ(lattice("type cubic; spacing 0.1;", 3)->pointVolume(), 1e-3);
    EXPECT_DOUBLE_EQ(lattice("type hexagonal; spacing 0.1;", 2)->pointVolume(), 0.01 * std::sqrt(3.0) / 2);
    EXPECT_DOUBLE_EQ(lattice("type hcp; spacing 0.1;", 3)->pointVolume(), 1e-3 / std::sqrt(2.0));
}

// Rows and layers are rounded to whole counts and rows shifted by half a spacing lose their last
// point at the half-open face, so the filled volume is short by up to about a row per face
// (spacing/length, 1-3% here): measured 0.28% (hexagonal) and 1.2% (hcp); bound 2%.
TEST(Lattice, HexagonalFillsABoxWithin2Percent) {
    const auto box = shape("type box; min (0 0); max (1 0.7);", 2);
    const auto f = fill(*box, *lattice("type hexagonal; spacing 0.01;", 2));
    EXPECT_NEAR(f.volume / 0.7, 1.0, 0.02);
}

TEST(Lattice, HcpFillsABoxWithin2Percent) {
    const auto box = shape("type box; min (0 0 0); max (1 0.8 0.6);", 3);
    const auto f = fill(*box, *lattice("type hcp; spacing 0.02;", 3));
    EXPECT_NEAR(f.volume / 0.48, 1.0, 0.02);
}

TEST(Lattice, HexagonalNeighboursAreAllOneSpacingApart) {
    // The first point of row 0 and its neighbours in row 0 and row 1.
    const auto l = lattice("type hexagonal; spacing 1;", 2);
    BoundingBox b;
    b.max = {3, 2, 0};
    const auto p = l->points(b);  // 3 columns × 3 rows
    ASSERT_EQ(p.size(), 3u * 3u * 2u);
    const auto dist = [&](int a, int c) {
        return std::hypot(p[2 * a] - p[2 * c], p[2 * a + 1] - p[2 * c + 1]);
    };
    EXPECT_NEAR(dist(0, 1), 1.0, 1e-12);  // along the row
    EXPECT_NEAR(dist(0, 3), 1.0, 1e-12);  // up to the offset row
    EXPECT_NEAR(dist(1, 3), 1.0, 1e-12);
}

TEST(Lattice, HcpNeighboursAreAllOneSpacingApart) {
    const auto l = lattice("type hcp; spacing 1;", 3);
    BoundingBox b;
    b.max = {3, 3, 2};
    const auto p = l->points(b);
    // Every point has at least one neighbour in the next layer exactly one spacing away and none
    // closer: the B layer sits on the A layer's triangle centroids.
    const std::size_t n = p.size() / 3;
    double closest = 1e9;
    for (std::size_t i = 0; i < n; ++i)
        for (std::size_t j = i + 1; j < n; ++j)
            closest = std::min(closest, std::hypot(p[3 * i] - p[3 * j], p[3 * i + 1] - p[3 * j + 1],
                                                   p[3 * i + 2] - p[3 * j + 2]));
    EXPECT_NEAR(closest, 1.0, 1e-12);
    // Point 0 (layer A) to the first point of layer B.
    const std::size_t perLayer = n / 3;
    EXPECT_NEAR(std::hypot(p[0] - p[3 * perLayer], p[1] - p[3 * perLayer + 1], p[2] - p[3 * perLayer + 2]),
                1.0, 1e-12);
}

TEST(Lattice, JitterIsDeterministicAndBounded) {
    const std::string text = "type hcp; spacing 0.1; jitter 0.1; seed 42;";
    BoundingBox b;
    b.max = {1, 1, 1};
    const auto a = lattice(text, 3)->points(b);
    const auto again = lattice(text, 3)->points(b);
    EXPECT_EQ(a, again);
    const auto regular = lattice("type hcp; spacing 0.1;", 3)->points(b);
    const auto other = lattice("type hcp; spacing 0.1; jitter 0.1; seed 43;", 3)->points(b);
    ASSERT_EQ(a.size(), regular.size());
    EXPECT_NE(a, other);
    double largest = 0;
    for (std::size_t i = 0; i < a.size(); ++i) largest = std::max(largest, std::abs(a[i] - regular[i]));
    EXPECT_LE(largest, 0.1 * 0.1);
    EXPECT_GT(largest, 0.05 * 0.1);  // thousands of draws: some come near the bound
}

TEST(Lattice, JitteredLatticesStillFillTheirShapes) {
    // Cell-centred points sit half a spacing from the box's faces and jitter 0.1 moves them at most
    // a tenth: none crosses, so the box is filled exactly.
    const auto box = shape("type box; min (0 0); max (1 1);", 2);
    EXPECT_NEAR(fill(*box, *lattice("type cubic; spacing 0.01; jitter 0.1; seed 42;", 2)).volume, 1.0, 1e-12);
    // At a curved surface jitter moves points in and out alike: the ball at 20 cells per radius
    // stays within the 1% of the regular lattice.
    const auto ball = shape("type sphere; centre (0 0 0); radius 1;", 3);
    const double exact = 4.0 / 3.0 * std::acos(-1.0);
    EXPECT_NEAR(fill(*ball, *lattice("type cubic; spacing 0.05; jitter 0.2; seed 7;", 3)).volume / exact, 1.0,
                0.01);
}

TEST(Lattice, RejectsBadInput) {
    EXPECT_THROW(lattice("type hexagonal; spacing 0.1;", 3), InputError);
    EXPECT_THROW(lattice("type hcp; spacing 0.1;", 2), InputError);
    EXPECT_THROW(lattice("type cubic; spacing 0.1; jitter 0.5;", 2), InputError);
    EXPECT_THROW(lattice("type cubic;", 2), InputError);
}
