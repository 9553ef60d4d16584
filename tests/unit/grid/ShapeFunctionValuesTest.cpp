// Known values of each shape function at hand-picked points (derivations beside each number), the
// edge fold, and the errors: a misspelt or missing type (listing the valid ones, at the entry's
// file and line), a grid too small for the type, a particle outside the grid, uGIMP's half-sizes.
#include "ShapeFunctionTestTools.hpp"

#include "core/Error.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace mfdyn {
namespace {

using test::makeShapeFunction;

template <int Dim>
CartesianGrid<Dim> unitGrid(double h, std::int64_t cells) {
    Vector<Dim> origin = Vector<Dim>::Zero(), size = Vector<Dim>::Constant(h);
    typename CartesianGrid<Dim>::Ijk n;
    n.fill(cells);
    return CartesianGrid<Dim>(origin, size, n);
}

// One particle in 1D: its (node, N, dN/dx) entries.
struct Expected1D {
    std::int64_t node;
    double weight, gradient;
};

void expect1D(const std::string& type, double h, std::int64_t cells, double x, double halfSize,
              const std::vector<Expected1D>& expected) {
    SCOPED_TRACE(type + " at x = " + std::to_string(x));
    const auto sf = makeShapeFunction<1>(type);
    const CartesianGrid<1> grid = unitGrid<1>(h, cells);
    const std::vector<Vector<1>> xs{Vector<1>(x)}, sizes{Vector<1>(halfSize)};
    ParticleNodeList<1> list;
    sf->evaluate(grid, xs, sizes, list);
    ASSERT_EQ(list.count[0], expected.size());
    for (std::size_t e = 0; e < expected.size(); ++e) {
        EXPECT_EQ(list.node[e], expected[e].node) << "entry " << e;
        // the hand values are exact decimals; the code's rounding is a few eps
        EXPECT_NEAR(list.weight[e], expected[e].weight, 1e-15) << "entry " << e;
        EXPECT_NEAR(list.gradient[e][0], expected[e].gradient, 1e-14) << "entry " << e;
    }
}

TEST(ShapeFunctionValues, linear2D) {
    // h = (0.5, 0.25), 4 x 4 cells, x = (0.7, 0.3): xi = 1.4, eta = 1.2, so nodes i = 1, 2 and
    // j = 1, 2 with N_x = (0.6, 0.4), N_y = (0.8, 0.2), dN_x/dx = (-1, 1)/0.5 = (-2, 2),
    // dN_y/dy = (-1, 1)/0.25 = (-4, 4). Node index i + 5 j: 6, 7, 11, 12.
    //   (1,1): N = 0.6*0.8 = 0.48, grad = (-2*0.8, 0.6*-4) = (-1.6, -2.4)
    //   (2,1): N = 0.4*0.8 = 0.32, grad = ( 2*0.8, 0.4*-4) = ( 1.6, -1.6)
    //   (1,2): N = 0.6*0.2 = 0.12, grad = (-2*0.2, 0.6* 4) = (-0.4,  2.4)
    //   (2,2): N = 0.4*0.2 = 0.08, grad = ( 2*0.2, 0.4* 4) = ( 0.4,  1.6)
    const auto sf = makeShapeFunction<2>("linear");
    const CartesianGrid<2> grid(Vector<2>(0, 0), Vector<2>(0.5, 0.25), {4, 4});
    const std::vector<Vector<2>> x{Vector<2>(0.7, 0.3)};
    ParticleNodeList<2> list;
    sf->evaluate(grid, x, {}, list);
    ASSERT_EQ(list.count[0], 4u);
    const std::int64_t nodes[] = {6, 7, 11, 12};
    const double weights[] = {0.48, 0.32, 0.12, 0.08};
    const double gx[] = {-1.6, 1.6, -0.4, 0.4}, gy[] = {-2.4, -1.6, 2.4, 1.6};
    for (int e = 0; e < 4; ++e) {
        EXPECT_EQ(list.node[e], nodes[e]);
        EXPECT_NEAR(list.weight[e], weights[e], 1e-15);
        EXPECT_NEAR(list.gradient[e][0], gx[e], 1e-14);
        EXPECT_NEAR(list.gradient[e][1], gy[e], 1e-14);
    }
}

TEST(ShapeFunctionValues, linear3DNumbering) {
    // 2 x 3 x 4 cells of 1 m, x = (0.5, 1.25, 2.75): i in {0, 1}, j in {1, 2}, k in {2, 3}; node
    // i + 3 (j + 4 k), x fastest: 27, 28, 30, 31, 39, 40, 42, 43. First entry (0,1,2):
    // N = 0.5 * 0.75 * 0.25 = 0.09375, grad = (-1 * 0.75 * 0.25, 0.5 * -1 * 0.25, 0.5 * 0.75 * -1).
    const auto sf = makeShapeFunction<3>("linear");
    const CartesianGrid<3> grid(Vector<3>::Zero(), Vector<3>::Ones(), {2, 3, 4});
    const std::vector<Vector<3>> x{Vector<3>(0.5, 1.25, 2.75)};
    ParticleNodeList<3> list;
    sf->evaluate(grid, x, {}, list);
    const std::int64_t nodes[] = {27, 28, 30, 31, 39, 40, 42, 43};
    for (int e = 0; e < 8; ++e) EXPECT_EQ(list.node[e], nodes[e]);
    EXPECT_NEAR(list.weight[0], 0.09375, 1e-16);
    EXPECT_NEAR(list.gradient[0][0], -0.1875, 1e-16);
    EXPECT_NEAR(list.gradient[0][1], -0.125, 1e-16);
    EXPECT_NEAR(list.gradient[0][2], -0.375, 1e-16);
}

TEST(ShapeFunctionValues, linearOnANodeTakesTheRightDerivative) {
    // x = 2 exactly (h = 1): cell 2, N = (1, 0) at nodes 2, 3 with slopes (-1, 1): the zero-weight
    // entry carries a slope, which sum grad N = 0 needs (ShapeFunction.hpp). At the upper edge
    // x = 4 the last cell is taken: nodes 3, 4, N = (0, 1), slopes (-1, 1).
    expect1D("linear", 1.0, 4, 2.0, 0.0, {{2, 1.0, -1.0}, {3, 0.0, 1.0}});
    expect1D("linear", 1.0, 4, 4.0, 0.0, {{3, 0.0, -1.0}, {4, 1.0, 1.0}});
}

TEST(ShapeFunctionValues, uGIMP) {
    // h = 1, lp = 0.25, x = 2.1: nearest node 2, window 1, 2, 3 with r = 1.1, 0.1, -0.9.
    //   node 1: 1 - lp < |r| < 1 + lp, q = 1.25 - 1.1 = 0.15: N = q^2/(4 lp) = 0.0225,
    //           dN/dr = -q/(2 lp) = -0.3
    //   node 2: |r| < lp: N = 1 - (0.01 + 0.0625)/(2 lp) = 0.855, dN/dr = -r/lp = -0.4
    //   node 3: q = 1.25 - 0.9 = 0.35: N = 0.1225, dN/dr = +q/(2 lp) = 0.7
    // (sum 1, slopes sum 0, sum N x_I = 0.0225 + 1.71 + 0.3675 = 2.1)
    expect1D("uGIMP", 1.0, 4, 2.1, 0.25, {{1, 0.0225, -0.3}, {2, 0.855, -0.4}, {3, 0.1225, 0.7}});
    // Same in a grid of h = 0.5 (x = 1.05, l_p = 0.125 m): N unchanged, slopes doubled.
    expect1D("uGIMP", 0.5, 4, 1.05, 0.125, {{1, 0.0225, -0.6}, {2, 0.855, -0.8}, {3, 0.1225, 1.4}});
    // Folded at the edge, x = 0.1: the window -1, 0, 1 has the numbers above (r = 1.1, 0.1,
    // -0.9); node -1's 0.0225 goes twice to node 0 and minus once to node 1:
    // N = (0.855 + 0.045, 0.1225 - 0.0225, 0) = (0.9, 0.1, 0), slopes (-0.4 - 0.6, 0.7 + 0.3, 0):
    // the linear hat, as the fold's derivation says.
    expect1D("uGIMP", 1.0, 4, 0.1, 0.25, {{0, 0.9, -1.0}, {1, 0.1, 1.0}, {2, 0.0, 0.0}});
}

TEST(ShapeFunctionValues, quadraticBSpline) {
    // h = 0.5, x = 1.3: xi = 2.6, nearest node 3, t = -0.4: nodes 2, 3, 4 with
    // N = (0.9^2/2, 0.75 - 0.16, 0.1^2/2) = (0.405, 0.59, 0.005), dN/dxi = (t - 1/2, -2t, t + 1/2)
    // = (-0.9, 0.8, 0.1), per metre x 2: (-1.8, 1.6, 0.2). (sum N x_I = 0.405 + 0.885 + 0.01 = 1.3)
    expect1D("quadraticBSpline", 0.5, 6, 1.3, 0.0, {{2, 0.405, -1.8}, {3, 0.59, 1.6}, {4, 0.005, 0.2}});
    // Folded at the edge, xi = 0.2 (x = 0.1): N = (1 - xi, xi, 0) = (0.8, 0.2, 0), slopes (-2, 2, 0).
    expect1D("quadraticBSpline", 0.5, 6, 0.1, 0.0, {{0, 0.8, -2.0}, {1, 0.2, 2.0}, {2, 0.0, 0.0}});
    // At the upper edge xi = 6: window 5, 6, 7 with N = (1/8, 3/4, 1/8), dN/dxi = (-1/2, 0, 1/2);
    // node 7's share goes twice to node 6 and minus once to node 5: N = (0, 0, 1) on nodes 4, 5, 6
    // (the edge node interpolates), dN/dxi = (0, -1, 1), per metre x 2.
    expect1D("quadraticBSpline", 0.5, 6, 3.0, 0.0, {{4, 0.0, 0.0}, {5, 0.0, -2.0}, {6, 1.0, 2.0}});
}

TEST(ShapeFunctionValues, cubicBSpline) {
    // h = 1, x = 2.25: cell 2, t = 0.25, u = 0.75: nodes 1..4 with
    //   N = (u^3/6, (3t^3 - 6t^2 + 4)/6, (-3t^3 + 3t^2 + 3t + 1)/6, t^3/6)
    //     = (0.421875/6, 3.671875/6, 1.890625/6, 0.015625/6)
    //   dN = (-u^2/2, (3t^2 - 4t)/2, (-3t^2 + 2t + 1)/2, t^2/2) = (-0.28125, -0.40625, 0.65625, 0.03125)
    expect1D("cubicBSpline", 1.0, 6, 2.25, 0.0,
             {{1, 0.421875 / 6, -0.28125},
              {2, 3.671875 / 6, -0.40625},
              {3, 1.890625 / 6, 0.65625},
              {4, 0.015625 / 6, 0.03125}});
    // Folded at the edge, t = 0.5: node 0: 1 - t + t^3/6 = 0.5 + 0.125/6, slope -1 + t^2/2 = -0.875;
    // node 1: t - t^3/3 = 0.5 - 0.125/3, slope 1 - t^2 = 0.75; node 2: t^3/6, slope t^2/2 = 0.125.
    expect1D(
        "cubicBSpline", 1.0, 6, 0.5, 0.0,
        {{0, 0.5 + 0.125 / 6, -0.875}, {1, 0.5 - 0.125 / 3, 0.75}, {2, 0.125 / 6, 0.125}, {3, 0.0, 0.0}});
}

// The node list of a shape function: what M's transfers rely on.
TEST(ShapeFunctionValues, sizesAndStride) {
    const auto q = makeShapeFunction<3>("quadraticBSpline");
    EXPECT_EQ(q->nodesPerAxis(), 3);
    EXPECT_DOUBLE_EQ(q->supportHalfWidth(), 1.5);
    const auto c = makeShapeFunction<2>("cubicBSpline");
    EXPECT_EQ(c->nodesPerAxis(), 4);
    EXPECT_DOUBLE_EQ(c->supportHalfWidth(), 2.0);
    EXPECT_TRUE(makeShapeFunction<2>("uGIMP")->needsParticleSize());
    EXPECT_FALSE(makeShapeFunction<2>("linear")->needsParticleSize());
    ParticleNodeList<3> list;
    const CartesianGrid<3> grid = unitGrid<3>(1.0, 4);
    const std::vector<Vector<3>> x(5, Vector<3>::Constant(1.7));
    q->evaluate(grid, x, {}, list);
    EXPECT_EQ(list.stride, 27u);
    EXPECT_EQ(list.node.size(), 5u * 27u);
}

// ---- selection and errors ------------------------------------------------------------------

std::string errorOf(const std::function<void()>& f) {
    try {
        f();
    } catch (const Error& e) {
        return e.what();
    }
    return "(no error)";
}

TEST(ShapeFunctionSelection, wordAndDictionaryForms) {
    const Dictionary word =
        Dictionary::parse("grid { cells (2 2); }\nshapeFunction cubicBSpline;\n", "mpmProperties");
    EXPECT_EQ(ShapeFunction<2>::New(word)->type(), "cubicBSpline");
    EXPECT_EQ(ShapeFunction<2>::New(word)->nodesPerAxis(), 4);
    const Dictionary sub = Dictionary::parse("shapeFunction { type uGIMP; }\n", "mpmProperties");
    EXPECT_EQ(ShapeFunction<3>::New(sub)->type(), "uGIMP");
    EXPECT_EQ(ShapeFunction<1>::New(sub.subDict("shapeFunction"))->type(), "uGIMP");
}

TEST(ShapeFunctionSelection, misspeltTypeListsTheValidOnesAtItsLine) {
    const Dictionary sub =
        Dictionary::parse("\nshapeFunction\n{\n    type cubicBSplin;\n}\n", "mpmProperties");
    const std::string m = errorOf([&] { ShapeFunction<2>::New(sub); });
    EXPECT_NE(m.find("mpmProperties:4"), std::string::npos) << m;
    EXPECT_NE(m.find("'cubicBSplin'"), std::string::npos) << m;
    EXPECT_NE(m.find("did you mean 'cubicBSpline'"), std::string::npos) << m;
    for (const char* t : {"linear", "uGIMP", "quadraticBSpline"})
        EXPECT_NE(m.find(t), std::string::npos) << m;

    const Dictionary word = Dictionary::parse("a 1;\n\nshapeFunction quadraticBspline;\n", "mpmProperties");
    const std::string w = errorOf([&] { ShapeFunction<3>::New(word); });
    EXPECT_NE(w.find("mpmProperties:3"), std::string::npos) << w;
    EXPECT_NE(w.find("did you mean 'quadraticBSpline'"), std::string::npos) << w;
    EXPECT_NE(w.find("cubicBSpline"), std::string::npos) << w;
}

TEST(ShapeFunctionSelection, missingTypeListsTheValidOnes) {
    const Dictionary none = Dictionary::parse("grid { }\n", "mpmProperties");
    const std::string m = errorOf([&] { ShapeFunction<2>::New(none); });
    EXPECT_NE(m.find("missing keyword 'shapeFunction'"), std::string::npos) << m;
    for (const char* t : {"linear", "uGIMP", "quadraticBSpline", "cubicBSpline"})
        EXPECT_NE(m.find(t), std::string::npos) << m;
}

TEST(ShapeFunctionErrors, gridTooSmallForTheType) {
    // cubic needs 3 cells per axis (4 nodes, folded at both edges); 5 x 2 cells have 2 along y.
    const auto c = makeShapeFunction<2>("cubicBSpline");
    const CartesianGrid<2> grid(Vector<2>::Zero(), Vector<2>::Ones(), {5, 2});
    const std::string problem = c->gridProblem(grid);
    EXPECT_NE(problem.find("cubicBSpline needs at least 3 cells along each axis"), std::string::npos)
        << problem;
    EXPECT_NE(problem.find("the grid has 2 along y"), std::string::npos) << problem;
    ParticleNodeList<2> list;
    const std::vector<Vector<2>> x{Vector<2>(1.0, 1.0)};
    EXPECT_EQ(errorOf([&] { c->evaluate(grid, x, {}, list); }), problem);
    // the linear hat works on one cell
    EXPECT_TRUE(makeShapeFunction<2>("linear")
                    ->gridProblem(CartesianGrid<2>(Vector<2>::Zero(), Vector<2>::Ones(), {1, 1}))
                    .empty());
}

TEST(ShapeFunctionErrors, particleOutsideTheGridIsNamedNotWrittenOutOfBounds) {
    const CartesianGrid<2> grid = unitGrid<2>(0.5, 4);    // [0, 2]^2
    std::vector<Vector<2>> x(6000, Vector<2>(1.0, 1.0));  // above the parallel threshold
    x[4500] = Vector<2>(2.5, 1.0);
    x[5000] = Vector<2>(1.0, std::numeric_limits<double>::quiet_NaN());
    x[4200] = Vector<2>(1.0, -0.01);
    for (const std::string& type : ShapeFunction<2>::Selector::names()) {
        const auto sf = makeShapeFunction<2>(type);
        std::vector<Vector<2>> sizes(x.size(), Vector<2>::Constant(0.1));
        ParticleNodeList<2> list;
        const std::string m = errorOf([&] { sf->evaluate(grid, x, sizes, list); });
        // the lowest bad index, whatever the thread count
        EXPECT_NE(m.find("particle 4200 at (1 -0.01) is outside the grid (0 0) to (2 2)"), std::string::npos)
            << type << ": " << m;
        EXPECT_EQ(list.count[4200], 0u) << type;
        // a point on the edge within 1e-12 of a cell is evaluated at the edge
        std::vector<Vector<2>> edge{Vector<2>(-1e-14, 2.0 + 1e-14)};
        std::vector<Vector<2>> edgeSizes(1, Vector<2>::Constant(0.1));
        EXPECT_NO_THROW(sf->evaluate(grid, edge, edgeSizes, list)) << type;
    }
}

TEST(ShapeFunctionErrors, uGIMPHalfSizes) {
    const auto g = makeShapeFunction<2>("uGIMP");
    const CartesianGrid<2> grid = unitGrid<2>(0.5, 4);
    const std::vector<Vector<2>> x{Vector<2>(1.0, 1.0), Vector<2>(0.3, 0.4)};
    ParticleNodeList<2> list;
    const std::string missing = errorOf([&] { g->evaluate(grid, x, {}, list); });
    EXPECT_NE(missing.find("uGIMP needs every particle's half-size: got 0 for 2 particles"),
              std::string::npos)
        << missing;
    // half-size 0.3 m in cells of 0.5 m: more than half a cell (a particle larger than a cell)
    const std::vector<Vector<2>> large{Vector<2>(0.2, 0.2), Vector<2>(0.3, 0.2)};
    const std::string m = errorOf([&] { g->evaluate(grid, x, large, list); });
    EXPECT_NE(m.find("particle 1 has half-size (0.3 0.2) m"), std::string::npos) << m;
    EXPECT_NE(m.find("at most half a cell (0.25 0.25) m"), std::string::npos) << m;
    const std::vector<Vector<2>> zero{Vector<2>(0.2, 0.2), Vector<2>(0.0, 0.2)};
    EXPECT_NE(errorOf([&] { g->evaluate(grid, x, zero, list); }).find("particle 1 has half-size (0 0.2)"),
              std::string::npos);
    // exactly half a cell is the largest allowed (one particle per cell)
    const std::vector<Vector<2>> half{Vector<2>(0.25, 0.25), Vector<2>(0.25, 0.25)};
    EXPECT_NO_THROW(g->evaluate(grid, x, half, list));
}

}  // namespace
}  // namespace mfdyn
