// The gridBoundaryCondition family: each type built from a dictionary through New, as a case
// builds it, and applied to node velocities and accelerations with hand-computed results.
#include "grid/gridBoundaryConditions/GridBoundaryCondition.hpp"
#include "grid/gridBoundaryConditions/GridFixed.hpp"
#include "grid/gridBoundaryConditions/GridFriction.hpp"
#include "grid/gridBoundaryConditions/GridOpen.hpp"
#include "grid/gridBoundaryConditions/GridPrescribedVelocity.hpp"
#include "grid/gridBoundaryConditions/GridSlip.hpp"

#include "../SchemaTestTools.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

using namespace mfdyn;

namespace {

// 4 x 3 cells of 0.25: 5 x 4 nodes, index i + 5 j.
CartesianGrid<2> grid2() {
    return CartesianGrid<2>(Vector<2>(0.0, 0.0), Vector<2>(0.25, 0.25), {4, 3});
}

template <int Dim>
std::unique_ptr<GridBoundaryCondition<Dim>> make(const std::string& text, const CartesianGrid<Dim>& grid) {
    const Dictionary dict =
        Dictionary::parse("gridBoundaryConditions {\nwall {\n" + text + "\n}\n}\n", "constant/mpmProperties");
    return GridBoundaryCondition<Dim>::New(dict.subDict("gridBoundaryConditions").subDict("wall"), grid);
}

std::string errorOf(const std::string& text) {
    return test::inputErrorOf([&] { make<2>(text, grid2()); }, text);
}

template <int Dim>
struct Fields {
    std::vector<Vector<Dim>> v, a;
    Fields(std::size_t n, const Vector<Dim>& v0, const Vector<Dim>& a0) : v(n, v0), a(n, a0) {}
};

}  // namespace

TEST(GridBoundaryCondition, slipRemovesExactlyTheNormalComponent) {
    const auto g = grid2();
    const auto slip = make<2>("type slip; faces (yMin);", g);
    Fields<2> f(g.nodeCount(), Vector<2>(0.3, -0.7), Vector<2>(2.0, -9.81));
    slip->apply(g, f.v, &f.a, 0.1, 1e-3);
    // Node 2 (i = 2, j = 0) moves into the floor: it keeps v_x, loses v_y, bit for bit.
    EXPECT_EQ(f.v[2], Vector<2>(0.3, 0.0));
    EXPECT_EQ(f.a[2], Vector<2>(2.0, 0.0));
    // Node 7 (j = 1) is not on the wall.
    EXPECT_EQ(f.v[7], Vector<2>(0.3, -0.7));
    // Moving away the normal component goes too (no separation within a step, cb-geo's rule).
    f.v[3] = Vector<2>(-0.1, 0.4);
    slip->apply(g, f.v, nullptr, 0.1, 1e-3);
    EXPECT_EQ(f.v[3], Vector<2>(-0.1, 0.0));
    EXPECT_EQ(slip->describe(), "wall: slip on faces (yMin), 5 nodes, the faces' normals");
}

TEST(GridBoundaryCondition, slipOnTwoFacesStopsTheCornerBothWays) {
    const auto g = grid2();
    const auto slip = make<2>("type slip; faces (xMin yMin);", g);
    Fields<2> f(g.nodeCount(), Vector<2>(0.3, -0.7), Vector<2>(1.0, 1.0));
    slip->apply(g, f.v, &f.a, 0.0, 1e-3);
    EXPECT_EQ(f.v[0], Vector<2>(0.0, 0.0));   // the corner
    EXPECT_EQ(f.v[5], Vector<2>(0.0, -0.7));  // xMin only
    EXPECT_EQ(f.v[1], Vector<2>(0.3, 0.0));   // yMin only
    EXPECT_EQ(f.a[0], Vector<2>(0.0, 0.0));
    // A given normal applies to every node of a shape selection.
    const auto wall = make<2>("type slip; normal (-1 0); shape { type box; min (0.4 -1); max (0.6 2); }", g);
    Fields<2> h(g.nodeCount(), Vector<2>(0.3, -0.7), Vector<2>(1.0, 1.0));
    wall->apply(g, h.v, &h.a, 0.0, 1e-3);
    EXPECT_EQ(h.v[2], Vector<2>(0.0, -0.7));  // x = 0.5
    EXPECT_EQ(h.v[3], Vector<2>(0.3, -0.7));  // x = 0.75, outside
}

