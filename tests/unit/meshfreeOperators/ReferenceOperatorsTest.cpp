// Patch tests of the reference-configuration operators (doc/methods/tl-jst-sph.md 2.2-2.3) on a jittered box
// lattice that includes its faces, so that every correction is exercised where it matters: at the
// boundary, where the uncorrected kernel gradient is wrong by O(1).
//
// Tolerances. The identities checked are exact in exact arithmetic; what is left is round-off of
// sums of ~10-80 terms of size |f| V |g| (gradient ~ 1/dx, Laplacian ~ 1/dx^2), so the bounds are
// stated relative to the natural scale of each operator and sit a few decades above the measured
// errors (printed as "[measured]").
#include "core/Dictionary.hpp"
#include "core/Error.hpp"
#include "kernels/Kernel.hpp"
#include "meshfreeOperators/ReferenceOperators.hpp"

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

std::unique_ptr<Kernel> makeKernel(const std::string& type) {
    return Kernel::New(Dictionary::parse("type " + type + ";", "test"));
}

template <int Dim>
struct Lattice {
    std::vector<Vector<Dim>> X;
    std::vector<double> V;
    std::vector<bool> boundary;  // on a face of the box
    double dx = 0.0;
};

// n^Dim points on [0, 1]^Dim with the faces, dx = 1/(n-1); interior points jittered uniformly by
// up to 0.1 dx per component; tributary volumes (dx^Dim halved per face), so that sum V = 1.
template <int Dim>
Lattice<Dim> box(int n, unsigned seed = 12345) {
    Lattice<Dim> l;
    l.dx = 1.0 / (n - 1);
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> jitter(-0.1, 0.1);
    std::size_t total = 1;
    for (int d = 0; d < Dim; ++d) total *= std::size_t(n);
    for (std::size_t p = 0; p < total; ++p) {
        std::size_t rest = p;
        Vector<Dim> x;
        double v = std::pow(l.dx, Dim);
        bool onFace = false;
        for (int d = 0; d < Dim; ++d) {
            const int i = int(rest % std::size_t(n));
            rest /= std::size_t(n);
            x[d] = i * l.dx;
            if (i == 0 || i == n - 1) {
                onFace = true;
                v *= 0.5;
            }
        }
        if (!onFace)
            for (int d = 0; d < Dim; ++d) x[d] += jitter(rng) * l.dx;
        l.X.push_back(x);
        l.V.push_back(v);
        l.boundary.push_back(onFace);
    }
    return l;
}

template <int Dim>
int latticeSize() {
    return Dim == 1 ? 41 : Dim == 2 ? 30 : 11;
}

template <int Dim>
struct Linear {
    Tensor<Dim> C;
    Vector<Dim> d;
    Vector<Dim> c;  // scalar gradient
    double e = 0.3;
    Linear() {
        for (int i = 0; i < Dim; ++i) {
            c[i] = 0.7 - 1.3 * i;
            d[i] = 0.2 + 0.1 * i;
            for (int j = 0; j < Dim; ++j) C(i, j) = 1.0 + 0.5 * i - 0.8 * j + 0.3 * i * j;
        }
    }
    double scalar(const Vector<Dim>& x) const { return c.dot(x) + e; }
    Vector<Dim> vector(const Vector<Dim>& x) const { return C * x + d; }
};

template <int Dim>
using Options = typename ReferenceOperators<Dim>::Options;

class ReferenceOperatorsPatch : public ::testing::TestWithParam<std::string> {
protected:
    void SetUp() override { kernel = makeKernel(GetParam()); }

    template <int Dim>
    ReferenceOperators<Dim> build(const Lattice<Dim>& l, Options<Dim> options) const {
        return ReferenceOperators<Dim>(l.X, l.V, 1.3 * l.dx, *kernel, options);
    }

