// Material points for the material point method (issue 17 item 7; doc/methods/mpm.md sections 3,
// 4.1, 4.3, 4.7): the materialPoints lattice (sub-cell centres, 2^dim Gauss points per sub-cell),
// the 2D polygon shape, and particleGen's V_p = exact volume / N. The counts are the note's: 316
// and 3016 points for the disc of radius 0.2 (gauss, 10 x 10 and 31 x 31 sub-cells), 200 for the
// triangle of side 0.2 (gauss, 10 x 10), the spring's 10 points at y = 0.81 ... 0.99.
#include "core/Dictionary.hpp"
#include "core/Error.hpp"
#include "geometry/MaterialPointLattice.hpp"
#include "geometry/ParticleGenerator.hpp"
#include "particles/ParticleSet.hpp"

#include "GeometryTestUtils.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

using namespace mfdyn;

namespace {

struct Generated {
    std::unique_ptr<ParticleSetBase> set;
    std::vector<RegionReport> report;
};

Generated generate(const std::string& text) {
    const Dictionary dict = Dictionary::parse(text, "particleGenDict");
    ParticleGenerator gen(dict);
    Generated g;
    g.set = gen.generate();
    g.report = gen.report();
    return g;
}

std::string region(int dim, const std::string& shape, const std::string& lattice, double density = 1000) {
    return "dimension " + std::to_string(dim) + "; regions { body { shape { " + shape + " } lattice { " +
           lattice + " } density " + std::to_string(density) + "; } }";
}

std::string errorOf(const std::string& text) {
    try {
        generate(text);
    } catch (const InputError& e) {
        return e.what();
    }
    return "no error";
}

const std::string disc = "type sphere; centre (0.2 0.2); radius 0.2;";
const std::string triangle = "type polygon; vertices ((0 0) (0.2 0) (0.1 0.17320508075688773));";

}  // namespace

// mpm_circ, pattern 2: 316 points with 10 x 10 sub-cells, 3016 with 31 x 31; each with
// V_p = pi r^2 / N and mass rho V_p, so the disc's mass is rho pi r^2 (the two disks' K(0) of
// 2.51327 = rho pi r^2 |v|^2 needs exactly that).
TEST(MaterialPoints, DiscCountsOfTheNote) {
    for (const auto& [cells, count] : {std::pair{10, 316u}, std::pair{31, 3016u}}) {
        const std::string n = std::to_string(cells);
        const auto g =
            generate(region(2, disc, "type materialPoints; cells (" + n + " " + n + "); pattern gauss;"));
        ASSERT_EQ(g.report.size(), 1u);
        EXPECT_EQ(g.report[0].count, count) << cells;
        const double area = std::numbers::pi * 0.04;
        const auto& mass = particleSetCast<2>(*g.set).scalarField("mass");
        for (double m : mass) EXPECT_NEAR(m, 1000 * area / count, 1e-15) << cells;
        // The report sums the N masses: rounding about N x 1e-16 relative.
        EXPECT_NEAR(g.report[0].mass, 1000 * area, 1e-13 * 1000 * area) << cells;
        EXPECT_NEAR(g.report[0].volume, area, 1e-14) << cells;
    }
    // Pattern centre over 20 x 20 sub-cells (the same 0.02 point distance): a different count,
    // still sharing the exact area.
    const auto c = generate(region(2, disc, "type materialPoints; cells (20 20);"));
    EXPECT_EQ(c.report[0].count, 316u);
    EXPECT_NEAR(c.report[0].volume, std::numbers::pi * 0.04, 1e-14);
}

// mpm_tria, pattern 2, 10 x 10 sub-cells over the bounding box 0.2 x 0.1732 of the equilateral
// triangle, apex up: 200 points (the float's solid, note section 4.7).
TEST(MaterialPoints, TriangleCountOfTheNote) {
    const auto g = generate(region(2, triangle, "type materialPoints; cells (10 10); pattern gauss;", 917));
    EXPECT_EQ(g.report[0].count, 200u);
    const double area = std::sqrt(3.0) / 4 * 0.04;
    EXPECT_NEAR(g.report[0].exactVolume, area, 1e-16);
    EXPECT_NEAR(g.report[0].mass, 917 * area, 1e-12);
    // Apex down (vertices clockwise): the same count by symmetry.
    const auto d = generate(
        region(2, "type polygon; vertices ((0.1 0) (0.2 0.17320508075688773) (0 0.17320508075688773));",
               "type materialPoints; cells (10 10); pattern gauss;", 917));
    EXPECT_EQ(d.report[0].count, 200u);
}