TEST(GridBoundaryCondition, frictionSlowsTheTangentialVelocityByMuTimesTheNormalChange) {
    const auto g = grid2();
    const auto friction = make<2>("type friction; mu 0.3; faces (yMin);", g);
    Fields<2> f(g.nodeCount(), Vector<2>(1.0, -0.5), Vector<2>(2.0, 3.0));
    const double dt = 0.01;
    friction->apply(g, f.v, &f.a, 0.0, dt);
    // dv_n = 0.5 removed; |v_t| = 1 slowed by 0.3 x 0.5 = 0.15 to 0.85; the 0.15 over dt = 15
    // m/s^2 comes off a_x = 2, the normal rate goes as for slip.
    EXPECT_DOUBLE_EQ(f.v[1][0], 0.85);
    EXPECT_EQ(f.v[1][1], 0.0);
    EXPECT_NEAR(f.a[1][0], 2.0 - 15.0, 1e-12);  // (1 - 0.85) / 0.01 carries round-off of 1e-15 / 0.01
    EXPECT_EQ(f.a[1][1], 0.0);
    // Stick: |v_t| = 0.1 < mu dv_n = 0.15 stops, never reverses.
    f.v[2] = Vector<2>(-0.1, -0.5);
    friction->apply(g, f.v, nullptr, 0.0, dt);
    EXPECT_EQ(f.v[2], Vector<2>(0.0, 0.0));
    // Leaving the wall: untouched.
    f.v[3] = Vector<2>(1.0, 0.5);
    f.a[3] = Vector<2>(2.0, 3.0);
    friction->apply(g, f.v, &f.a, 0.0, dt);
    EXPECT_EQ(f.v[3], Vector<2>(1.0, 0.5));
    EXPECT_EQ(f.a[3], Vector<2>(2.0, 3.0));
    EXPECT_EQ(friction->describe(), "wall: friction on faces (yMin), 5 nodes, mu 0.3, the faces' normals");
}

TEST(GridBoundaryCondition, frictionOnAnUpperWallIn3D) {
    const CartesianGrid<3> g(Vector<3>(0, 0, 0), Vector<3>(1, 1, 1), {2, 2, 2});
    const auto friction = make<3>("type friction; mu 0.3; faces (yMax);", g);
    // At yMax the material is below: moving into the wall is v_y > 0. dv_n = 1, |v_t| = 1
    // (0.6, 0.8): slowed by 0.3 to 0.7 of itself, direction kept.
    std::vector<Vector<3>> v(g.nodeCount(), Vector<3>(0.6, 1.0, 0.8));
    friction->apply(g, v, nullptr, 0.0, 1e-3);
    const auto n = g.nodeIndex({1, 2, 1});
    EXPECT_NEAR(v[n][0], 0.42, 1e-15);
    EXPECT_EQ(v[n][1], 0.0);
    EXPECT_NEAR(v[n][2], 0.56, 1e-15);
    EXPECT_EQ(v[g.nodeIndex({1, 1, 1})], Vector<3>(0.6, 1.0, 0.8));
    // mu = 0 is slip while in contact.
    const auto frictionless = make<3>("type friction; mu 0; faces (yMax);", g);
    std::vector<Vector<3>> w(g.nodeCount(), Vector<3>(0.6, 1.0, 0.8));
    frictionless->apply(g, w, nullptr, 0.0, 1e-3);
    EXPECT_EQ(w[n], Vector<3>(0.6, 0.0, 0.8));
}