    template <int Dim>
    void linearGradient(GradientCorrection correction) {
        const auto l = box<Dim>(latticeSize<Dim>());
        Options<Dim> options;
        options.gradient = correction;
        options.laplacian = false;
        const auto ops = build<Dim>(l, options);
        const Linear<Dim> lin;
        std::vector<double> fs(l.X.size());
        std::vector<Vector<Dim>> fv(l.X.size());
        for (std::size_t a = 0; a < l.X.size(); ++a) {
            fs[a] = lin.scalar(l.X[a]);
            fv[a] = lin.vector(l.X[a]);
        }
        const auto gs = ops.gradientOf(fs);
        const auto gv = ops.gradientOf(fv);
        double errScalar = 0.0, errVector = 0.0, errBoundary = 0.0;
        for (std::size_t a = 0; a < l.X.size(); ++a) {
            const double es = (gs[a] - lin.c).norm() / lin.c.norm();
            const double ev = (gv[a] - lin.C).norm() / lin.C.norm();
            errScalar = std::max(errScalar, es);
            errVector = std::max(errVector, ev);
            if (l.boundary[a]) errBoundary = std::max(errBoundary, std::max(es, ev));
        }
        std::printf("[measured] %s %dD %s gradient of linear fields: max rel error scalar %.2e vector %.2e\n",
                    GetParam().c_str(), Dim, gradientCorrectionName(correction).c_str(), errScalar,
                    errVector);
        if (correction == GradientCorrection::uncorrected) {
            EXPECT_GT(errBoundary, 1e-3) << Dim << "D: the uncorrected gradient should fail at the boundary";
        } else {
            // Sums of ~80 terms of size |f| V |g| ~ |grad f|: round-off ~1e-15 relative.
            EXPECT_LT(errScalar, 1e-12) << Dim << "D";
            EXPECT_LT(errVector, 1e-12) << Dim << "D";
        }
    }

    template <int Dim>
    void laplacianPatch() {
        const auto l = box<Dim>(latticeSize<Dim>());
        const auto ops = build<Dim>(l, Options<Dim>{});
        const Linear<Dim> lin;
        const std::size_t n = l.X.size();
        std::vector<double> linear(n), quadratic(n);
        std::vector<Vector<Dim>> linearVector(n);
        for (std::size_t a = 0; a < n; ++a) {
            linear[a] = lin.scalar(l.X[a]);
            linearVector[a] = lin.vector(l.X[a]);
            quadratic[a] = 0.5 * l.X[a].squaredNorm() + lin.scalar(l.X[a]);
        }
        const auto Llin = ops.laplacianOf(linear);
        const auto LlinV = ops.laplacianOf(linearVector);
        const auto Lq = ops.laplacianOf(quadratic);
        const auto LLq = ops.laplacianOf(Lq);
        // Scale of a round-off error in L[f] after a second application: |L| sum_b V_b |Lap~_ab|.
        double weightSum = 0.0;
        const auto& off = ops.neighbours().offsets();
        const auto& idx = ops.neighbours().indices();
        for (std::size_t a = 0; a < n; ++a) {
            double s = 0.0;
            for (std::size_t k = off[a]; k < off[a + 1]; ++k) s += l.V[idx[k]] * std::abs(ops.laplacian()[k]);
            weightSum = std::max(weightSum, s);
        }
        double errLin = 0.0, errQ = 0.0, errBi = 0.0, errBiInterior = 0.0;
        for (std::size_t a = 0; a < n; ++a) {
            errLin = std::max(errLin, std::abs(Llin[a]) / (lin.c.norm() / l.dx));
            errLin = std::max(errLin, LlinV[a].norm() / (lin.C.norm() / l.dx));
            errQ = std::max(errQ, std::abs(Lq[a] - Dim));
            const double bi = std::abs(LLq[a]) / (Dim * weightSum);
            errBi = std::max(errBi, bi);
            if (!l.boundary[a]) errBiInterior = std::max(errBiInterior, bi);
        }
        std::printf(
            "[measured] %s %dD Laplacian: linear %.2e (rel |grad|/dx), |X|^2/2 %.2e (abs), bi-Laplacian %.2e "
            "(all rows) %.2e (interior), rel to Dim max sum V|Lap~| = %.3g\n",
            GetParam().c_str(), Dim, errLin, errQ, errBi, errBiInterior, Dim * weightSum);
        EXPECT_LT(errLin, 1e-10) << Dim << "D";
        EXPECT_LT(errQ, 1e-10) << Dim << "D";
        EXPECT_LT(errBiInterior, 1e-8) << Dim << "D";
    }

