// bodyCentroid (issue 18 item 5: a body's centroid and draft, a fluid's mean height) on hand-made
// particle sets, built through FunctionObject::New from a dictionary as controlDict gives it: the
// mass-weighted centroid, the extremes along up (default and tilted), the depths below a level and
// the largest of them over writes, the summary's mass to 17 digits, and the refused input.
// Every value is a short hand sum of a few binary-exact numbers: equality to a few ulps (the
// CSV's 10 significant digits where they are not short).
#include "FunctionObjectTestCase.hpp"
#include "core/Dictionary.hpp"
#include "core/Error.hpp"
#include "functionObjects/FunctionObject.hpp"
#include "particles/ParticleSet.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

using namespace mfdyn;
namespace fs = std::filesystem;

namespace {

template <int Dim>
using Context = functionObjectTest::TestContext<Dim>;
fs::path freshCase(const std::string& tag) {
    return functionObjectTest::freshCase("BodyCentroid", tag);
}

std::vector<std::string> lines(const fs::path& file) {
    std::ifstream in(file);
    std::vector<std::string> out;
    for (std::string line; std::getline(in, line);) out.push_back(line);
    return out;
}

std::vector<double> numbers(const std::string& line) {
    std::vector<double> out;
    std::istringstream in(line);
    for (std::string cell; std::getline(in, cell, ',');) out.push_back(std::stod(cell));
    return out;
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

// A drop over a pool in 2D: pool (region 0) m 2 at (0 0), m 2 at (4 0), m 4 at (1 1);
// drop (region 1) m 1 at (2 3), m 3 at (2 5).
// pool: M 8, c = (0 + 8 + 4, 0 + 0 + 4) / 8 = (1.5, 0.5), y in [0, 1];
// drop: M 4, c = (2, (3 + 15) / 4 = 4.5), y in [3, 5].
void dropAndPool(ParticleSet<2>& p) {
    p.resize(5);
    p.regionNames = {"pool", "drop"};
    const double m[5] = {2, 2, 4, 1, 3}, x[5][2] = {{0, 0}, {4, 0}, {1, 1}, {2, 3}, {2, 5}};
    const std::int64_t r[5] = {0, 0, 0, 1, 1};
    auto& mass = p.scalarField("mass");
    for (std::size_t i = 0; i < 5; ++i) {
        mass[i] = m[i];
        p.position()[i] = Vector<2>(x[i][0], x[i][1]);
        p.region()[i] = r[i];
        p.globalId()[i] = std::int64_t(i);
    }
}

}  // namespace

TEST(BodyCentroid, CentroidExtremesAndDepths) {
    const fs::path root = freshCase("values");
    Context<2> c(root);
    dropAndPool(c.particles);
    {
        auto fo = make("type bodyCentroid; regions (drop pool); level 4;", "bodies", c);
        fo->write();
        // The drop moves down by 2 (lowest 1: 3 below the level), then back up by 1: the largest
        // depth stays the one at t = 0.5.
        c.at(0.5);
        for (std::size_t i = 3; i < 5; ++i) c.particles.position()[i][1] -= 2;
        fo->write();
        c.at(0.75);
        for (std::size_t i = 3; i < 5; ++i) c.particles.position()[i][1] += 1;
        fo->write();
        const auto summary = fo->summary();
        ASSERT_EQ(summary.size(), 4u);  // 2 bodies x (values, depths)
        EXPECT_NE(summary[0].find("body drop: at t = 0.75 mass 4 (first write 4, change 0.000e+00), centroid "
                                  "(2 3.5), height 3.5, lowest 2, highest 4"),
                  std::string::npos)
            << summary[0];
        EXPECT_NE(summary[1].find("below the level 4: depth 2 (centroid 0.5), largest depth 3 at t = 0.5"),
                  std::string::npos)
            << summary[1];
    }
    const auto csv = lines(root / "postProcessing" / "bodies" / "0" / "bodyCentroid.csv");
    ASSERT_EQ(csv.size(), 4u);
    EXPECT_EQ(
        csv[0],
        "time,drop_mass,drop_centroid_x,drop_centroid_y,drop_height,drop_lowest,drop_highest,drop_depth,"
        "drop_centroidDepth,pool_mass,pool_centroid_x,pool_centroid_y,pool_height,pool_lowest,"
        "pool_highest,pool_depth,pool_centroidDepth");
    const auto first = numbers(csv[1]);
    const double expected[] = {0, 4, 2, 4.5, 4.5, 3, 5, 1, -0.5, 8, 1.5, 0.5, 0.5, 0, 1, 4, 3.5};
    ASSERT_EQ(first.size(), 17u);
    for (std::size_t k = 0; k < 17; ++k) EXPECT_DOUBLE_EQ(first[k], expected[k]) << csv[0] << " column " << k;
    const auto second = numbers(csv[2]);
    EXPECT_DOUBLE_EQ(second[3], 2.5);   // the drop's centroid y
    EXPECT_DOUBLE_EQ(second[7], 3.0);   // its depth 4 - 1
    EXPECT_DOUBLE_EQ(second[15], 4.0);  // the pool's unchanged
    fs::remove_all(root);
}

// Every region by default; up tilted to (1 1)/sqrt 2: the pool's heights x.u are 0, 4/sqrt 2 and
// 2/sqrt 2 (lowest 0, highest 2 sqrt 2), its centroid's (1.5 + 0.5)/sqrt 2 = sqrt 2. Up given
// as (2 2) is normalised first.
TEST(BodyCentroid, TiltedUpAndDefaultRegions) {
    const fs::path root = freshCase("tilted");
    Context<2> c(root);
    dropAndPool(c.particles);
    {
        auto fo = make("type bodyCentroid; up (2 2);", "tilted", c);
        fo->write();
    }
    const auto csv = lines(root / "postProcessing" / "tilted" / "0" / "bodyCentroid.csv");
    ASSERT_EQ(csv.size(), 2u);
    EXPECT_EQ(csv[0].substr(0, 15), "time,pool_mass,");  // the run's region order
    const auto row = numbers(csv[1]);
    ASSERT_EQ(row.size(), 13u);  // no level: 6 columns a body
    // The CSV holds 10 significant digits: a relative 1e-9.
    const double r2 = std::sqrt(2.0), digits = 1e-9;
    EXPECT_NEAR(row[4], r2, digits * r2);               // pool height
    EXPECT_EQ(row[5], 0.0);                             // pool lowest
    EXPECT_NEAR(row[6], 2 * r2, digits * 2 * r2);       // pool highest
    EXPECT_NEAR(row[10], 6.5 / r2, digits * 6.5 / r2);  // drop height (2 + 4.5)/sqrt 2
    EXPECT_NEAR(row[11], 5 / r2, digits * 5 / r2);      // drop lowest (2 + 3)/sqrt 2
    fs::remove_all(root);
}

// 3D: up defaults to +z.
TEST(BodyCentroid, DefaultUpIsZIn3D) {
    const fs::path root = freshCase("3d");
    Context<3> c(root);
    auto& p = c.particles;
    p.resize(2);
    p.regionNames = {"block"};
    auto& mass = p.scalarField("mass");
    mass[0] = 1, mass[1] = 3;
    p.position()[0] = Vector<3>(0, 7, 1);
    p.position()[1] = Vector<3>(4, -1, 5);
    p.region()[0] = p.region()[1] = 0;
    p.globalId()[0] = 0, p.globalId()[1] = 1;
    {
        auto fo = make("type bodyCentroid;", "block", c);
        fo->write();
    }
    const auto row = numbers(lines(root / "postProcessing" / "block" / "0" / "bodyCentroid.csv")[1]);
    ASSERT_EQ(row.size(), 8u);
    const double expected[] = {0, 4, 3, 1, 4, 4, 1, 5};  // t, M, c (3 1 4), height 4, z in [1, 5]
    for (std::size_t k = 0; k < 8; ++k) EXPECT_DOUBLE_EQ(row[k], expected[k]) << k;
    fs::remove_all(root);
}

// A body whose particles are all removed: mass 0, the rest NaN, the mass change in the summary.
TEST(BodyCentroid, EmptiedBody) {
    const fs::path root = freshCase("empty");
    Context<2> c(root);
    dropAndPool(c.particles);
    auto fo = make("type bodyCentroid; regions (drop);", "drop", c);
    fo->write();
    c.particles.resize(3);  // the drop's two points are the last two
    c.at(0.5);
    fo->write();
    const auto summary = fo->summary();
    ASSERT_EQ(summary.size(), 1u);
    EXPECT_NE(summary[0].find("mass 0 (first write 4, change -4.000e+00)"), std::string::npos) << summary[0];
    const auto row = numbers(lines(root / "postProcessing" / "drop" / "0" / "bodyCentroid.csv")[2]);
    EXPECT_EQ(row[1], 0.0);
    EXPECT_TRUE(std::isnan(row[2]) && std::isnan(row[5])) << row[2] << " " << row[5];
    fs::remove_all(root);
}

TEST(BodyCentroid, RefusedInput) {
    const fs::path root = freshCase("errors");
    Context<2> c(root);
    dropAndPool(c.particles);
    const std::string unknown = errorOf("type bodyCentroid; regions (drop lake);", c);
    EXPECT_NE(unknown.find("controlDict:1"), std::string::npos) << unknown;
    EXPECT_NE(unknown.find("no region 'lake' in this run; regions: pool drop"), std::string::npos) << unknown;
    const std::string zero = errorOf("type bodyCentroid; up (0 0);", c);
    EXPECT_NE(zero.find("controlDict:1"), std::string::npos) << zero;
    EXPECT_NE(zero.find("up"), std::string::npos) << zero;
    EXPECT_NE(zero.find("non-zero"), std::string::npos) << zero;
    const std::string shortUp = errorOf("type bodyCentroid; up (1);", c);
    EXPECT_NE(shortUp.find("expected 2 components"), std::string::npos) << shortUp;
    fs::remove_all(root);
}
