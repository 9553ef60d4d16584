// bodyExtents's directions and mode radius (issue 19 item 6, for fpmSolid's sphere tests), on
// hand-made particle sets through FunctionObject::New: the extents along given directions
// (normalised when read) beside the axes' own, the radius about an axis through a given centre or
// the centroid (mass-weighted, else the mean position), the height along a tilted axis, the outer
// ring's mean radius, 2D's out-of-plane axis, and the refused input. The older modes' own tests
// (bounds, lines, references) are in tests/unit/sampling/MpmFunctionObjectsTest.cpp, unchanged.
// The CSV holds 10 significant digits: a relative 1e-9 where values are not short.
#include "FunctionObjectTestCase.hpp"
#include "core/Dictionary.hpp"
#include "core/Error.hpp"
#include "functionObjects/FunctionObject.hpp"
#include "particles/ParticleSet.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>

using namespace mfdyn;
namespace fs = std::filesystem;

namespace {

template <int Dim>
using Context = functionObjectTest::TestContext<Dim>;
fs::path freshCase(const std::string& tag) {
    return functionObjectTest::freshCase("BodyExtents", tag);
}

std::unique_ptr<FunctionObject> make(const std::string& text, const std::string& name, const RunContext& c) {
    return FunctionObject::New(Dictionary::parse(text, "controlDict"), name, c);
}

std::string errorOf(const std::string& text, const RunContext& c) {
    try {
        make(text, "fo", c);
    } catch (const InputError& e) {
        return e.what();
    }
    return "no error";
}

std::string header(const fs::path& file) {
    std::ifstream in(file);
    std::string line;
    std::getline(in, line);
    return line;
}

fs::path csvOf(const fs::path& root, const std::string& name) {
    return root / "postProcessing" / name / "0" / "bodyExtents.csv";
}

template <int Dim>
void place(ParticleSet<Dim>& p, const std::vector<Vector<Dim>>& x) {
    p.resize(x.size());
    p.regionNames = {"body"};
    for (std::size_t i = 0; i < x.size(); ++i) {
        p.position()[i] = x[i];
        p.region()[i] = 0;
        p.globalId()[i] = std::int64_t(i);
    }
}

}  // namespace

// (0 0 0), (2 2 0), (1 -1 3): along (1 1 0)/sqrt 2 the projections 0, 2 sqrt 2, 0; along
// (1 -1 0)/sqrt 2 0, 0, sqrt 2; along z 0, 0, 3. The axes' own extents 2, 3, 3 stay first.
// (2 2 0) normalises to the same direction as (1 1 0).
TEST(BodyExtents, Directions) {
    const fs::path root = freshCase("directions");
    Context<3> c(root);
    place<3>(c.particles, {Vector<3>(0, 0, 0), Vector<3>(2, 2, 0), Vector<3>(1, -1, 3)});
    {
        auto fo = make("type bodyExtents; directions ((1 1 0) (1 -1 0) (0 0 1) (2 2 0));", "dirs", c);
        fo->write();
        EXPECT_TRUE(fo->referenceValues().empty());
    }
    EXPECT_EQ(header(csvOf(root, "dirs")), "time,l_x,l_y,l_z,l_d1,l_d2,l_d3,l_d4");
    const auto rows = functionObjectTest::csvRows(csvOf(root, "dirs"));
    ASSERT_EQ(rows.size(), 1u);
    ASSERT_EQ(rows[0].size(), 8u);
    const double r2 = std::sqrt(2.0);
    const double expected[] = {0, 2, 3, 3, 2 * r2, r2, 3, 2 * r2};
    for (std::size_t k = 0; k < 8; ++k) EXPECT_NEAR(rows[0][k], expected[k], 1e-9 * expected[k]) << k;
    fs::remove_all(root);
}

