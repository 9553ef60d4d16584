// Exactness tests of the least-squares operators on a jittered box lattice that includes its faces
// and corners (boundary points: the neighbourhood is one-sided), with a smoothing length that
// varies by +-25% across the box, at the particles (difference form) and at points between and
// just outside them (value form).
//
// Tolerances: the reproduced identities are exact in exact arithmetic; what is left is round-off
// of sums of ~10-60 terms through a moment matrix of condition 1e2-1e4, so 1e-10 of the operator's
// natural scale (|f| / h for a gradient, |f| / h^2 for second derivatives, with |f| = O(1) on the
// unit box) leaves a few decades above the measured errors (printed as "[measured]").
#include "core/Dictionary.hpp"
#include "core/Error.hpp"
#include "kernels/Kernel.hpp"
#include "meshfreeOperators/LeastSquaresOperators.hpp"

#include <gtest/gtest.h>
#include <omp.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <random>
#include <string>

namespace mfdyn {
namespace {

std::unique_ptr<Kernel> wendland() {
    return Kernel::New(Dictionary::parse("type wendlandC2;", "test"));
}

template <int Dim>
struct Cloud {
    std::vector<Vector<Dim>> x;
    std::vector<double> V;
    std::vector<double> h;  // per particle, varying smoothly
    std::vector<bool> boundary;
    double dx = 0.0;
};

// n^Dim points on [0, 1]^Dim, interior ones jittered by up to 0.15 dx per component, h from
// 1.1 dx to 1.6 dx across the box (enough neighbours for the quadratic basis everywhere, corners
// included).
template <int Dim>
Cloud<Dim> box(int n) {
    Cloud<Dim> c;
    c.dx = 1.0 / (n - 1);
    std::mt19937_64 rng(2026);
    std::uniform_real_distribution<double> jitter(-0.15, 0.15);
    std::size_t total = 1;
    for (int d = 0; d < Dim; ++d) total *= std::size_t(n);
    for (std::size_t p = 0; p < total; ++p) {
        std::size_t rest = p;
        Vector<Dim> x;
        bool onFace = false;
        for (int d = 0; d < Dim; ++d) {
            const int i = int(rest % std::size_t(n));
            rest /= std::size_t(n);
            x[d] = i * c.dx;
            onFace = onFace || i == 0 || i == n - 1;
        }
        if (!onFace)
            for (int d = 0; d < Dim; ++d) x[d] += jitter(rng) * c.dx;
        c.x.push_back(x);
        c.V.push_back(std::pow(c.dx, Dim));
        c.boundary.push_back(onFace);
        c.h.push_back(c.dx * (1.1 + 0.5 * x[0]));
    }
    return c;
}

// Gather rows: the particles within the support radius of each point's own h (self included, to
// show that it carries nothing in the difference form).
template <int Dim>
NeighbourList gatherRows(const std::vector<Vector<Dim>>& points, const std::vector<double>& h,
                         const std::vector<Vector<Dim>>& x, const Kernel& kernel) {
    std::vector<std::size_t> offsets{0};
    std::vector<NeighbourList::Index> indices;
    for (std::size_t a = 0; a < points.size(); ++a) {
        for (std::size_t b = 0; b < x.size(); ++b)
            if ((x[b] - points[a]).norm() < kernel.supportRadius(h[a]))
                indices.push_back(NeighbourList::Index(b));
        offsets.push_back(indices.size());
    }
    return NeighbourList(std::move(offsets), std::move(indices));
}

// f = c + g.x + 1/2 x^T A x with A symmetric: grad f = g + A x, Hess f = A, Lap f = tr A.
template <int Dim>
struct Quadratic {
    double c = 0.3;
    Vector<Dim> g;
    Tensor<Dim> A;
    explicit Quadratic(bool linearOnly) {
        for (int i = 0; i < Dim; ++i) {
            g[i] = 0.7 - 0.4 * i;
            for (int j = 0; j < Dim; ++j)
                A(i, j) = linearOnly ? 0.0 : (i == j ? 1.5 - i : 0.6 + 0.1 * (i + j));
        }
    }
    double operator()(const Vector<Dim>& x) const { return c + g.dot(x) + 0.5 * x.dot(A * x); }
    Vector<Dim> gradient(const Vector<Dim>& x) const { return g + A * x; }
};

template <int Dim>
std::vector<double> sampled(const Quadratic<Dim>& f, const std::vector<Vector<Dim>>& x) {
    std::vector<double> out;
    for (const auto& p : x) out.push_back(f(p));
    return out;
}

using Ops1 = LeastSquaresOperators<1>;

template <int Dim>
typename LeastSquaresOperators<Dim>::Options options(int order,
                                                     typename LeastSquaresOperators<Dim>::Form form) {
    typename LeastSquaresOperators<Dim>::Options o;
    o.order = order;
    o.form = form;
    return o;
}

template <int Dim>
int cloudSize() {
    return Dim == 1 ? 31 : Dim == 2 ? 16 : 7;
}

// Errors in units of the operator's scale at the point (h for the gradient, h^2 for second
// derivatives), worst over interior and over boundary points separately.
template <int Dim>
void checkAtParticles(int order) {
    const auto kernel = wendland();
    const Cloud<Dim> c = box<Dim>(cloudSize<Dim>());
    const NeighbourList rows = gatherRows<Dim>(c.x, c.h, c.x, *kernel);
    LeastSquaresOperators<Dim> ops(options<Dim>(order, LeastSquaresOperators<Dim>::Form::difference));
    ops.rebuild(c.x, c.x, rows, c.V, c.h, *kernel);
    const Quadratic<Dim> f(order == 1);
    const auto values = sampled(f, c.x);
    const auto grad = ops.gradientOf(values);
    double errGrad[2] = {0, 0}, errHess[2] = {0, 0}, errLap[2] = {0, 0};
    std::vector<Tensor<Dim>> hess;
    std::vector<double> lap;
    if (order == 2) {
        hess = ops.hessianOf(values);
        lap = ops.laplacianOf(values);
    }
    for (std::size_t a = 0; a < c.x.size(); ++a) {
        const int side = c.boundary[a] ? 1 : 0;
        errGrad[side] = std::max(errGrad[side], (grad[a] - f.gradient(c.x[a])).norm() * c.h[a]);
        if (order == 2) {
            errHess[side] = std::max(errHess[side], (hess[a] - f.A).norm() * c.h[a] * c.h[a]);
            errLap[side] = std::max(errLap[side], std::abs(lap[a] - f.A.trace()) * c.h[a] * c.h[a]);
        }
    }
    std::printf(
        "[measured] %dD order %d at particles: gradient %.2e / %.2e, Hessian %.2e / %.2e, "
        "Laplacian %.2e / %.2e (interior / boundary)\n",
        Dim, order, errGrad[0], errGrad[1], errHess[0], errHess[1], errLap[0], errLap[1]);
    for (int side = 0; side < 2; ++side) {
        EXPECT_LT(errGrad[side], 1e-10) << "side " << side;
        EXPECT_LT(errHess[side], 1e-10) << "side " << side;
        EXPECT_LT(errLap[side], 1e-10) << "side " << side;
    }
}

TEST(LeastSquaresOperators, order1GradientExactOnLinearFieldsAtParticles1D) {
    checkAtParticles<1>(1);
}
TEST(LeastSquaresOperators, order1GradientExactOnLinearFieldsAtParticles2D) {
    checkAtParticles<2>(1);
}
TEST(LeastSquaresOperators, order1GradientExactOnLinearFieldsAtParticles3D) {
    checkAtParticles<3>(1);
}
TEST(LeastSquaresOperators, order2ExactOnQuadraticFieldsAtParticles1D) {
    checkAtParticles<1>(2);
}
TEST(LeastSquaresOperators, order2ExactOnQuadraticFieldsAtParticles2D) {
    checkAtParticles<2>(2);
}
TEST(LeastSquaresOperators, order2ExactOnQuadraticFieldsAtParticles3D) {
    checkAtParticles<3>(2);
}

// Points between the particles and a quarter spacing outside the box (one-sided neighbourhoods),
// each with its own h.
template <int Dim>
void checkAtOtherPoints(int order) {
    const auto kernel = wendland();
    const Cloud<Dim> c = box<Dim>(cloudSize<Dim>());
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> u(-0.25 * c.dx, 1.0 + 0.25 * c.dx);
    std::vector<Vector<Dim>> points;
    std::vector<double> h;
    for (int p = 0; p < 60; ++p) {
        Vector<Dim> y;
        for (int d = 0; d < Dim; ++d) y[d] = u(rng);
        if (p < 2) y.setConstant(p == 0 ? -0.25 * c.dx : 1.0 + 0.25 * c.dx);  // beyond two corners
        points.push_back(y);
        h.push_back(c.dx * (1.4 + 0.4 * std::abs(y[0])));
    }
    const NeighbourList rows = gatherRows<Dim>(points, h, c.x, *kernel);
    LeastSquaresOperators<Dim> ops(options<Dim>(order, LeastSquaresOperators<Dim>::Form::value));
    ops.rebuild(points, c.x, rows, c.V, h, *kernel);
    const Quadratic<Dim> f(order == 1);
    const auto values = sampled(f, c.x);
    const auto interpolated = ops.valueOf(values);
    const auto grad = ops.gradientOf(values);
    double errValue = 0, errGrad = 0, errHess = 0, errLap = 0;
    for (std::size_t a = 0; a < points.size(); ++a) {
        errValue = std::max(errValue, std::abs(interpolated[a] - f(points[a])));
        errGrad = std::max(errGrad, (grad[a] - f.gradient(points[a])).norm() * h[a]);
    }
    if (order == 2) {
        const auto hess = ops.hessianOf(values);
        const auto lap = ops.laplacianOf(values);
        for (std::size_t a = 0; a < points.size(); ++a) {
            errHess = std::max(errHess, (hess[a] - f.A).norm() * h[a] * h[a]);
            errLap = std::max(errLap, std::abs(lap[a] - f.A.trace()) * h[a] * h[a]);
        }
    }
    std::printf(
        "[measured] %dD order %d at other points: value %.2e, gradient %.2e, Hessian %.2e, "
        "Laplacian %.2e\n",
        Dim, order, errValue, errGrad, errHess, errLap);
    EXPECT_LT(errValue, 1e-10);
    EXPECT_LT(errGrad, 1e-10);
    EXPECT_LT(errHess, 1e-10);
    EXPECT_LT(errLap, 1e-10);
}

TEST(LeastSquaresOperators, order1ValueAndGradientExactOnLinearFieldsAtOtherPoints2D) {
    checkAtOtherPoints<2>(1);
}
TEST(LeastSquaresOperators, order1ValueAndGradientExactOnLinearFieldsAtOtherPoints3D) {
    checkAtOtherPoints<3>(1);
}
TEST(LeastSquaresOperators, order2ExactOnQuadraticFieldsAtOtherPoints1D) {
    checkAtOtherPoints<1>(2);
}
TEST(LeastSquaresOperators, order2ExactOnQuadraticFieldsAtOtherPoints2D) {
    checkAtOtherPoints<2>(2);
}
TEST(LeastSquaresOperators, order2ExactOnQuadraticFieldsAtOtherPoints3D) {
    checkAtOtherPoints<3>(2);
}

// A vector field's gradient is the tensor of its components' gradients, row = component.
TEST(LeastSquaresOperators, vectorGradientRowsAreComponents) {
    const auto kernel = wendland();
    const Cloud<2> c = box<2>(12);
    const NeighbourList rows = gatherRows<2>(c.x, c.h, c.x, *kernel);
    LeastSquaresOperators<2> ops(options<2>(1, LeastSquaresOperators<2>::Form::difference));
    ops.rebuild(c.x, c.x, rows, c.V, c.h, *kernel);
    Tensor<2> C;
    C << 1.0, -2.0, 0.5, 3.0;
    std::vector<Vector<2>> u;
    for (const auto& x : c.x) u.push_back(C * x);
    for (const auto& G : ops.gradientOf(u)) EXPECT_LT((G - C).norm(), 1e-10);
}

// The pair arrays keep their memory on a rebuild with the same neighbour counts (particles moved
// within their rows, as in a step between neighbour-list rebuilds), and the new weights are the
// moved configuration's.
TEST(LeastSquaresOperators, rebuildReusesMemory) {
    const auto kernel = wendland();
    Cloud<2> c = box<2>(12);
    const NeighbourList rows = gatherRows<2>(c.x, c.h, c.x, *kernel);
    LeastSquaresOperators<2> ops(options<2>(2, LeastSquaresOperators<2>::Form::difference));
    ops.rebuild(c.x, c.x, rows, c.V, c.h, *kernel);
    const std::size_t capacity = ops.capacity();
    const auto* gradientData = ops.gradient().data();
    const auto* hessianData = ops.hessian().data();
    const auto* laplacianData = ops.laplacian().data();
    EXPECT_EQ(capacity, rows.pairCount());
    // A small rigid shift and stretch: rows stay valid (support radii are checked at the rebuild only
    // through the weights, which stay positive for pairs moved by 1e-3 dx).
    for (auto& x : c.x) x = Vector<2>(1.001 * x[0] + 1e-3, x[1]);
    ops.rebuild(c.x, c.x, rows, c.V, c.h, *kernel);
    EXPECT_EQ(ops.capacity(), capacity);
    EXPECT_EQ(ops.gradient().data(), gradientData);
    EXPECT_EQ(ops.hessian().data(), hessianData);
    EXPECT_EQ(ops.laplacian().data(), laplacianData);
    const Quadratic<2> f(false);
    const auto grad = ops.gradientOf(sampled(f, c.x));
    for (std::size_t a = 0; a < c.x.size(); ++a)
        EXPECT_LT((grad[a] - f.gradient(c.x[a])).norm() * c.h[a], 1e-10);
}

TEST(LeastSquaresOperators, identicalForOneAndTwoThreads) {
    const auto kernel = wendland();
    const Cloud<3> c = box<3>(9);  // enough pairs for the parallel path
    const NeighbourList rows = gatherRows<3>(c.x, c.h, c.x, *kernel);
    auto build = [&](int threads) {
        omp_set_num_threads(threads);
        LeastSquaresOperators<3> ops(options<3>(2, LeastSquaresOperators<3>::Form::difference));
        ops.rebuild(c.x, c.x, rows, c.V, c.h, *kernel);
        return ops.hessian();
    };
    const auto one = build(1);
    const auto two = build(2);
    omp_set_num_threads(1);
    ASSERT_EQ(one.size(), two.size());
    for (std::size_t k = 0; k < one.size(); ++k) ASSERT_TRUE(one[k] == two[k]) << "pair " << k;
}

// Neighbours on one line in 2D do not determine a 2D gradient: an Error naming the point, or, with
// OnFailure::flag, a status and zero weights for a caller's fallback.
TEST(LeastSquaresOperators, undeterminedPointIsNamedOrFlagged) {
    std::vector<Vector<2>> x;
    for (int i = 0; i < 6; ++i) x.push_back(Vector<2>(0.1 * i, 0.0));
    const std::vector<double> V(x.size(), 0.01), h(x.size(), 0.25);
    const auto kernel = wendland();
    const NeighbourList rows = gatherRows<2>(x, h, x, *kernel);
    LeastSquaresOperators<2> ops(options<2>(1, LeastSquaresOperators<2>::Form::difference));
    try {
        ops.rebuild(x, x, rows, V, h, *kernel);
        FAIL() << "collinear neighbours accepted";
    } catch (const Error& e) {
        const std::string what = e.what();
        EXPECT_NE(what.find("point 0 at (0 0)"), std::string::npos) << what;
        EXPECT_NE(what.find("ill-conditioned moment matrix"), std::string::npos) << what;
        EXPECT_NE(what.find("5 more points fail alike"), std::string::npos) << what;
    }
    auto o = options<2>(1, LeastSquaresOperators<2>::Form::difference);
    o.onFailure = LeastSquaresOperators<2>::OnFailure::flag;
    LeastSquaresOperators<2> flagged(o);
    flagged.rebuild(x, x, rows, V, h, *kernel);
    for (auto s : flagged.status()) EXPECT_EQ(s, LeastSquaresOperators<2>::Status::illConditioned);
    for (const auto& g : flagged.gradient()) EXPECT_EQ(g.norm(), 0.0);

    // Order 2 in 1D needs two neighbours: an isolated pair has one each.
    const std::vector<Vector<1>> pair{Vector<1>(0.0), Vector<1>(0.1)};
    const std::vector<double> V1(2, 0.1), h1(2, 0.2);
    Ops1 second(options<1>(2, Ops1::Form::difference));
    EXPECT_THROW(second.rebuild(pair, pair, gatherRows<1>(pair, h1, pair, *kernel), V1, h1, *kernel), Error);
}

TEST(LeastSquaresOperators, badArgumentsAreClearErrors) {
    EXPECT_THROW(Ops1(options<1>(3, Ops1::Form::value)), Error);
    Ops1 ops(options<1>(1, Ops1::Form::difference));
    EXPECT_THROW(ops.hessian(), Error);
    EXPECT_THROW(ops.value(), Error);
    const std::vector<Vector<1>> x{Vector<1>(0.0), Vector<1>(0.1), Vector<1>(0.2)};
    const std::vector<Vector<1>> other{Vector<1>(0.05)};
    const auto kernel = wendland();
    const std::vector<double> V(3, 0.1), h(3, 0.2), h1(1, 0.2);
    // The difference form needs f at the point: other points are refused.
    EXPECT_THROW(ops.rebuild(other, x, gatherRows<1>(other, h1, x, *kernel), V, h1, *kernel), Error);
    const std::vector<double> zeroH(3, 0.0);
    EXPECT_THROW(ops.rebuild(x, x, gatherRows<1>(x, h, x, *kernel), V, zeroH, *kernel), Error);
    ops.rebuild(x, x, gatherRows<1>(x, h, x, *kernel), V, h, *kernel);
    EXPECT_THROW(ops.gradientOf(std::vector<double>(2)), Error);
}

}  // namespace
}  // namespace mfdyn
