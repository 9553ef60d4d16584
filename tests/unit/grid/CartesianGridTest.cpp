// CartesianGrid: the node numbering and geometry of the header comment, both dictionary forms,
// and bad input as an InputError at the entry's file and line.
#include "grid/CartesianGrid.hpp"

#include "../SchemaTestTools.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

using namespace mfdyn;

namespace {

template <int Dim>
CartesianGrid<Dim> gridOf(const std::string& body) {
    const Dictionary dict = Dictionary::parse("grid {\n" + body + "\n}\n", "constant/mpmProperties");
    return CartesianGrid<Dim>::fromDictionary(dict.subDict("grid"));
}

template <int Dim>
std::string errorOf(const std::string& body) {
    return test::inputErrorOf([&] { gridOf<Dim>(body); }, body);
}

}  // namespace

TEST(CartesianGrid, explicitFormNumbersNodesXFastest) {
    auto g = gridOf<2>("origin (0 0); cellSize (0.05 0.05); cells (20 20);");
    EXPECT_EQ(g.nodeCount(), 441u);  // (20 + 1)^2
    EXPECT_EQ(g.cellCount(), 400u);
    EXPECT_EQ(g.nodesPerAxis()[0], 21);
    // Node (i, j) = i + 21 j (header comment).
    EXPECT_EQ(g.nodeIndex({3, 2}), 3 + 21 * 2);
    const auto ijk = g.nodeIjk(3 + 21 * 2);
    EXPECT_EQ(ijk[0], 3);
    EXPECT_EQ(ijk[1], 2);
    EXPECT_DOUBLE_EQ(g.nodePosition(3 + 21 * 2)[0], 0.15);
    EXPECT_DOUBLE_EQ(g.nodePosition(3 + 21 * 2)[1], 0.10);
    EXPECT_DOUBLE_EQ(g.upperCorner()[0], 1.0);
    EXPECT_EQ(g.describe(), "grid: 20 x 20 cells of 0.05 x 0.05 m from (0 0), 441 nodes");
    EXPECT_EQ(g.nodes().size(), 441u);  // node fields have one entry per node
    EXPECT_EQ(g.nodes().field<double>("mass").size(), 441u);
}

TEST(CartesianGrid, scalarCellSizeAndThreeDimensions) {
    const auto g = gridOf<3>("origin (-1 0 2); cellSize 0.5; cells (2 3 4);");
    EXPECT_EQ(g.nodeCount(), 3u * 4u * 5u);
    EXPECT_EQ(g.nodeIndex({1, 2, 3}), 1 + 3 * (2 + 4 * 3));
    for (std::int64_t n = 0; n < std::int64_t(g.nodeCount()); ++n) EXPECT_EQ(g.nodeIndex(g.nodeIjk(n)), n);
    EXPECT_DOUBLE_EQ(g.nodePosition(g.nodeIndex({2, 3, 4}))[2], 4.0);
    EXPECT_DOUBLE_EQ(g.smallestCellSize(), 0.5);
}

TEST(CartesianGrid, boxFormRoundsTheCellCountAndFitsTheSize) {
    // 1 / 0.3 = 3.33 cells: 3 cells of 1/3 along x; 0.5 / 0.3 = 1.67: 2 cells of 0.25 along y.
    const auto g = gridOf<2>("box { min (0 0); max (1 0.5); } cellSize 0.3;");
    EXPECT_EQ(g.cells()[0], 3);
    EXPECT_EQ(g.cells()[1], 2);
    EXPECT_DOUBLE_EQ(g.cellSize(0), 1.0 / 3.0);
    EXPECT_DOUBLE_EQ(g.cellSize(1), 0.25);
    EXPECT_DOUBLE_EQ(g.upperCorner()[0], 1.0);
    // A size larger than the box still gives one cell.
    EXPECT_EQ(gridOf<1>("box { min (0); max (1); } cellSize 5;").cells()[0], 1);
    // Or the counts, the size following.
    const auto h = gridOf<2>("box { min (0 0 0); max (2 1 0); } cells (4 5);");
    EXPECT_DOUBLE_EQ(h.cellSize(0), 0.5);
    EXPECT_DOUBLE_EQ(h.cellSize(1), 0.2);
}

TEST(CartesianGrid, cellOfClampsTheUpperFaceAndContainsHasATolerance) {
    const auto g = gridOf<2>("origin (0 0); cellSize 0.1; cells (10 5);");
    // The upper face belongs to the last cell (header comment): x = 1 is cell 9, not 10.
    EXPECT_EQ(g.cellOf(Vector<2>(1.0, 0.5))[0], 9);
    EXPECT_EQ(g.cellOf(Vector<2>(1.0, 0.5))[1], 4);
    EXPECT_EQ(g.cellOf(Vector<2>(0.25, 0.31))[0], 2);
    EXPECT_EQ(g.cellOf(Vector<2>(-7.0, 1e300))[0], 0);  // clamped, no overflow
    EXPECT_EQ(g.cellOf(Vector<2>(-7.0, 1e300))[1], 4);
    EXPECT_TRUE(g.contains(Vector<2>(1.0, 0.5)));
    EXPECT_TRUE(g.contains(Vector<2>(1.0 + 1e-14, 0.0)));  // within 1e-12 of a cell
    EXPECT_FALSE(g.contains(Vector<2>(1.0 + 1e-9, 0.0)));
    EXPECT_FALSE(g.contains(Vector<2>(std::nan(""), 0.0)));
    EXPECT_DOUBLE_EQ(g.cellCoordinates(Vector<2>(0.25, 0.31))[0], 2.5);
}