// A sheared disc in 2D: a square of side 2 about the origin, corners (+-1, +-1), sheared by
// x += y (to (2 1), (0 1), (0 -1), (-2 -1)): along the bisector (1 1)/sqrt 2 it spans
// (3 - -3)/sqrt 2 = 3 sqrt 2, normal to it (1 -1)/sqrt 2 (1 - -1)/sqrt 2 = sqrt 2; references
// still compare the axes' columns (4, 2).
TEST(BodyExtents, DirectionsIn2DWithReference) {
    const fs::path root = freshCase("directions2");
    Context<2> c(root);
    place<2>(c.particles, {Vector<2>(2, 1), Vector<2>(0, 1), Vector<2>(0, -1), Vector<2>(-2, -1)});
    {
        auto fo = make("type bodyExtents; region body; reference (4 2); directions ((1 1) (1 -1));", "d2", c);
        fo->write();
        const auto ref = fo->referenceValues();
        ASSERT_EQ(ref.size(), 2u);
        EXPECT_EQ(ref[0].name, "l_x");
        EXPECT_EQ(ref[0].value, 4.0);
        EXPECT_EQ(ref[1].value, 2.0);
    }
    EXPECT_EQ(header(csvOf(root, "d2")), "time,l_x,l_y,l_d1,l_d2");
    const auto row = functionObjectTest::csvRows(csvOf(root, "d2"))[0];
    const double r2 = std::sqrt(2.0);
    EXPECT_NEAR(row[3], 3 * r2, 1e-9 * 3 * r2);
    EXPECT_NEAR(row[4], r2, 1e-9 * r2);
    fs::remove_all(root);
}

// About the z axis through the given centre (1 1 0): four points at 2 from it in z = 0, one at
// 1.8 (in the ring, >= 1.6), one at 1 (not), and two on the axis at z = 4 and -2: r 2, height
// 6, r_ring (4 2 + 1.8)/5 = 1.96. With directions appended after.
TEST(BodyExtents, RadiusAboutGivenCentre) {
    const fs::path root = freshCase("radius");
    Context<3> c(root);
    place<3>(c.particles,
             {Vector<3>(3, 1, 0), Vector<3>(-1, 1, 0), Vector<3>(1, 3, 0), Vector<3>(1, -1, 0),
              Vector<3>(1, 2.8, 0), Vector<3>(1, 2, 0), Vector<3>(1, 1, 4), Vector<3>(1, 1, -2)});
    {
        auto fo = make("type bodyExtents; mode radius; centre (1 1 0); axis (0 0 2); directions ((1 0 0));",
                       "radius", c);
        fo->write();
        EXPECT_TRUE(fo->referenceValues().empty());
    }
    EXPECT_EQ(header(csvOf(root, "radius")), "time,r,height,r_ring,l_d1");
    const auto row = functionObjectTest::csvRows(csvOf(root, "radius"))[0];
    ASSERT_EQ(row.size(), 5u);
    EXPECT_EQ(row[1], 2.0);
    EXPECT_EQ(row[2], 6.0);
    EXPECT_NEAR(row[3], 1.96, 1e-9 * 1.96);
    EXPECT_EQ(row[4], 4.0);
    fs::remove_all(root);
}

// The default centre: the centroid at each write. Masses 3 at (0 0 0) and 1 at (4 0 0): the
// centroid (1 0 0), distances 1 and 3: r 3, r_ring 3 (only the one at >= 2.4), height 0. Without
// masses (all zero) the mean position (2 0 0): r 2, r_ring 2. Moved by (10 5 7) the body measures
// the same (the centre follows).
TEST(BodyExtents, RadiusAboutTheCentroid) {
    const fs::path root = freshCase("centroid");
    Context<3> c(root);
    place<3>(c.particles, {Vector<3>(0, 0, 0), Vector<3>(4, 0, 0)});
    auto& mass = c.particles.scalarField("mass");
    {
        auto mean = make("type bodyExtents; mode radius;", "mean", c);
        mean->write();
        mass[0] = 3, mass[1] = 1;
        auto weighted = make("type bodyExtents; mode radius;", "weighted", c);
        weighted->write();
        for (std::size_t i = 0; i < 2; ++i) c.particles.position()[i] += Vector<3>(10, 5, 7);
        c.at(0.5);
        weighted->write();
    }
    const auto mean = functionObjectTest::csvRows(csvOf(root, "mean"));
    ASSERT_EQ(mean.size(), 1u);
    const double meanExpected[] = {0, 2, 0, 2};
    for (std::size_t k = 0; k < 4; ++k) EXPECT_EQ(mean[0][k], meanExpected[k]) << k;
    const auto weighted = functionObjectTest::csvRows(csvOf(root, "weighted"));
    ASSERT_EQ(weighted.size(), 2u);
    const double weightedExpected[2][4] = {{0, 3, 0, 3}, {0.5, 3, 0, 3}};
    for (std::size_t w = 0; w < 2; ++w)
        for (std::size_t k = 0; k < 4; ++k)
            EXPECT_NEAR(weighted[w][k], weightedExpected[w][k], 1e-14) << w << k;
    fs::remove_all(root);
}