    template <int Dim>
    void internalForceIdentities(GradientCorrection correction) {
        const auto l = box<Dim>(latticeSize<Dim>());
        Options<Dim> options;
        options.gradient = correction;
        options.laplacian = false;
        const auto ops = build<Dim>(l, options);
        const std::size_t n = l.X.size();
        std::mt19937_64 rng(7);
        std::uniform_real_distribution<double> u(-1.0, 1.0);
        std::vector<Tensor<Dim>> random(n), constant(n);
        Tensor<Dim> P0;
        for (int i = 0; i < Dim; ++i)
            for (int j = 0; j < Dim; ++j) P0(i, j) = 1.0 + i - 2.0 * j + 0.5 * i * j;
        for (std::size_t a = 0; a < n; ++a) {
            for (int i = 0; i < Dim; ++i)
                for (int j = 0; j < Dim; ++j) random[a](i, j) = u(rng);
            constant[a] = P0;
        }
        for (const auto* P : {&random, &constant}) {
            const auto T = ops.internalForce(*P);
            Vector<Dim> total = Vector<Dim>::Zero();
            Tensor<Dim> moment = Tensor<Dim>::Zero(), stress = Tensor<Dim>::Zero();
            double scaleT = 0.0, scaleM = 0.0, scaleP = 0.0;
            for (std::size_t a = 0; a < n; ++a) {
                total += l.V[a] * T[a];
                scaleT += l.V[a] * T[a].norm();
                moment += l.V[a] * T[a] * l.X[a].transpose();
                scaleM += l.V[a] * T[a].norm() * l.X[a].norm();
                stress += l.V[a] * (*P)[a];
                scaleP += l.V[a] * (*P)[a].norm();
            }
            const double errTotal = total.norm() / scaleT;
            const double errMoment = (moment - stress).norm() / std::max(scaleP, scaleM);
            std::printf(
                "[measured] %s %dD %s internalForce (%s P): |sum V T|/sum V|T| %.2e, "
                "|sum V T(x)X - sum V P| rel %.2e\n",
                GetParam().c_str(), Dim, gradientCorrectionName(correction).c_str(),
                P == &random ? "random" : "constant", errTotal, errMoment);
            EXPECT_LT(errTotal, 1e-12) << Dim << "D";
            if (correction != GradientCorrection::uncorrected) {
                EXPECT_LT(errMoment, 1e-12) << Dim << "D";
            }
        }
    }

    template <int Dim>
    void correctedKernel() {
        const auto l = box<Dim>(latticeSize<Dim>());
        Options<Dim> options;
        options.laplacian = false;
        options.correctedKernel = true;
        const auto ops = build<Dim>(l, options);
        const auto& off = ops.neighbours().offsets();
        const auto& idx = ops.neighbours().indices();
        double errOne = 0.0, errX = 0.0;
        for (std::size_t a = 0; a < l.X.size(); ++a) {
            double sum = l.V[a] * ops.correctedKernelSelf()[a];
            Vector<Dim> first = l.V[a] * ops.correctedKernelSelf()[a] * l.X[a];
            for (std::size_t k = off[a]; k < off[a + 1]; ++k) {
                sum += l.V[idx[k]] * ops.correctedKernel()[k];
                first += l.V[idx[k]] * ops.correctedKernel()[k] * l.X[idx[k]];
            }
            errOne = std::max(errOne, std::abs(sum - 1.0));
            errX = std::max(errX, (first - l.X[a]).norm());
        }
        std::printf("[measured] %s %dD corrected kernel: |sum V W~ - 1| %.2e, |sum V W~ X_b - X_a| %.2e\n",
                    GetParam().c_str(), Dim, errOne, errX);
        EXPECT_LT(errOne, 1e-12) << Dim << "D";
        EXPECT_LT(errX, 1e-12) << Dim << "D";
    }