TEST(GridBoundaryCondition, prescribedVelocityInterpolatesItsTablePerComponent) {
    const auto g = grid2();
    const auto lid = make<2>(
        "type prescribedVelocity; faces (yMax); table ((0 (0 0)) (1 (2 -4)) (3 (2 0))); components (y);", g);
    Fields<2> f(g.nodeCount(), Vector<2>(7.0, 7.0), Vector<2>(5.0, 5.0));
    const auto top = g.nodeIndex({2, 3});
    // t = 0.5: halfway up the first row pair, v_y = -2 with slope -4; v_x is free and kept.
    lid->apply(g, f.v, &f.a, 0.5, 1e-3);
    EXPECT_EQ(f.v[top], Vector<2>(7.0, -2.0));
    EXPECT_EQ(f.a[top], Vector<2>(5.0, -4.0));
    // t = 2: the second pair, v_y = -4 + (0 + 4) / 2 = -2 with slope +2.
    lid->apply(g, f.v, &f.a, 2.0, 1e-3);
    EXPECT_DOUBLE_EQ(f.v[top][1], -2.0);
    EXPECT_DOUBLE_EQ(f.a[top][1], 2.0);
    // Beyond the table: held at the last row, no rate.
    lid->apply(g, f.v, &f.a, 5.0, 1e-3);
    EXPECT_EQ(f.v[top][1], 0.0);
    EXPECT_EQ(f.a[top][1], 0.0);
    lid->apply(g, f.v, &f.a, -1.0, 1e-3);
    EXPECT_EQ(f.v[top][1], 0.0);
    EXPECT_EQ(f.v[g.nodeIndex({2, 2})], Vector<2>(7.0, 7.0));  // not on the lid
    // A constant: the rate is zero.
    const auto push = make<2>("type prescribedVelocity; faces (xMin); velocity (0.5 0 0);", g);
    push->apply(g, f.v, &f.a, 1.0, 1e-3);
    EXPECT_EQ(f.v[0], Vector<2>(0.5, 0.0));
    EXPECT_EQ(f.a[0], Vector<2>(0.0, 0.0));
}

TEST(GridBoundaryCondition, fixedAndOpen) {
    const auto g = grid2();
    Fields<2> f(g.nodeCount(), Vector<2>(0.3, -0.7), Vector<2>(2.0, -9.81));
    make<2>("type fixed; faces (xMax);", g)->apply(g, f.v, &f.a, 0.0, 1e-3);
    EXPECT_EQ(f.v[4], Vector<2>(0.0, 0.0));
    EXPECT_EQ(f.a[19], Vector<2>(0.0, 0.0));
    EXPECT_EQ(f.v[3], Vector<2>(0.3, -0.7));
    // Only v_y on the top nodes, as the thesis's spring.
    const auto top = make<2>("type fixed; faces (yMax); components (y);", g);
    top->apply(g, f.v, &f.a, 0.0, 1e-3);
    EXPECT_EQ(f.v[16], Vector<2>(0.3, 0.0));
    EXPECT_EQ(f.a[16], Vector<2>(2.0, 0.0));
    EXPECT_EQ(top->describe(), "wall: fixed on faces (yMax), 5 nodes, components (y)");
    const Fields<2> before = f;
    make<2>("type open; all yes;", g)->apply(g, f.v, &f.a, 0.0, 1e-3);
    EXPECT_EQ(f.v, before.v);
    EXPECT_EQ(f.a, before.a);
}