// A tilted axis (1 1 0) (normalised) through the origin: (1 1 0) and (-1 -1 0) on it at heights
// sqrt 2 and -sqrt 2, (1 -1 0) at height 0 and sqrt 2 from it: r sqrt 2, height 2 sqrt 2.
TEST(BodyExtents, RadiusAboutTiltedAxis) {
    const fs::path root = freshCase("tilted");
    Context<3> c(root);
    place<3>(c.particles, {Vector<3>(1, 1, 0), Vector<3>(-1, -1, 0), Vector<3>(1, -1, 0)});
    {
        auto fo = make("type bodyExtents; mode radius; axis (1 1 0); centre (0 0 0);", "tilted", c);
        fo->write();
    }
    const auto row = functionObjectTest::csvRows(csvOf(root, "tilted"))[0];
    const double r2 = std::sqrt(2.0);
    EXPECT_NEAR(row[1], r2, 1e-9 * r2);
    EXPECT_NEAR(row[2], 2 * r2, 1e-9 * r2);
    EXPECT_NEAR(row[3], r2, 1e-9 * r2);
    fs::remove_all(root);
}

// 2D: about the out-of-plane axis through the mean position (0 0): (3 4) and (-3 -4) at 5, the
// origin at 0: r 5, no height column, r_ring 5.
TEST(BodyExtents, RadiusIn2D) {
    const fs::path root = freshCase("radius2");
    Context<2> c(root);
    place<2>(c.particles, {Vector<2>(3, 4), Vector<2>(-3, -4), Vector<2>(0, 0)});
    {
        auto fo = make("type bodyExtents; mode radius; region body;", "disc", c);
        fo->write();
    }
    EXPECT_EQ(header(csvOf(root, "disc")), "time,r,r_ring");
    const auto row = functionObjectTest::csvRows(csvOf(root, "disc"))[0];
    ASSERT_EQ(row.size(), 3u);
    EXPECT_EQ(row[1], 5.0);
    EXPECT_EQ(row[2], 5.0);
    fs::remove_all(root);
}

// An emptied region: the same RunError as mode bounds.
TEST(BodyExtents, RadiusOfAnEmptyBody) {
    const fs::path root = freshCase("empty");
    Context<3> c(root);
    place<3>(c.particles, {Vector<3>(0, 0, 0)});
    auto fo = make("type bodyExtents; mode radius; region body;", "empty", c);
    c.particles.resize(0);
    try {
        fo->write();
        ADD_FAILURE() << "no error";
    } catch (const RunError& e) {
        EXPECT_NE(std::string(e.what()).find("bodyExtents 'empty': no particle in region 'body'"),
                  std::string::npos)
            << e.what();
    }
    fs::remove_all(root);
}

TEST(BodyExtents, RefusedNewInput) {
    const fs::path root = freshCase("refused");
    Context<3> c3(root);
    place<3>(c3.particles, {Vector<3>(0, 0, 0)});
    Context<2> c2(root);
    place<2>(c2.particles, {Vector<2>(0, 0)});
    const auto has = [](const std::string& message, const std::string& part) {
        EXPECT_NE(message.find(part), std::string::npos) << message;
        EXPECT_NE(message.find("controlDict:1"), std::string::npos) << message;
    };
    has(errorOf("type bodyExtents; directions ((0 0 0));", c3), "a direction must be non-zero");
    has(errorOf("type bodyExtents; directions ((1 1));", c3), "'(1 1)': expected 3 components, found 2");
    has(errorOf("type bodyExtents; directions ();", c3), "the list is empty");
    has(errorOf("type bodyExtents; directions ((1 a 0));", c3), "holds a non-number");
    has(errorOf("type bodyExtents; directions (1 0 0);", c3), "is not a direction");
    has(errorOf("type bodyExtents; mode lines; directions ((1 1));", c2), "not lines");
    has(errorOf("type bodyExtents; axis (0 0 1);", c3), "axis is mode radius's");
    has(errorOf("type bodyExtents; mode lines; centre (0 0);", c2), "centre is mode radius's");
    has(errorOf("type bodyExtents; mode radius; axis (0 1);", c2), "out-of-plane axis: give no axis");
    has(errorOf("type bodyExtents; mode radius; axis (0 0 0);", c3), "non-zero");
    has(errorOf("type bodyExtents; mode radius; centre (0 0);", c3), "expected 3 components, found 2");
    has(errorOf("type bodyExtents; mode radius; reference (1 1 1);", c3), "not mode radius");
    fs::remove_all(root);
}
