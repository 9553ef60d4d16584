// The exact essential boundary conditions of Lee et al. 2016 App. B (doc/methods/tl-jst-sph.md 2.7) on nodal
// box lattices (faces included, h = 1.3 dx, wendlandC2, tributary volumes): after the projection
// the corrected-kernel interpolant of the rate meets the constraints C_B at every constrained
// particle; the change is the V-weighted least-squares one (orthogonal to every feasible change);
// only the constrained directions are acted on; particles out of reach are untouched; the
// momentum variant keeps the total force and moment.
//
// Tolerances. Residuals are round-off of the back-substitution (measured ~1e-15 relative, printed
// as "[measured]"); the bound 1e-10 leaves the conditioning of the multiplier matrix room. Before
// the projection the residual of a random field is O(1), so every bound can fail. Orthogonality
// and conservation are sums of ~1e3 products of O(1) terms: bounds 1e-12 relative to their scale.
#include "boundaryConditions/BoundaryConditionList.hpp"
#include "core/Dictionary.hpp"
#include "core/Error.hpp"
#include "kernels/Kernel.hpp"
#include "meshfreeOperators/ReferenceOperators.hpp"
#include "tlSph/LagrangeMultiplierProjection.hpp"
#include "tlSph/MomentumProjection.hpp"

#include <gtest/gtest.h>
#include <Eigen/Geometry>

#include <array>
#include <cmath>
#include <cstdio>
#include <map>
#include <memory>
#include <random>
#include <string>

