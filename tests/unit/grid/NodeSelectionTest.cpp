// NodeSelection: faces by index (exact, corners on both faces), a plane's side test, shapes
// through geometry's Shape::New, `all`, their intersection, and the errors of a selection that
// selects nothing or names a face the grid does not have.
#include "grid/NodeSelection.hpp"

#include "../SchemaTestTools.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

using namespace mfdyn;

namespace {

using Nodes = std::vector<std::int64_t>;

// 4 x 3 cells of 0.25 x 1/3 (the y size not exact in binary, so positions carry round-off).
CartesianGrid<2> grid2() {
    return CartesianGrid<2>(Vector<2>(0.0, 0.0), Vector<2>(0.25, 1.0 / 3.0), {4, 3});
}

template <int Dim>
NodeSelection<Dim> select(const std::string& text, const CartesianGrid<Dim>& grid) {
    const Dictionary dict = Dictionary::parse("sel {\n" + text + "\n}\n", "constant/mpmProperties");
    return NodeSelection<Dim>(dict.subDict("sel"), grid);
}

std::string errorOf(const std::string& text) {
    return test::inputErrorOf([&] { select<2>(text, grid2()); }, text);
}

}  // namespace

TEST(NodeSelection, facesAreExactAndIncludeTheCorners) {
    const auto g = grid2();  // 5 x 4 nodes, index i + 5 j
    EXPECT_EQ(select<2>("faces (xMin);", g).nodes(), (Nodes{0, 5, 10, 15}));
    EXPECT_EQ(select<2>("faces (yMax);", g).nodes(), (Nodes{15, 16, 17, 18, 19}));
    // Union of faces, sorted, each node once (the corner 15 is on both).
    EXPECT_EQ(select<2>("faces (yMax xMin);", g).nodes(), (Nodes{0, 5, 10, 15, 16, 17, 18, 19}));
    const auto s = select<2>("faces (xMax xMax);", g);
    EXPECT_EQ(s.faces().size(), 1u);
    EXPECT_EQ(s.nodes(), (Nodes{4, 9, 14, 19}));
    EXPECT_EQ(s.describe(), "faces (xMax)");
}

TEST(NodeSelection, planeTakesTheLayerOnItAndEverythingBehind) {
    const auto g = grid2();
    // y = 2/3 is node row j = 2, at 2 * (1/3) with round-off; normal +y: rows 0..2 are on or behind.
    const auto s = select<2>("plane { point (0 0.6666666666666666); normal (0 2); }", g);
    EXPECT_EQ(s.size(), 15u);
    EXPECT_EQ(s.nodes().back(), 14);
    // Normal -y: rows 2 and 3.
    EXPECT_EQ(select<2>("plane { point (0 0.6666666666666666); normal (0 -1); }", g).nodes().front(), 10);
}

TEST(NodeSelection, shapeAllAndIntersections) {
    const auto g = grid2();
    // A box around x in [0.2, 0.55]: columns i = 1, 2.
    const auto box = select<2>("shape { type box; min (0.2 -1); max (0.55 2); }", g);
    EXPECT_EQ(box.size(), 8u);
    EXPECT_EQ(box.describe(), "shape box");
    EXPECT_EQ(select<2>("all yes;", g).size(), 20u);
    // The part of the bottom face inside the box.
    const auto part = select<2>("faces (yMin); shape { type box; min (0.2 -1); max (0.55 2); }", g);
    EXPECT_EQ(part.nodes(), (Nodes{1, 2}));
    EXPECT_EQ(part.describe(), "faces (yMin) and shape box");
}

TEST(NodeSelection, oneAndThreeDimensions) {
    const CartesianGrid<1> line(Vector<1>(0.0), Vector<1>(0.1), {10});
    EXPECT_EQ(select<1>("faces (xMax);", line).nodes(), (Nodes{10}));
    const CartesianGrid<3> cube(Vector<3>(0, 0, 0), Vector<3>(1, 1, 1), {2, 2, 2});
    const auto top = select<3>("faces (zMax);", cube);
    EXPECT_EQ(top.size(), 9u);
    EXPECT_EQ(top.nodes().front(), 18);  // k = 2: 9 k
    EXPECT_EQ(select<3>("faces (xMin yMin zMin);", cube).size(), 27u - 8u);
}

TEST(NodeSelection, errorsNameTheFaceAndTheValidOnes) {
    std::string e = errorOf("faces (zMin);");  // a 2D grid has no z faces
    EXPECT_NE(e.find("unknown face 'zMin'"), std::string::npos) << e;
    EXPECT_NE(e.find("Valid faces: xMin xMax yMin yMax"), std::string::npos) << e;
    EXPECT_NE(e.find("constant/mpmProperties:2"), std::string::npos) << e;
    e = errorOf("faces (xmin);");
    EXPECT_NE(e.find("did you mean 'xMin'"), std::string::npos) << e;
    e = errorOf("");
    EXPECT_NE(e.find("no grid nodes selected"), std::string::npos) << e;
    e = errorOf("all no;");
    EXPECT_NE(e.find("no grid nodes selected"), std::string::npos) << e;
    e = errorOf("all yes; faces (xMin);");
    EXPECT_NE(e.find("`all yes` selects every node"), std::string::npos) << e;
    e = errorOf("plane { point (0 0); normal (0 0); }");
    EXPECT_NE(e.find("non-zero"), std::string::npos) << e;
    e = errorOf("shape { type bx; min (0 0); max (1 1); }");
    EXPECT_NE(e.find("box"), std::string::npos) << e;  // the valid shape types are listed
}