TEST(CartesianGrid, badSizesAndCountsAreErrorsAtTheirLine) {
    // Line 2: the entries follow "grid {" on line 1.
    std::string e = errorOf<2>("origin (0 0); cellSize (0.1 0); cells (10 10);");
    EXPECT_NE(e.find("constant/mpmProperties:2"), std::string::npos) << e;
    EXPECT_NE(e.find("cellSize"), std::string::npos) << e;
    EXPECT_NE(e.find("> 0"), std::string::npos) << e;
    e = errorOf<2>("origin (0 0); cellSize -0.1; cells (10 10);");
    EXPECT_NE(e.find("found -0.1"), std::string::npos) << e;
    e = errorOf<2>("origin (0 0);\ncellSize 0.1;\ncells (10 0);");
    EXPECT_NE(e.find("constant/mpmProperties:4"), std::string::npos) << e;
    EXPECT_NE(e.find("at least 1"), std::string::npos) << e;
    e = errorOf<2>("origin (0 0); cellSize 0.1; cells (10 2.5);");
    EXPECT_NE(e.find("whole numbers"), std::string::npos) << e;
}

TEST(CartesianGrid, wrongDimensionAndBadBoxesAreErrors) {
    std::string e = errorOf<2>("origin (0 0); cellSize 0.1; cells (10 10 10);");
    EXPECT_NE(e.find("expected 2 values"), std::string::npos) << e;
    EXPECT_NE(e.find("found 3"), std::string::npos) << e;
    e = errorOf<3>("origin (0 0 0); cellSize (0.1 0.1); cells (1 1 1);");
    EXPECT_NE(e.find("expected 3 values"), std::string::npos) << e;
    e = errorOf<2>("origin (0); cellSize 0.1; cells (1 1);");
    EXPECT_NE(e.find("origin"), std::string::npos) << e;
    e = errorOf<2>("box {\n min (0 0);\n max (1 0); }\ncellSize 0.1;");
    EXPECT_NE(e.find("constant/mpmProperties:4"), std::string::npos) << e;
    EXPECT_NE(e.find("max > min"), std::string::npos) << e;
    e = errorOf<2>("box { min (0 0); max (1 1); } cellSize 0.1; cells (3 3);");
    EXPECT_NE(e.find("not both"), std::string::npos) << e;
    e = errorOf<2>("origin (0 0); box { min (0 0); max (1 1); } cellSize 0.1;");
    EXPECT_NE(e.find("not both"), std::string::npos) << e;
    e = errorOf<2>("cellSize 0.1; cells (3 3);");
    EXPECT_NE(e.find("needs `origin"), std::string::npos) << e;
    e = errorOf<2>("origin (0 0); cells (3 3);");
    EXPECT_NE(e.find("cellSize"), std::string::npos) << e;
    // 10^4 cells per axis in 3D (a 1 m box with cellSize 1e-4): 1e12 nodes, 80 TB of mass,
    // momentum, velocity and force, beyond any machine's memory: refused at the entry, not an
    // allocation failure later.
    e = errorOf<3>("box { min (0 0 0); max (1 1 1); }\ncellSize 1e-4;");
    EXPECT_NE(e.find("constant/mpmProperties:3"), std::string::npos) << e;
    EXPECT_NE(e.find("1000300030001 nodes"), std::string::npos) << e;
    EXPECT_NE(e.find("GB of memory of this machine"), std::string::npos) << e;
    // 2^21 cells per axis in 3D is 2^63 nodes: refused, not an overflow.
    e = errorOf<3>("origin (0 0 0); cellSize 1; cells (2097152 2097152 2097152);");
    EXPECT_NE(e.find("2^40"), std::string::npos) << e;
}

TEST(CartesianGrid, constructorRefusesBadValues) {
    EXPECT_THROW(CartesianGrid<1>(Vector<1>(0.0), Vector<1>(0.0), {1}), Error);
    EXPECT_THROW(CartesianGrid<1>(Vector<1>(0.0), Vector<1>(1.0), {0}), Error);
    EXPECT_THROW(CartesianGrid<1>(Vector<1>(0.0), Vector<1>(std::nan("")), {1}), Error);
    EXPECT_NO_THROW(CartesianGrid<1>(Vector<1>(0.0), Vector<1>(1.0), {1}));
}
