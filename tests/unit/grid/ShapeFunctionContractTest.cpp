// The family contract of `shapeFunction` (issue 17 item 2; doc/methods/mpm.md section 5, test
// U1), over every registered type (the registry is iterated, so a new type is covered without
// touching this file) in 1, 2 and 3D, at random points inside the grid with a third of the
// coordinates in the edge cells and a third exactly on nodes, cell faces or half-cells:
//   - the list: count = stride = nodesPerAxis^Dim, nodes increasing and inside the grid;
//   - partition of unity sum N = 1, sum grad N = 0, N >= 0;
//   - linear completeness sum N x_I = x and sum grad N (x) x_I = I;
//   - grad N against a 4th-order finite difference of evaluate()'s own N (tolerance from the
//     rounding of the difference, see fdTolerance);
//   - the 1D derivative against the complex step of the 1D function (1e-12 per cell, the issue's
//     figure, met with orders of magnitude to spare), and evaluate() equal to the tensor product of
//     those 1D functions, so the 1e-12 check covers what evaluate() returns.
#include "ShapeFunctionTestTools.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <cstdio>
#include <map>
#include <random>
#include <set>

namespace mfdyn {
namespace {

using test::entriesOf;
using test::makeShapeFunction;
using test::testGrid;

// Cell coordinates of the sample points along one axis of n cells: uniform, in the edge cells,
// exactly on a node (the edges 0 and n included), exactly on a half-cell.
double sampleCoordinate(std::mt19937_64& rng, std::int64_t n) {
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    std::uniform_int_distribution<std::int64_t> node(0, n), cell(0, n - 1);
    switch (std::uniform_int_distribution<int>(0, 5)(rng)) {
        case 0:
        case 1:
            return unit(rng) * double(n);
        case 2:
            return unit(rng);
        case 3:
            return double(n) - unit(rng);
        case 4:
            return double(node(rng));
        default:
            return double(cell(rng)) + 0.5;
    }
}

// uGIMP's half-sizes in cells: a quarter (2 particles per cell per axis), the largest allowed
// (1 per cell), and one with no simple relation to the knots.
constexpr double halfSizesInCells[] = {0.25, 0.5, 0.17};

template <int Dim>
struct Samples {
    std::vector<Vector<Dim>> x, halfSize;
};

template <int Dim>
Samples<Dim> samples(const CartesianGrid<Dim>& grid, std::size_t n, unsigned seed) {
    std::mt19937_64 rng(seed);
    Samples<Dim> s;
    for (std::size_t p = 0; p < n; ++p) {
        Vector<Dim> x, l;
        for (int d = 0; d < Dim; ++d) {
            x[d] = grid.origin()[d] + sampleCoordinate(rng, grid.cells()[d]) * grid.cellSize(d);
            l[d] = halfSizesInCells[(p + d) % 3] * grid.cellSize(d);
        }
        // a node exactly: x = origin + i h can round off the node; the edges stay inside
        for (int d = 0; d < Dim; ++d) x[d] = std::clamp(x[d], grid.origin()[d], grid.upperCorner()[d]);
        s.x.push_back(x);
        s.halfSize.push_back(l);
    }
    return s;
}

// The rounding of a 4th-order difference with step d of values of size <= 1: the stencil's
// coefficient sum (18/12 central, 128/12 one-sided) times eps over d, and the steps x + k d are
// themselves rounded to eps |x|, a relative error eps |x| / d of the derivative (|x| <= 2 m here,
// d = 1e-4 h >= 7e-6 m: 6e-11). Truncation is zero: every type is a polynomial of degree <= 3 on
// each piece and the formulas are exact to degree 4, as long as the stencil stays in one piece.
// 1e-9 per cell covers both with a margin and still fails any wrong slope (an error of order 1).
constexpr double fdTolerance = 1e-9;

template <int Dim>
void checkContract(const std::string& type) {
    SCOPED_TRACE(type + " in " + std::to_string(Dim) + "D");
    const CartesianGrid<Dim> grid = testGrid<Dim>();
    const auto sf = makeShapeFunction<Dim>(type);
    ASSERT_EQ(sf->type(), type);
    ASSERT_TRUE(sf->gridProblem(grid).empty()) << sf->gridProblem(grid);
    const int width = sf->nodesPerAxis();
    std::size_t stride = 1;
    for (int d = 0; d < Dim; ++d) stride *= std::size_t(width);

    const std::size_t n = 400;
    const Samples<Dim> s = samples(grid, n, 17 + Dim);
    const std::span<const Vector<Dim>> sizes =
        sf->needsParticleSize() ? std::span<const Vector<Dim>>(s.halfSize) : std::span<const Vector<Dim>>();
    ParticleNodeList<Dim> list;
    sf->evaluate(grid, s.x, sizes, list);
    ASSERT_EQ(list.particles(), n);
    ASSERT_EQ(list.stride, stride);

    // The shifted evaluations of the finite differences: x + k d e_a, k = -4..4, one list each.
    constexpr int reach = 4;
    std::vector<std::array<ParticleNodeList<Dim>, 2 * reach + 1>> shifted(Dim);
    std::vector<std::array<std::vector<bool>, 2 * reach + 1>> inside(Dim);
    for (int a = 0; a < Dim; ++a) {
        const double step = 1e-4 * grid.cellSize(a);
        for (int k = -reach; k <= reach; ++k) {
            std::vector<Vector<Dim>> y = s.x;
            std::vector<bool>& in = inside[a][k + reach];
            in.assign(n, true);
            for (std::size_t p = 0; p < n; ++p) {
                y[p][a] += k * step;
                if (y[p][a] < grid.origin()[a] || y[p][a] > grid.upperCorner()[a]) {
                    in[p] = false;
                    y[p] = s.x[p];  // evaluated, never used
                }
            }
            sf->evaluate(grid, y, sizes, shifted[a][k + reach]);
        }
    }

    double worstDifference = 0.0, worstComplexStep = 0.0;  // printed: the figures behind the tolerances
    for (std::size_t p = 0; p < n; ++p) {
        SCOPED_TRACE("particle " + std::to_string(p));
        ASSERT_EQ(list.count[p], stride);
        const auto entries = entriesOf(list, p);
        ASSERT_EQ(entries.size(), stride) << "a node listed twice";
        std::int64_t previous = -1;
        double sum = 0.0;
        Vector<Dim> gradientSum = Vector<Dim>::Zero(), moment = Vector<Dim>::Zero();
        Tensor<Dim> gradientMoment = Tensor<Dim>::Zero();
        for (std::size_t e = p * stride; e < (p + 1) * stride; ++e) {
            const std::int64_t node = list.node[e];
            ASSERT_GT(node, previous) << "nodes not in increasing order";
            ASSERT_LT(node, std::int64_t(grid.nodeCount()));
            previous = node;
            EXPECT_GE(list.weight[e], -1e-15) << "negative weight at node " << node;
            const Vector<Dim> xI = grid.nodePosition(node);
            sum += list.weight[e];
            gradientSum += list.gradient[e];
            moment += list.weight[e] * xI;
            gradientMoment += list.gradient[e] * xI.transpose();
        }
        // Sums of at most 64 terms of size <= 1 (N), 1/h (grad N), 2 m (N x_I), 2 m/h: rounding
        // of a few eps each.
        EXPECT_NEAR(sum, 1.0, 1e-14);
        for (int a = 0; a < Dim; ++a) {
            EXPECT_NEAR(gradientSum[a] * grid.cellSize(a), 0.0, 1e-13) << "axis " << a;
            EXPECT_NEAR(moment[a], s.x[p][a], 1e-13) << "axis " << a;
            for (int b = 0; b < Dim; ++b)
                EXPECT_NEAR(gradientMoment(a, b), a == b ? 1.0 : 0.0, 1e-12) << "axes " << a << b;
        }

        // grad N against 4th-order differences: central where the stencil fits, else one-sided;
        // a stencil across a knot of a C0 or C1 piece misses, so the best fitting one is taken.
        for (int a = 0; a < Dim; ++a) {
            const double step = 1e-4 * grid.cellSize(a);
            std::array<std::map<std::int64_t, test::Entry<Dim>>, 2 * reach + 1> around;
            for (int k = -reach; k <= reach; ++k) around[k + reach] = entriesOf(shifted[a][k + reach], p);
            auto value = [&](int k, std::int64_t node) {
                const auto& m = around[k + reach];
                const auto it = m.find(node);
                return it == m.end() ? 0.0 : it->second.weight;
            };
            auto fits = [&](int lo, int hi) {
                for (int k = lo; k <= hi; ++k)
                    if (!inside[a][k + reach][p]) return false;
                return true;
            };
            struct Stencil {
                int lo, hi;
                std::array<double, 5> c;
            };
            const Stencil stencils[] = {
                {-2, 2, {1.0 / 12, -8.0 / 12, 0.0, 8.0 / 12, -1.0 / 12}},
                {0, 4, {-25.0 / 12, 48.0 / 12, -36.0 / 12, 16.0 / 12, -3.0 / 12}},
                {-4, 0, {3.0 / 12, -16.0 / 12, 36.0 / 12, -48.0 / 12, 25.0 / 12}},
            };
            std::set<std::int64_t> nodes;
            for (const auto& m : around)
                for (const auto& [node, entry] : m) nodes.insert(node);
            double best = INFINITY;
            for (const Stencil& st : stencils) {
                if (!fits(st.lo, st.hi)) continue;
                double worst = 0.0;
                for (std::int64_t node : nodes) {
                    double fd = 0.0;
                    for (int k = st.lo; k <= st.hi; ++k) fd += st.c[k - st.lo] * value(k, node);
                    fd /= step;
                    const auto it = entries.find(node);
                    const double analytic = it == entries.end() ? 0.0 : it->second.gradient[a];
                    worst = std::max(worst, std::abs(fd - analytic) * grid.cellSize(a));
                }
                best = std::min(best, worst);
            }
            EXPECT_LE(best, fdTolerance) << "axis " << a << ": grad N differs from every finite difference";
            worstDifference = std::max(worstDifference, best);
        }

        // The complex step per axis, and evaluate() equal to the tensor product of the axes.
        std::vector<std::vector<double>> w(Dim), dw(Dim);
        std::vector<std::int64_t> first(Dim);
        for (int a = 0; a < Dim; ++a) {
            // as evaluate() computes it, clamped into [0, n] (a point on the upper face may come out
            // a rounding above n)
            const double xi = std::clamp((s.x[p][a] - grid.origin()[a]) * (1.0 / grid.cellSize(a)), 0.0,
                                         double(grid.cells()[a]));
            const double lp = sf->needsParticleSize() ? s.halfSize[p][a] / grid.cellSize(a) : 0.0;
            constexpr double e = 1e-30;
            std::vector<std::complex<double>> N(width), dN(width), Nc(width), dNc(width);
            first[a] = sf->axisWeights(xi, lp, grid.cells()[a], N, dN);
            ASSERT_EQ(sf->axisWeights(std::complex<double>(xi, e), lp, grid.cells()[a], Nc, dNc), first[a]);
            for (int k = 0; k < width; ++k) {
                // Im N(xi + i e)/e is exact to rounding: no difference of nearby values is taken.
                EXPECT_NEAR(Nc[k].imag() / e, dN[k].real(), 1e-12) << "axis " << a << " node " << k;
                worstComplexStep = std::max(worstComplexStep, std::abs(Nc[k].imag() / e - dN[k].real()));
                w[a].push_back(N[k].real());
                dw[a].push_back(dN[k].real() / grid.cellSize(a));
            }
        }
        std::size_t e = p * stride;
        std::array<int, 3> k{};
        for (std::size_t entry = 0; entry < stride; ++entry, ++e) {
            std::size_t rest = entry;
            for (int a = 0; a < Dim; ++a) {
                k[a] = int(rest % width);
                rest /= width;
            }
            typename CartesianGrid<Dim>::Ijk ijk;
            double weight = 1.0;
            Vector<Dim> gradient = Vector<Dim>::Ones();
            for (int a = 0; a < Dim; ++a) {
                ijk[a] = first[a] + k[a];
                weight *= w[a][k[a]];
                for (int b = 0; b < Dim; ++b) gradient[b] *= (a == b ? dw[a][k[a]] : w[a][k[a]]);
            }
            EXPECT_EQ(list.node[e], grid.nodeIndex(ijk));
            EXPECT_NEAR(list.weight[e], weight, 1e-15);
            for (int b = 0; b < Dim; ++b)
                EXPECT_NEAR(list.gradient[e][b] * grid.cellSize(b), gradient[b] * grid.cellSize(b), 1e-14);
        }
    }
    std::printf("%-16s %dD: largest |grad N - finite difference| h = %.1e, |dN/dxi - complex step| = %.1e\n",
                type.c_str(), Dim, worstDifference, worstComplexStep);
}

template <int Dim>
void checkEveryType() {
    const std::vector<std::string> names = ShapeFunction<Dim>::Selector::names();
    // The four must be among them (a registration lost by the linker would show here).
    for (const char* expected : {"linear", "uGIMP", "quadraticBSpline", "cubicBSpline"})
        EXPECT_NE(std::find(names.begin(), names.end(), expected), names.end()) << expected;
    for (const std::string& type : names) checkContract<Dim>(type);
}

TEST(ShapeFunctionContract, everyTypeIn1D) {
    checkEveryType<1>();
}
TEST(ShapeFunctionContract, everyTypeIn2D) {
    checkEveryType<2>();
}
TEST(ShapeFunctionContract, everyTypeIn3D) {
    checkEveryType<3>();
}

// On the smallest grid a type accepts (minimumCells() per axis) every window spans the whole
// grid and the folds at both edges meet: the partition of unity, completeness and N >= 0 still hold.
template <int Dim>
void checkSmallestGrid(const std::string& type) {
    SCOPED_TRACE(type + " in " + std::to_string(Dim) + "D on its smallest grid");
    const auto sf = makeShapeFunction<Dim>(type);
    typename CartesianGrid<Dim>::Ijk cells;
    cells.fill(sf->minimumCells());
    Vector<Dim> h;
    for (int d = 0; d < Dim; ++d) h[d] = 0.1 + 0.03 * d;
    const CartesianGrid<Dim> grid(Vector<Dim>::Constant(0.5), h, cells);
    ASSERT_TRUE(sf->gridProblem(grid).empty());
    cells.fill(sf->minimumCells() - 1);
    if (sf->minimumCells() > 1)
        EXPECT_FALSE(sf->gridProblem(CartesianGrid<Dim>(Vector<Dim>::Zero(), h, cells)).empty());
    const Samples<Dim> s = samples(grid, 200, 29);
    ParticleNodeList<Dim> list;
    sf->evaluate(grid, s.x, s.halfSize, list);
    for (std::size_t p = 0; p < s.x.size(); ++p) {
        double sum = 0.0;
        Vector<Dim> moment = Vector<Dim>::Zero(), gradientSum = Vector<Dim>::Zero();
        for (std::size_t e = p * list.stride; e < (p + 1) * list.stride; ++e) {
            ASSERT_GE(list.node[e], 0);
            ASSERT_LT(list.node[e], std::int64_t(grid.nodeCount()));
            EXPECT_GE(list.weight[e], -1e-15);
            sum += list.weight[e];
            moment += list.weight[e] * grid.nodePosition(list.node[e]);
            gradientSum += list.gradient[e];
        }
        EXPECT_NEAR(sum, 1.0, 1e-14) << "particle " << p;
        for (int a = 0; a < Dim; ++a) {
            EXPECT_NEAR(moment[a], s.x[p][a], 1e-13) << "particle " << p;
            EXPECT_NEAR(gradientSum[a] * h[a], 0.0, 1e-13) << "particle " << p;
        }
    }
}

TEST(ShapeFunctionContract, smallestGridOfEveryType) {
    for (const std::string& type : ShapeFunction<1>::Selector::names()) checkSmallestGrid<1>(type);
    for (const std::string& type : ShapeFunction<2>::Selector::names()) checkSmallestGrid<2>(type);
    for (const std::string& type : ShapeFunction<3>::Selector::names()) checkSmallestGrid<3>(type);
}

// What the contract is for: U2 of doc/methods/mpm.md section 5 in miniature. A mass and momentum
// spread with N and gathered back sum to the particle's, and sum grad N = 0 makes the internal
// forces f_I = -sum_p V_p sigma_p grad N_Ip sum to zero for any stresses.
template <int Dim>
void checkTransferSums(const std::string& type) {
    SCOPED_TRACE(type);
    const CartesianGrid<Dim> grid = testGrid<Dim>();
    const auto sf = makeShapeFunction<Dim>(type);
    const Samples<Dim> s = samples(grid, 300, 5);
    ParticleNodeList<Dim> list;
    sf->evaluate(grid, s.x, s.halfSize, list);
    std::vector<double> nodeMass(grid.nodeCount(), 0.0);
    std::vector<Vector<Dim>> force(grid.nodeCount(), Vector<Dim>::Zero());
    double mass = 0.0;
    std::mt19937_64 rng(3);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    for (std::size_t p = 0; p < s.x.size(); ++p) {
        const double m = 1.0 + u(rng);
        Tensor<Dim> sigma;
        for (int a = 0; a < Dim; ++a)
            for (int b = 0; b < Dim; ++b) sigma(a, b) = 1e6 * u(rng);
        mass += m;
        for (std::size_t e = p * list.stride; e < (p + 1) * list.stride; ++e) {
            nodeMass[list.node[e]] += list.weight[e] * m;
            force[list.node[e]] -= 1e-3 * sigma * list.gradient[e];
        }
    }
    double gridMass = 0.0;
    Vector<Dim> totalForce = Vector<Dim>::Zero();
    for (std::size_t i = 0; i < grid.nodeCount(); ++i) {
        gridMass += nodeMass[i];
        totalForce += force[i];
    }
    EXPECT_NEAR(gridMass, mass, 1e-12 * mass);
    // each node's force is ~1e3 N/h ~ 1e4 N; the total cancels to rounding
    EXPECT_LT(totalForce.norm(), 1e-12 * 1e4 * double(s.x.size()));
}

TEST(ShapeFunctionContract, transfersConserveMassAndSumForcesToZero) {
    for (const std::string& type : ShapeFunction<2>::Selector::names()) checkTransferSums<2>(type);
    for (const std::string& type : ShapeFunction<3>::Selector::names()) checkTransferSums<3>(type);
}

}  // namespace
}  // namespace mfdyn