TEST(GridBoundaryCondition, theListAppliesInOrderTheLaterWinning) {
    const auto g = grid2();
    const Dictionary dict = Dictionary::parse(
        "gridBoundaryConditions {\n"
        "  floor { type fixed; faces (yMin); }\n"
        "  belt  { type prescribedVelocity; faces (yMin); velocity (1 0); components (x); }\n"
        "}\n",
        "constant/mpmProperties");
    const GridBoundaryConditionList<2> list(dict.subDict("gridBoundaryConditions"), g);
    ASSERT_EQ(list.size(), 2u);
    std::vector<Vector<2>> v(g.nodeCount(), Vector<2>(0.3, -0.7));
    list.apply(g, v, nullptr, 0.0, 1e-3);
    EXPECT_EQ(v[1], Vector<2>(1.0, 0.0));
    EXPECT_EQ(list.describe()[1],
              "belt: prescribedVelocity on faces (yMin), 5 nodes, velocity (1 0), components (x)");
    const Dictionary plain = Dictionary::parse("g {\n floor fixed;\n}\n", "constant/mpmProperties");
    const std::string e =
        test::inputErrorOf([&] { GridBoundaryConditionList<2>(plain.subDict("g"), g); }, "a plain entry");
    EXPECT_NE(e.find("constant/mpmProperties:2"), std::string::npos) << e;
    EXPECT_NE(e.find("found a plain entry"), std::string::npos) << e;
}

TEST(GridBoundaryCondition, misspeltTypeListsTheValidOnes) {
    const std::string e = errorOf("type slp; faces (yMin);");
    EXPECT_NE(e.find("did you mean 'slip'"), std::string::npos) << e;
    for (const char* type : {"fixed", "friction", "open", "prescribedVelocity", "slip"})
        EXPECT_NE(e.find(type), std::string::npos) << type << " missing from: " << e;
    EXPECT_NE(e.find("constant/mpmProperties:3"), std::string::npos) << e;
}

TEST(GridBoundaryCondition, badEntriesAreInputErrors) {
    std::string e = errorOf("type slip; normal (1 1); faces (yMin);");
    EXPECT_NE(e.find("along one axis"), std::string::npos) << e;
    e = errorOf("type slip; shape { type box; min (0 0); max (1 1); }");
    EXPECT_NE(e.find("needs its normal"), std::string::npos) << e;
    e = errorOf("type friction; faces (yMin);");
    EXPECT_NE(e.find("mu"), std::string::npos) << e;
    e = errorOf("type friction; mu -0.1; faces (yMin);");
    EXPECT_NE(e.find(">= 0"), std::string::npos) << e;
    e = errorOf("type prescribedVelocity; faces (yMin);");
    EXPECT_NE(e.find("neither of `velocity` and `table`"), std::string::npos) << e;
    e = errorOf("type prescribedVelocity; faces (yMin); velocity (1 0); table ((0 (1 0)));");
    EXPECT_NE(e.find("both"), std::string::npos) << e;
    e = errorOf("type prescribedVelocity; faces (yMin); table ((0 (1 0)) (0 (2 0)));");
    EXPECT_NE(e.find("the times must increase"), std::string::npos) << e;
    e = errorOf("type prescribedVelocity; faces (yMin); table ((0 (1 0 3)));");
    EXPECT_NE(e.find("non-zero, but the grid is 2D"), std::string::npos) << e;
    e = errorOf("type fixed; faces (yMin); components (z);");
    EXPECT_NE(e.find("valid components: x y"), std::string::npos) << e;
    e = errorOf("type fixed;");
    EXPECT_NE(e.find("no grid nodes selected"), std::string::npos) << e;
}

TEST(GridBoundaryCondition, schemasAreRegisteredAndEndWithTheSelection) {
    test::expectRegisteredSchemas(
        "gridBoundaryCondition",
        {GridFixed<2>::keywords(), GridSlip<2>::keywords(), GridFriction<2>::keywords(),
         GridPrescribedVelocity<2>::keywords(), GridOpen<2>::keywords()},
        "libraries/grid/gridBoundaryConditions/");
    for (const auto& schema : {GridFixed<3>::keywords(), GridSlip<3>::keywords(), GridFriction<3>::keywords(),
                               GridPrescribedVelocity<3>::keywords(), GridOpen<3>::keywords()})
        test::expectEndsWith(schema, commonGridBoundaryConditionKeywords());
}