    template <int Dim>
    void neighbourGradient() {
        const auto l = box<Dim>(latticeSize<Dim>());
        for (auto correction : {GradientCorrection::corrected, GradientCorrection::uncorrected,
                                GradientCorrection::correctedKernel}) {
            Options<Dim> options;
            options.gradient = correction;
            options.laplacian = false;
            const auto ops = build<Dim>(l, options);
            const auto& off = ops.neighbours().offsets();
            const auto& idx = ops.neighbours().indices();
            double err = 0.0;
            for (std::size_t a = 0; a < l.X.size(); ++a)
                for (std::size_t k = off[a]; k < off[a + 1]; ++k) {
                    const std::size_t b = idx[k];
                    const auto row = ops.neighbours()[b];
                    const auto it = std::find(row.begin(), row.end(), NeighbourList::Index(a));
                    ASSERT_NE(it, row.end()) << "pair (" << a << ", " << b << ") has no mirror";
                    const std::size_t kb = off[b] + std::size_t(it - row.begin());
                    err = std::max(err, (ops.gradientAtNeighbour()[k] - ops.gradient()[kb]).norm());
                }
            EXPECT_LE(err, 1e-15) << Dim << "D " << gradientCorrectionName(correction);
        }
    }

    std::unique_ptr<Kernel> kernel;
};

TEST_P(ReferenceOperatorsPatch, correctedGradientExactOnLinearFields) {
    linearGradient<1>(GradientCorrection::corrected);
    linearGradient<2>(GradientCorrection::corrected);
    linearGradient<3>(GradientCorrection::corrected);
}

TEST_P(ReferenceOperatorsPatch, correctedKernelGradientExactOnLinearFields) {
    linearGradient<1>(GradientCorrection::correctedKernel);
    linearGradient<2>(GradientCorrection::correctedKernel);
    linearGradient<3>(GradientCorrection::correctedKernel);
}

TEST_P(ReferenceOperatorsPatch, uncorrectedGradientWrongAtTheBoundary) {
    linearGradient<1>(GradientCorrection::uncorrected);
    linearGradient<2>(GradientCorrection::uncorrected);
    linearGradient<3>(GradientCorrection::uncorrected);
}

TEST_P(ReferenceOperatorsPatch, correctedLaplacianExactOnLinearAndHalfSquaredNorm) {
    laplacianPatch<1>();
    laplacianPatch<2>();
    laplacianPatch<3>();
}

TEST_P(ReferenceOperatorsPatch, internalForceConservesAndMatchesStressIntegral) {
    for (auto correction : {GradientCorrection::corrected, GradientCorrection::correctedKernel}) {
        internalForceIdentities<1>(correction);
        internalForceIdentities<2>(correction);
        internalForceIdentities<3>(correction);
    }
    internalForceIdentities<3>(GradientCorrection::uncorrected);  // momentum only
}

TEST_P(ReferenceOperatorsPatch, correctedKernelReproducesConstantsAndLinearFields) {
    correctedKernel<1>();
    correctedKernel<2>();
    correctedKernel<3>();
}

TEST_P(ReferenceOperatorsPatch, gradientAtNeighbourIsTheMirrorPairsGradient) {
    neighbourGradient<1>();
    neighbourGradient<2>();
    neighbourGradient<3>();
}

INSTANTIATE_TEST_SUITE_P(kernels, ReferenceOperatorsPatch, ::testing::Values("cubicSpline", "wendlandC2"),
                         [](const auto& info) { return info.param; });