namespace mfdyn {
namespace {

using Constraints2 = std::vector<LagrangeMultiplierProjection<2>::Constraint>;

template <int Dim>
struct Lattice {
    std::vector<Vector<Dim>> X;
    std::vector<double> V;
    std::vector<std::array<int, 3>> ijk;  // integer coordinates
    int n = 0;
    double dx = 0;
    std::unique_ptr<ReferenceOperators<Dim>> operators;
};

// n^Dim nodes on [0, 1]^Dim, dx = 1/(n-1), V = dx^Dim halved per face; W~ on.
template <int Dim>
Lattice<Dim> box(int n) {
    Lattice<Dim> l;
    l.n = n, l.dx = 1.0 / (n - 1);
    std::size_t total = 1;
    for (int d = 0; d < Dim; ++d) total *= std::size_t(n);
    for (std::size_t p = 0; p < total; ++p) {
        std::size_t rest = p;
        Vector<Dim> x;
        std::array<int, 3> c{0, 0, 0};
        double v = std::pow(l.dx, Dim);
        for (int d = 0; d < Dim; ++d) {
            c[d] = int(rest % std::size_t(n));
            rest /= std::size_t(n);
            x[d] = c[d] * l.dx;
            if (c[d] == 0 || c[d] == n - 1) v *= 0.5;
        }
        l.X.push_back(x), l.V.push_back(v), l.ijk.push_back(c);
    }
    const auto kernel = Kernel::New(Dictionary::parse("type wendlandC2;", "test"));
    typename ReferenceOperators<Dim>::Options options;
    options.laplacian = false;
    options.correctedKernel = true;
    l.operators = std::make_unique<ReferenceOperators<Dim>>(l.X, l.V, 1.3 * l.dx, *kernel, options);
    return l;
}

template <int Dim>
std::vector<Vector<Dim>> randomField(std::size_t n, unsigned seed, double scale = 1e3) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> u(-1, 1);
    std::vector<Vector<Dim>> f(n);
    for (auto& v : f)
        for (int d = 0; d < Dim; ++d) v[d] = scale * u(rng);
    return f;
}

template <int Dim>
Tensor<Dim> rollerProjector(int axis) {
    const Vector<Dim> e = Vector<Dim>::Unit(axis);
    return e * e.transpose();
}

// Clamped (I) on x = 0, rollers (e_y e_y^T) on y = 0, the edge x = y = 0 clamped (the union);
// in 3D also skew-symmetric (I - e_z e_z^T) on z = 1, its edges with the roller face constrain all.
template <int Dim>
std::vector<typename LagrangeMultiplierProjection<Dim>::Constraint> mixedConstraints(const Lattice<Dim>& l) {
    std::vector<typename LagrangeMultiplierProjection<Dim>::Constraint> c;
    for (std::size_t i = 0; i < l.X.size(); ++i) {
        Tensor<Dim> C = Tensor<Dim>::Zero();
        if (l.ijk[i][0] == 0) C = Tensor<Dim>::Identity();
        if (l.ijk[i][1] == 0) C = projectorUnion<Dim>(C, rollerProjector<Dim>(1));
        if (Dim == 3 && l.ijk[i][2] == l.n - 1)
            C = projectorUnion<Dim>(C, Tensor<Dim>(Tensor<Dim>::Identity() - rollerProjector<Dim>(Dim - 1)));
        if (C.norm() > 0) c.push_back({i, C});
    }
    return c;
}

template <int Dim>
double dotV(const std::vector<double>& V, const std::vector<Vector<Dim>>& a,
            const std::vector<Vector<Dim>>& b) {
    double s = 0;
    for (std::size_t i = 0; i < a.size(); ++i) s += V[i] * a[i].dot(b[i]);
    return s;
}

template <int Dim>
std::vector<Vector<Dim>> minus(const std::vector<Vector<Dim>>& a, const std::vector<Vector<Dim>>& b) {
    std::vector<Vector<Dim>> d(a.size());
    for (std::size_t i = 0; i < a.size(); ++i) d[i] = a[i] - b[i];
    return d;
}

template <int Dim>
void meetsTheConstraints(int n) {
    const auto l = box<Dim>(n);
    const LagrangeMultiplierProjection<Dim> lm(*l.operators, l.V, mixedConstraints(l));
    auto rate = randomField<Dim>(l.X.size(), 1);
    const auto prescribed = randomField<Dim>(lm.size(), 2);
    const double before = lm.residual(rate, prescribed);
    lm.project(rate, prescribed);
    const double after = lm.residual(rate, prescribed);
    std::printf("[measured] %dD: %zu constraints, %zu multipliers, residual %.3e -> %.3e\n", Dim, lm.size(),
                lm.unknowns(), before, after);
    EXPECT_GT(before, 1e-2);
    EXPECT_LT(after, 1e-10);
    // Idempotent: a field that meets the constraints is left as it is.
    const auto once = rate;
    lm.project(rate, prescribed);
    double change = 0, size = 0;
    for (std::size_t i = 0; i < rate.size(); ++i)
        change = std::max(change, (rate[i] - once[i]).norm()), size = std::max(size, once[i].norm());
    EXPECT_LT(change, 1e-10 * size);
}

TEST(LagrangeMultiplierProjection, MeetsClampedRollerAndMixedConstraints2D) {
    meetsTheConstraints<2>(21);
}
TEST(LagrangeMultiplierProjection, MeetsClampedRollerSkewAndMixedConstraints3D) {
    meetsTheConstraints<3>(9);
}

TEST(LagrangeMultiplierProjection, ClampedBarEnds1D) {
    const auto l = box<1>(41);
    const LagrangeMultiplierProjection<1> lm(*l.operators, l.V,
                                             {{0, Tensor<1>::Identity()}, {40, Tensor<1>::Identity()}});
    auto rate = randomField<1>(l.X.size(), 3);
    const std::vector<Vector<1>> prescribed{Vector<1>(5.0), Vector<1>(-7.0)};
    EXPECT_GT(lm.residual(rate, prescribed), 1e-2);
    lm.project(rate, prescribed);
    EXPECT_LT(lm.residual(rate, prescribed), 1e-10);
    EXPECT_NEAR(lm.interpolate(rate)[1][0], -7.0, 1e-9);
}

// Least squares: the feasible rates form an affine set {q : A q = r}; the minimiser p~ of
// sum V |q - p|^2 on it is characterised by sum V (p~ - p).(q - p~) = 0 for EVERY feasible q. A
// second feasible field q is the projection of an unrelated random field g.
template <int Dim>
void changesLeast(int n) {
    const auto l = box<Dim>(n);
    const LagrangeMultiplierProjection<Dim> lm(*l.operators, l.V, mixedConstraints(l));
    const auto p = randomField<Dim>(l.X.size(), 4);
    const auto prescribed = randomField<Dim>(lm.size(), 5);
    auto pTilde = p, q = randomField<Dim>(l.X.size(), 6);
    lm.project(pTilde, prescribed);
    lm.project(q, prescribed);
    ASSERT_LT(lm.residual(q, prescribed), 1e-10);
    const auto change = minus(pTilde, p), other = minus(q, pTilde);
    const double cosine =
        dotV(l.V, change, other) / std::sqrt(dotV(l.V, change, change) * dotV(l.V, other, other));
    std::printf("[measured] %dD: V-cosine between the change and a feasible direction %.3e\n", Dim, cosine);
    EXPECT_LT(std::abs(cosine), 1e-12);
    // Hence the smallest change: |q - p|_V >= |p~ - p|_V, strictly for q != p~.
    EXPECT_GT(dotV(l.V, minus(q, p), minus(q, p)), dotV(l.V, change, change));
    // The unweighted orthogonality does not hold: the V weighting is what is tested above.
    double plain = 0, a = 0, b = 0;
    for (std::size_t i = 0; i < p.size(); ++i)
        plain += change[i].dot(other[i]), a += change[i].squaredNorm(), b += other[i].squaredNorm();
    EXPECT_GT(std::abs(plain) / std::sqrt(a * b), 1e-6);
}

TEST(LagrangeMultiplierProjection, ChangeIsTheVWeightedLeastSquaresOne2D) {
    changesLeast<2>(21);
}
TEST(LagrangeMultiplierProjection, ChangeIsTheVWeightedLeastSquaresOne3D) {
    changesLeast<3>(9);
}

// Rollers only (normal e_y on y = 0): the multipliers act along e_y alone, so the x components
// are untouched everywhere, bit for bit; at the roller particles the tangential part of the
// interpolant is not forced to the prescribed value (which has a large tangential part here).
TEST(LagrangeMultiplierProjection, ActsOnlyInTheConstrainedDirections) {
    const auto l = box<2>(21);
    Constraints2 c;
    for (std::size_t i = 0; i < l.X.size(); ++i)
        if (l.ijk[i][1] == 0) c.push_back({i, rollerProjector<2>(1)});
    const LagrangeMultiplierProjection<2> lm(*l.operators, l.V, c);
    EXPECT_EQ(lm.unknowns(), lm.size());
    const auto p = randomField<2>(l.X.size(), 7);
    std::vector<Vector<2>> prescribed(lm.size(), Vector<2>(1e4, 30.0));
    auto rate = p;
    lm.project(rate, prescribed);
    EXPECT_LT(lm.residual(rate, prescribed), 1e-10);
    std::size_t changed = 0;
    for (std::size_t i = 0; i < p.size(); ++i) {
        EXPECT_EQ(rate[i][0], p[i][0]) << i;
        changed += rate[i][1] != p[i][1];
    }
    EXPECT_GT(changed, lm.size());
    const auto value = lm.interpolate(rate);
    for (std::size_t k = 0; k < lm.size(); ++k) {
        EXPECT_NEAR(value[k][1], 30.0, 1e-9 * 1e4) << k;
        EXPECT_GT(std::abs(value[k][0] - 1e4), 1e3) << k;  // not forced
    }
}

// Particles more than two supports from every constrained particle are not touched (they are
// beyond one support already); those within one support are.
TEST(LagrangeMultiplierProjection, FarParticlesAreUnchangedExactly) {
    const auto l = box<2>(31);
    Constraints2 c;
    for (std::size_t i = 0; i < l.X.size(); ++i)
        if (l.ijk[i][0] == 0) c.push_back({i, Tensor<2>::Identity()});
    const LagrangeMultiplierProjection<2> lm(*l.operators, l.V, c);
    const auto p = randomField<2>(l.X.size(), 8);
    auto rate = p;
    lm.project(rate, std::vector<Vector<2>>(lm.size(), Vector<2>::Zero()));
    const double support = 2 * 1.3 * l.dx;
    std::size_t far = 0, nearChanged = 0;
    for (std::size_t i = 0; i < p.size(); ++i) {
        if (l.X[i][0] > 2 * support) {
            ++far;
            EXPECT_EQ(rate[i], p[i]) << i;
        } else if (l.X[i][0] < support && rate[i] != p[i]) {
            ++nearChanged;
        }
    }
    EXPECT_GT(far, p.size() / 2);
    EXPECT_EQ(nearChanged, std::size_t(l.n) * 3);  // columns x = 0, dx, 2dx (< 2.6 dx)
}

// With (B.2) the total force sum V pdot and the moment sum V x~ x pdot are those of the input,
// the constraints still hold, and the change is least squares on the smaller feasible set
// (q: same constraints, same force and moment as p).
template <int Dim>
void conservesMomentum(int n) {
    const auto l = box<Dim>(n);
    const LagrangeMultiplierProjection<Dim> lm(*l.operators, l.V, mixedConstraints(l));
    const auto p = randomField<Dim>(l.X.size(), 9);
    const auto prescribed = randomField<Dim>(lm.size(), 10);
    auto xTilde = l.X;
    const auto noise = randomField<Dim>(l.X.size(), 11, 0.05);
    for (std::size_t i = 0; i < xTilde.size(); ++i) xTilde[i] += Vector<Dim>::Constant(3.0) + noise[i];
    auto totals = [&](const std::vector<Vector<Dim>>& f) {
        Vector<Dim> force = Vector<Dim>::Zero();
        Eigen::Vector3d moment = Eigen::Vector3d::Zero();
        for (std::size_t i = 0; i < f.size(); ++i) {
            force += l.V[i] * f[i];
            Eigen::Vector3d x3 = Eigen::Vector3d::Zero(), f3 = Eigen::Vector3d::Zero();
            x3.head<Dim>() = xTilde[i], f3.head<Dim>() = f[i];
            moment += l.V[i] * x3.cross(f3);
        }
        return std::make_pair(force, moment);
    };
    auto pTilde = p;
    lm.projectConservingMomentum(pTilde, prescribed, xTilde);
    EXPECT_LT(lm.residual(pTilde, prescribed), 1e-10);
    const auto [f0, m0] = totals(p);
    const auto [f1, m1] = totals(pTilde);
    // Scales: sum V |f| and sum V |x~| |f|.
    double fScale = 0, mScale = 0;
    for (std::size_t i = 0; i < p.size(); ++i)
        fScale += l.V[i] * p[i].norm(), mScale += l.V[i] * xTilde[i].norm() * p[i].norm();
    std::printf("[measured] %dD: residual %.3e, force change %.3e, moment change %.3e (relative)\n", Dim,
                lm.residual(pTilde, prescribed), (f1 - f0).norm() / fScale, (m1 - m0).norm() / mScale);
    EXPECT_LT((f1 - f0).norm(), 1e-12 * fScale);
    EXPECT_LT((m1 - m0).norm(), 1e-12 * mScale);
    // Without (B.2) the totals do change.
    auto plain = p;
    lm.project(plain, prescribed);
    EXPECT_GT((totals(plain).first - f0).norm(), 1e-3 * fScale);

    // Optimality: q = projection of p + h, h with zero force and moment about x~.
    auto h = randomField<Dim>(l.X.size(), 12);
    MomentumProjection<Dim>::momentum(h, l.V, xTilde);
    auto q = p;
    for (std::size_t i = 0; i < q.size(); ++i) q[i] += h[i];
    lm.projectConservingMomentum(q, prescribed, xTilde);
    const auto change = minus(pTilde, p), other = minus(q, pTilde);
    const double cosine =
        dotV(l.V, change, other) / std::sqrt(dotV(l.V, change, change) * dotV(l.V, other, other));
    EXPECT_LT(std::abs(cosine), 1e-11);
}

TEST(LagrangeMultiplierProjection, ConservingMomentumKeepsForceAndMoment2D) {
    conservesMomentum<2>(21);
}
TEST(LagrangeMultiplierProjection, ConservingMomentumKeepsForceAndMoment3D) {
    conservesMomentum<3>(9);
}

// Mirror ghosts after the real particles: never constrained, never modified, left out of sums.
TEST(LagrangeMultiplierProjection, IgnoresGhostNeighbours) {
    const auto l = box<2>(21);
    std::vector<Vector<2>> X = l.X;
    std::vector<double> V = l.V;
    const std::size_t n = X.size();
    for (std::size_t i = 0; i < n; ++i)
        if (l.ijk[i][0] > 0 && l.ijk[i][0] <= 6)
            X.push_back(Vector<2>(-l.X[i][0], l.X[i][1])), V.push_back(V[i]);
    const auto kernel = Kernel::New(Dictionary::parse("type wendlandC2;", "test"));
    ReferenceOperators<2>::Options options;
    options.laplacian = false, options.correctedKernel = true;
    const ReferenceOperators<2> operators(X, V, 1.3 * l.dx, *kernel, options);
    Constraints2 c;
    for (std::size_t i = 0; i < n; ++i)
        if (l.ijk[i][0] == 0) c.push_back({i, rollerProjector<2>(0)});
    const LagrangeMultiplierProjection<2> lm(operators, V, c, n);
    auto rate = randomField<2>(n, 13);
    const std::vector<Vector<2>> prescribed(lm.size(), Vector<2>::Zero());
    lm.project(rate, prescribed);
    EXPECT_LT(lm.residual(rate, prescribed), 1e-10);
    auto tooLong = randomField<2>(X.size(), 14);
    EXPECT_THROW(lm.project(tooLong, prescribed), Error);
    EXPECT_THROW(LagrangeMultiplierProjection<2>(operators, V, {{n, Tensor<2>::Identity()}}, n), Error);
}

TEST(LagrangeMultiplierProjection, RejectsBadInput) {
    const auto l = box<2>(11);
    EXPECT_THROW(LagrangeMultiplierProjection<2>(*l.operators, l.V,
                                                 {{3, Tensor<2>::Identity()}, {3, rollerProjector<2>(0)}}),
                 Error);
    EXPECT_THROW(LagrangeMultiplierProjection<2>(*l.operators, l.V, {{3, Tensor<2>::Identity() * 2.0}}),
                 Error);
    const auto kernel = Kernel::New(Dictionary::parse("type wendlandC2;", "test"));
    const ReferenceOperators<2> noKernel(l.X, l.V, 1.3 * l.dx, *kernel, {});
    EXPECT_THROW(LagrangeMultiplierProjection<2>(noKernel, l.V, {{3, Tensor<2>::Identity()}}), Error);
}

TEST(LagrangeMultiplierProjection, ProjectorUnion) {
    const Vector<2> a = Vector<2>(1, 1).normalized(), b(1, 0);
    EXPECT_LT((projectorUnion<2>(a * a.transpose(), b * b.transpose()) - Tensor<2>::Identity()).norm(),
              1e-15);
    EXPECT_LT((projectorUnion<2>(b * b.transpose(), b * b.transpose()) - b * b.transpose()).norm(), 1e-14);
    const Vector<3> e = Vector<3>::UnitZ();
    const Tensor<3> skew = Tensor<3>::Identity() - e * e.transpose();
    EXPECT_EQ(projectorUnion<3>(skew, rollerProjector<3>(2)), Tensor<3>::Identity());
    EXPECT_LT((projectorUnion<3>(skew, rollerProjector<3>(0)) - skew).norm(), 1e-14);
}

// From a case's conditions on the unit square (11 x 11): clamp on x = 0, rollers on y = 0 and
// x = 1, skew-symmetric on y = 1.
TEST(LagrangeMultiplierProjection, ConstraintsFromBoundaryConditions) {
    const int n = 11;
    ParticleSet<2> p(std::size_t(n * n));
    p.regionNames = {"body", "left"};
    for (std::size_t i = 0; i < p.size(); ++i) {
        p.position()[i] = Vector<2>(double(i % n) / (n - 1), double(i / n) / (n - 1));
        p.globalId()[i] = std::int64_t(i);
        p.region()[i] = i % n == 0 ? 1 : 0;
    }
    p.vectorField("velocity");
    auto at = [&](int i, int j) { return std::size_t(j * n + i); };
    const BoundaryConditionList<2> bcs(Dictionary::parse(R"(
        clamp  { type fixed; regions (left); releaseTime 1; }
        bottom { type symmetryPlane; point (0 0); normal (0 1); }
        right  { type symmetryPlane; point (1 0); normal (-1 0); }
        top    { type skewSymmetricPlane; point (0 1); normal (0 -1); }
        punch  { type prescribedVelocity; regions (left); table ((0 (0 0)) (2 (0 -4))); }
    )",
                                                         "constant/boundaryConditions"),
                                       p);
    const auto c = constraintsFrom<2>(bcs, p);
    EXPECT_EQ(c.size(), std::size_t(4 * (n - 1)));  // the perimeter
    std::map<std::size_t, Tensor<2>> C;
    for (const auto& k : c) C[k.particle] = k.projector;
    const Tensor<2> ex = rollerProjector<2>(0), ey = rollerProjector<2>(1);
    EXPECT_EQ(C.at(at(0, 0)), Tensor<2>::Identity());  // clamp + roller: the full projector
    EXPECT_EQ(C.at(at(0, 5)), Tensor<2>::Identity());
    EXPECT_LT((C.at(at(5, 0)) - ey).norm(), 1e-15);
    EXPECT_LT((C.at(at(n - 1, 0)) - Tensor<2>::Identity()).norm(), 1e-15);  // two rollers
    EXPECT_LT((C.at(at(5, n - 1)) - ex).norm(), 1e-15);                     // skew: tangential
    EXPECT_LT((C.at(at(n - 1, n - 1)) - ex).norm(), 1e-14);                 // roller x + skew = e_x only
    EXPECT_EQ(C.count(at(5, 5)), 0u);