// mpm_rect([x0, 0.8], [0.02, 0.2], [1, 10], 1): 10 points at x0 + 0.01, y = 0.81 ... 0.99 (step
// 0.02), V0 = 4e-4 and m = 0.6 at rho = 1500 (note section 4.1).
TEST(MaterialPoints, SpringOfTheNote) {
    const auto g = generate(region(2, "type box; min (0.02 0.8); max (0.04 1.0);",
                                   "type materialPoints; cells (1 10); pattern centre;", 1500));
    auto& p = particleSetCast<2>(*g.set);
    ASSERT_EQ(p.size(), 10u);
    for (std::size_t i = 0; i < 10; ++i) {
        EXPECT_NEAR(p.position()[i][0], 0.03, 1e-15);
        EXPECT_NEAR(p.position()[i][1], 0.81 + 0.02 * double(i), 1e-15);
        EXPECT_NEAR(p.scalarField("mass")[i], 0.6, 1e-14);
        EXPECT_EQ(p.scalarField("density")[i], 1500.0);
        EXPECT_EQ(p.region()[i], 0u);
    }
}

// The Gauss points sit at -+ h / (2 sqrt 3) of each sub-cell centre; in 3D 8 per sub-cell; in 1D 2.
TEST(MaterialPoints, GaussPointPositions) {
    const auto l = test::lattice("type materialPoints; cells (2 1); pattern gauss;", 2);
    BoundingBox box;
    box.min = {0, 0, 0};
    box.max = {1, 0.5, 0};
    const auto p = l->points(box);
    ASSERT_EQ(p.size(), 8u * 2);  // 2 sub-cells x 4 points
    const double g = 0.5 / std::sqrt(3.0);
    // x fastest: row y = 0.25 - 0.5 g first.
    const double xs[4] = {0.25 - 0.5 * g, 0.25 + 0.5 * g, 0.75 - 0.5 * g, 0.75 + 0.5 * g};
    for (int i = 0; i < 4; ++i) {
        EXPECT_NEAR(p[2 * i], xs[i], 1e-15);
        EXPECT_NEAR(p[2 * i + 1], 0.25 - 0.5 * g, 1e-15);
        EXPECT_NEAR(p[8 + 2 * i + 1], 0.25 + 0.5 * g, 1e-15);
    }
    // The lattice volumes: sub-cell / 4.
    for (double v : l->pointVolumes(box, p)) EXPECT_NEAR(v, 0.5 * 0.5 / 4, 1e-16);

    const auto cube = generate(region(3, "type box; min (0 0 0); max (0.1 0.1 0.1);",
                                      "type materialPoints; cells (3 3 3); pattern gauss;"));
    EXPECT_EQ(cube.report[0].count, 216u);
    EXPECT_NEAR(cube.report[0].mass, 1.0, 1e-12);  // 1000 x 0.001
    const auto bar = generate(
        region(1, "type box; min (0); max (1);", "type materialPoints; spacing 0.1; pattern gauss;"));
    EXPECT_EQ(bar.report[0].count, 20u);
}

// `spacing` rounds to a whole number of sub-cells of the bounding box: 0.03 on a length of 0.1
// gives 3 sub-cells of 0.0333.
TEST(MaterialPoints, SpacingFitsTheBox) {
    const auto l = test::lattice("type materialPoints; spacing 0.03;", 2);
    BoundingBox box;
    box.max = {0.1, 0.2, 0};
    const auto* mp = dynamic_cast<const MaterialPointLattice*>(l.get());
    ASSERT_NE(mp, nullptr);
    EXPECT_EQ(mp->cells(box)[0], 3);
    EXPECT_EQ(mp->cells(box)[1], 7);
    EXPECT_NEAR(mp->cellSizes(box)[0], 0.1 / 3, 1e-16);
    EXPECT_EQ(l->points(box).size(), 21u * 2);
}