// 1 and 2 threads give bit-identical operators and results. Above parallelThreshold (4096) rows so
// that the loops do run in parallel.
template <int Dim>
void compareThreadCounts(int n) {
    const auto kernel = makeKernel("wendlandC2");
    const auto l = box<Dim>(n);
    ASSERT_GT(l.X.size(), 4096u);
    typename ReferenceOperators<Dim>::Options options;
    options.correctedKernel = true;
    std::vector<double> f(l.X.size());
    std::vector<Tensor<Dim>> P(l.X.size());
    for (std::size_t a = 0; a < l.X.size(); ++a) {
        f[a] = std::sin(3.0 * l.X[a].sum()) + l.X[a].squaredNorm();
        P[a] = Tensor<Dim>::Constant(f[a]) + Tensor<Dim>::Identity();
    }
    const int before = omp_get_max_threads();
    auto run = [&](int threads) {
        omp_set_num_threads(threads);
        ReferenceOperators<Dim> ops(l.X, l.V, 1.3 * l.dx, *kernel, options);
        return std::make_tuple(ops.gradient(), ops.gradientAtNeighbour(), ops.laplacian(),
                               ops.correctedKernel(), ops.gradientOf(f), ops.laplacianOf(f),
                               ops.internalForce(P));
    };
    const auto one = run(1);
    const auto two = run(2);
    omp_set_num_threads(before);
    EXPECT_TRUE(one == two) << Dim << "D: results differ between 1 and 2 threads";
}

TEST(ReferenceOperators, identicalForOneAndTwoThreads) {
    compareThreadCounts<2>(70);
    compareThreadCounts<3>(17);
}

// A rank's share of a body (issue 21, TlSphSolver): its owned points, in any order, then a halo of
// the others within two supports, keyed by their serial indices (Options::order) and with only
// the owned rows and their neighbours' computed (Options::interior). Every owned row must be the
// serial row to the bit: the same neighbours in the same order, the same weights, the same
// weights at the neighbour's row (gradientAtNeighbour, the Laplacian at mirror()). A far point
// with no neighbour in the share is left alone (the whole set refuses it).
template <int Dim>
void compareShare(int n, GradientCorrection gradient) {
    const auto kernel = makeKernel("wendlandC2");
    const auto l = box<Dim>(n);
    const double h = 1.3 * l.dx, reach = 2.0 * kernel->supportRadius(h);
    typename ReferenceOperators<Dim>::Options options;
    options.gradient = gradient;
    options.correctedKernel = true;
    const ReferenceOperators<Dim> serial(l.X, l.V, h, *kernel, options);
    // Owned: x < 0.4, last index first; the halo: the rest within 2R of an owned point.
    std::vector<std::size_t> local;
    for (std::size_t a = l.X.size(); a-- > 0;)
        if (l.X[a][0] < 0.4) local.push_back(a);
    const std::size_t owned = local.size();
    for (std::size_t b = 0; b < l.X.size(); ++b) {
        if (l.X[b][0] < 0.4) continue;
        for (std::size_t k = 0; k < owned; ++k)
            if ((l.X[b] - l.X[local[k]]).norm() < reach) {
                local.push_back(b);
                break;
            }
    }
    ASSERT_LT(local.size(), l.X.size());
    std::vector<Vector<Dim>> X;
    std::vector<double> V;
    for (const std::size_t a : local) X.push_back(l.X[a]), V.push_back(l.V[a]);
    options.order.assign(local.begin(), local.end());
    options.interior = owned;
    X.push_back(Vector<Dim>::Constant(5.0)), V.push_back(l.V[0]), options.order.push_back(1000000);
    const ReferenceOperators<Dim> share(X, V, h, *kernel, options);
    const auto& rows = share.neighbours();
    const auto& serialRows = serial.neighbours();
    for (std::size_t a = 0; a < owned; ++a) {
        const std::size_t A = local[a];
        ASSERT_EQ(rows.rowSize(a), serialRows.rowSize(A)) << Dim << "D, owned " << a;
        for (std::size_t j = 0; j < rows.rowSize(a); ++j) {
            const std::size_t k = rows.offsets()[a] + j, K = serialRows.offsets()[A] + j;
            ASSERT_EQ(local[rows.indices()[k]], serialRows.indices()[K]) << Dim << "D, owned " << a;
            EXPECT_TRUE(share.gradient()[k] == serial.gradient()[K]);
            EXPECT_TRUE(share.gradientAtNeighbour()[k] == serial.gradientAtNeighbour()[K]);
            EXPECT_EQ(share.laplacian()[k], serial.laplacian()[K]);
            EXPECT_EQ(share.laplacian()[share.mirror()[k]], serial.laplacian()[serial.mirror()[K]]);
            EXPECT_EQ(share.correctedKernel()[k], serial.correctedKernel()[K]);
        }
    }
    options.interior = std::size_t(-1);
    EXPECT_THROW(ReferenceOperators<Dim>(X, V, h, *kernel, options), Error);
}