    // The projector of a particle in a roller and a clamp constrains every direction in the
    // projection too: its interpolant takes the prescribed vector.
    const auto l = box<2>(n);
    const LagrangeMultiplierProjection<2> lm(*l.operators, l.V, c);
    const std::vector<double> rho0(p.size(), 2.0);
    const auto prescribed = prescribedRates<2>(bcs, c, rho0, 1.0);
    auto rate = randomField<2>(p.size(), 15);
    lm.project(rate, prescribed);
    EXPECT_LT(lm.residual(rate, prescribed), 1e-10);
    const auto value = lm.interpolate(rate);
    for (std::size_t k = 0; k < c.size(); ++k)
        if (c[k].particle == at(0, 0)) {
            EXPECT_LT((value[k] - Vector<2>(0, -4)).norm(), 1e-9);  // rho0 dv/dt
        }

    // After the clamp's releaseTime the left column keeps only the prescribed velocity and the
    // rollers; prescribedRates is rho0 dv_pres/dt for the punch, zero elsewhere.
    EXPECT_EQ(constraintsFrom<2>(bcs, p, 1.5).size(), c.size());
    for (std::size_t k = 0; k < c.size(); ++k)
        EXPECT_EQ(prescribed[k], c[k].particle % n == 0 ? Vector<2>(0, -4) : Vector<2>::Zero()) << k;
    const auto late = prescribedRates<2>(bcs, c, rho0, 3.0);  // after the table: constant velocity
    for (const auto& v : late) EXPECT_EQ(v, Vector<2>::Zero());
}

}  // namespace
}  // namespace mfdyn