// A shape without a closed-form volume keeps the lattice volumes (sub-cell / points per
// sub-cell), here the disc minus a box, whose particles then stand for the sub-cells they fill.
TEST(MaterialPoints, CsgShapeKeepsTheLatticeVolume) {
    const auto g = generate(region(2,
                                   "type difference; shapes ( { type sphere; centre (0.2 0.2); radius 0.2; } "
                                   "{ type box; min (0.2 0); max (0.4 0.4); } );",
                                   "type materialPoints; cells (10 10); pattern gauss;"));
    EXPECT_EQ(g.report[0].count, 158u);  // half of 316, the disc's points being symmetric about x = 0.2
    EXPECT_NEAR(g.report[0].volume, 158 * 0.04 * 0.04 / 4, 1e-14);
}

TEST(MaterialPoints, BadInputNamesTheEntry) {
    const std::string both = errorOf(region(2, disc, "type materialPoints; cells (10 10); spacing 0.01;"));
    EXPECT_NE(both.find("exactly one of `cells"), std::string::npos) << both;
    const std::string neither = errorOf(region(2, disc, "type materialPoints;"));
    EXPECT_NE(neither.find("exactly one of `cells"), std::string::npos) << neither;
    const std::string count = errorOf(region(2, disc, "type materialPoints; cells (10 2.5);"));
    EXPECT_NE(count.find("whole numbers"), std::string::npos) << count;
    EXPECT_NE(count.find("particleGenDict:1"), std::string::npos) << count;
    const std::string short_ =
        errorOf(region(3, "type sphere; centre (0 0 0); radius 1;", "type materialPoints; cells (10 10);"));
    EXPECT_NE(short_.find("3 sub-cell counts"), std::string::npos) << short_;
    const std::string pattern = errorOf(region(2, disc, "type materialPoints; cells (10 10); pattern gaus;"));
    EXPECT_NE(pattern.find("gauss"), std::string::npos) << pattern;
    EXPECT_NE(pattern.find("centre"), std::string::npos) << pattern;
    const std::string equal =
        errorOf("dimension 2; regions { a { shape { " + disc +
                " } lattice { type materialPoints; spacing 0.01; } density 1000; mass equalMass; } }");
    EXPECT_NE(equal.find("equalMass"), std::string::npos) << equal;
}

// polygon: area by the shoelace formula, even-odd inside, errors for a bad outline.
TEST(PolygonShape, AreaInsideAndErrors) {
    const auto l = test::shape("type polygon; vertices ((0 0) (2 0) (2 1) (1 1) (1 2) (0 2));", 2);  // an L
    EXPECT_NEAR(*l->volume(), 3.0, 1e-15);
    const double in[2] = {0.5, 1.5}, out[2] = {1.5, 1.5}, below[2] = {1.5, 0.5};
    EXPECT_TRUE(l->inside(in));
    EXPECT_FALSE(l->inside(out));
    EXPECT_TRUE(l->inside(below));
    EXPECT_EQ(l->bounds().max[0], 2.0);
    EXPECT_EQ(l->bounds().min[1], 0.0);
    // A cubic lattice fills it to its area (whole cells).
    const auto filled = test::fill(*l, *test::lattice("type cubic; spacing 0.1;", 2));
    EXPECT_EQ(filled.count, 300u);

    const auto error = [](const std::string& text, int dim) {
        try {
            test::shape(text, dim);
        } catch (const InputError& e) {
            return std::string(e.what());
        }
        return std::string("no error");
    };
    EXPECT_NE(error("type polygon; vertices ((0 0) (1 0));", 2).find("at least 3"), std::string::npos);
    EXPECT_NE(error("type polygon; vertices ((0 0) (1 1) (1 0) (0 1));", 2).find("simple"),
              std::string::npos);
    EXPECT_NE(error("type polygon; vertices ((0 0) (1 0) (2 0));", 2).find("area"), std::string::npos);
    EXPECT_NE(error("type polygon; vertices ((0 0) (1 0) (1 0) (0 1));", 2).find("same point"),
              std::string::npos);
    EXPECT_NE(error("type polygon; vertices ((0 0 0) (1 0 0) (0 1 0));", 3).find("2D shape"),
              std::string::npos);
    const std::string huge = error("type polygon; vertices ((0 0) (1 0) (0 1e200));", 2);
    EXPECT_NE(huge.find("1e150"), std::string::npos) << huge;
}