TEST(ReferenceOperators, aSharesOwnedRowsAreTheSerialRowsToTheBit) {
    compareShare<2>(20, GradientCorrection::corrected);
    compareShare<3>(17, GradientCorrection::corrected);
    compareShare<3>(17, GradientCorrection::correctedKernel);
}

TEST(ReferenceOperators, isolatedParticleIsAClearError) {
    const auto kernel = makeKernel("cubicSpline");
    auto l = box<2>(10);
    l.X.push_back(Vector<2>(5.0, 5.0));
    l.V.push_back(l.V.back());
    try {
        ReferenceOperators<2> ops(l.X, l.V, 1.3 * l.dx, *kernel, {});
        FAIL() << "an isolated particle was accepted";
    } catch (const Error& e) {
        const std::string what = e.what();
        EXPECT_NE(what.find("particle 100 "), std::string::npos) << what;
        EXPECT_NE(what.find("(5 5)"), std::string::npos) << what;
        EXPECT_NE(what.find("increase h"), std::string::npos) << what;
    }
}

TEST(ReferenceOperators, smoothingLengthTooSmallIsAClearError) {
    const auto kernel = makeKernel("wendlandC2");
    const auto l = box<3>(5);
    // Support 0.8 dx: the jittered interior particles and the face ones see nobody or one neighbour.
    for (auto correction : {GradientCorrection::corrected, GradientCorrection::correctedKernel}) {
        ReferenceOperators<3>::Options options;
        options.gradient = correction;
        EXPECT_THROW(
            {
                try {
                    ReferenceOperators<3>(l.X, l.V, 0.4 * l.dx, *kernel, options);
                } catch (const Error& e) {
                    EXPECT_NE(std::string(e.what()).find("particle 0 at X = (0 0 0)"), std::string::npos)
                        << e.what();
                    throw;
                }
            },
            Error);
    }
    // One neighbour in 2D: L_a is rank one.
    const auto k2 = makeKernel("cubicSpline");
    std::vector<Vector<2>> X{Vector<2>(0.0, 0.0), Vector<2>(1.0, 0.0)};
    try {
        ReferenceOperators<2>(X, {1.0, 1.0}, 1.0, *k2, {});
        FAIL() << "a rank-one correction matrix was accepted";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("ill-conditioned gradient correction"), std::string::npos)
            << e.what();
    }
}

TEST(ReferenceOperators, disabledOperatorsThrowAndNamesParse) {
    const auto kernel = makeKernel("cubicSpline");
    const auto l = box<2>(8);
    ReferenceOperators<2>::Options options;
    options.laplacian = false;
    const ReferenceOperators<2> ops(l.X, l.V, 1.3 * l.dx, *kernel, options);
    EXPECT_THROW(ops.laplacian(), Error);
    EXPECT_THROW(ops.correctedKernel(), Error);
    EXPECT_THROW(ops.laplacianOf(std::vector<double>(l.X.size())), Error);
    EXPECT_THROW(ops.gradientOf(std::vector<double>(3)), Error);

    const auto dict = Dictionary::parse("a corrected; b uncorrected; c correctedKernel; d corected;", "test");
    EXPECT_EQ(gradientCorrectionFromName(dict, "a"), GradientCorrection::corrected);
    EXPECT_EQ(gradientCorrectionFromName(dict, "b"), GradientCorrection::uncorrected);
    EXPECT_EQ(gradientCorrectionFromName(dict, "c"), GradientCorrection::correctedKernel);
    try {
        gradientCorrectionFromName(dict, "d");
        FAIL() << "an unknown name was accepted";
    } catch (const InputError& e) {
        const std::string what = e.what();
        EXPECT_NE(what.find("corected"), std::string::npos) << what;
        EXPECT_NE(what.find("corrected, uncorrected, correctedKernel"), std::string::npos) << what;
    }
}

}  // namespace
}  // namespace mfdyn
