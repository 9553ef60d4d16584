// The swinging cube's exact solution (Lee et al. 2016 eq. 52) checked against its own PDE and
// boundary conditions by finite differences, in 1, 2 and 3 dimensions.
#include "verification/SwingingCube.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

using namespace mfdyn;

namespace {

// The paper's cube: rho0 = 1100, E = 17 MPa, nu = 0.3, U0 = 5e-4 m.
template <int Dim>
SwingingCube<Dim> paperCube() {
    return SwingingCube<Dim>(1100.0, 17e6, 0.3, 5e-4);
}

template <int Dim>
Vector<Dim> randomPoint(std::mt19937& rng) {
    std::uniform_real_distribution<double> u(0.0, 1.0);
    Vector<Dim> X;
    for (int k = 0; k < Dim; ++k) X(k) = u(rng);
    return X;
}

template <class T>
class SwingingCubeTest : public ::testing::Test {};
using Dims = ::testing::Types<std::integral_constant<int, 1>, std::integral_constant<int, 2>,
                              std::integral_constant<int, 3>>;
TYPED_TEST_SUITE(SwingingCubeTest, Dims);

}  // namespace

// omega = sqrt(3)/2 c_d pi in 3D: the note's c_d = 144.2 m/s, omega = 392.4 rad/s, T = 16.01 ms.
TEST(SwingingCube, paperFrequencyIn3D) {
    const auto cube = paperCube<3>();
    EXPECT_NEAR(cube.waveSpeed(), 144.2, 0.05);
    EXPECT_NEAR(cube.angularFrequency(), 392.4, 0.05);
    EXPECT_NEAR(cube.period(), 16.01e-3, 0.005e-3);
    // In Dim dimensions the frequency scales as sqrt(Dim) (Laplacian eigenvalue -Dim (pi/2)^2).
    EXPECT_NEAR(paperCube<2>().angularFrequency(), 392.4 * std::sqrt(2.0 / 3.0), 0.05);
    EXPECT_NEAR(paperCube<1>().angularFrequency(), 392.4 / std::sqrt(3.0), 0.05);
}

// rho0 u_tt = DIV P, with u_tt from central differences of v in time and DIV P from central
// differences of P in space (step 1e-4 m: truncation ~1e-8 relative, round-off ~1e-8).
TYPED_TEST(SwingingCubeTest, satisfiesMomentumBalance) {
    constexpr int Dim = TypeParam::value;
    const auto cube = paperCube<Dim>();
    const double rho0 = 1100.0;
    std::mt19937 rng(7);
    const double h = 1e-4, dt = 1e-4 * cube.period();
    double worst = 0, scale = 0;
    for (int trial = 0; trial < 50; ++trial) {
        Vector<Dim> X = randomPoint<Dim>(rng);
        for (int k = 0; k < Dim; ++k) X(k) = 0.01 + 0.98 * X(k);
        const double t = std::uniform_real_distribution<double>(0, cube.period())(rng);
        const Vector<Dim> accel = (cube.velocity(X, t + dt) - cube.velocity(X, t - dt)) / (2 * dt);
        Vector<Dim> divP = Vector<Dim>::Zero();
        for (int J = 0; J < Dim; ++J) {
            Vector<Dim> e = Vector<Dim>::Zero();
            e(J) = h;
            divP +=
                (cube.firstPiolaStress(X + e, t).col(J) - cube.firstPiolaStress(X - e, t).col(J)) / (2 * h);
        }
        worst = std::max(worst, (rho0 * accel - divP).norm());
        scale = std::max(scale, divP.norm());
    }
    ASSERT_GT(scale, 0.0);
    EXPECT_LT(worst / scale, 1e-6) << "largest |rho0 u_tt - DIV P| / |DIV P| over 50 points";
}

// v = du/dt, grad u = du/dX, F = I + grad u, P from the linear elastic law, p = rho0 v.
TYPED_TEST(SwingingCubeTest, fieldsAreConsistent) {
    constexpr int Dim = TypeParam::value;
    const auto cube = paperCube<Dim>();
    std::mt19937 rng(11);
    const double h = 1e-5, dt = 1e-5 * cube.period(), U0 = 5e-4;
    for (int trial = 0; trial < 20; ++trial) {
        const Vector<Dim> X = randomPoint<Dim>(rng);
        const double t = std::uniform_real_distribution<double>(0, cube.period())(rng);
        const Vector<Dim> v = (cube.displacement(X, t + dt) - cube.displacement(X, t - dt)) / (2 * dt);
        EXPECT_LT((v - cube.velocity(X, t)).norm(), 1e-6 * U0 * cube.angularFrequency());
        EXPECT_LT((1100.0 * cube.velocity(X, t) - cube.momentum(X, t)).norm(), 1e-9);
        Tensor<Dim> grad;
        for (int J = 0; J < Dim; ++J) {
            Vector<Dim> e = Vector<Dim>::Zero();
            e(J) = h;
            grad.col(J) = (cube.displacement(X + e, t) - cube.displacement(X - e, t)) / (2 * h);
        }
        EXPECT_LT((grad - cube.displacementGradient(X, t)).norm(), 1e-6 * U0);
        EXPECT_LT((cube.deformationGradient(X, t) - Tensor<Dim>::Identity() - grad).norm(), 1e-6 * U0);
        const Tensor<Dim> P =
            cube.lambda() * grad.trace() * Tensor<Dim>::Identity() + cube.mu() * (grad + grad.transpose());
        EXPECT_LT((P - cube.firstPiolaStress(X, t)).norm(), 1e-6 * U0 * cube.lambda());
    }
    // At t = 0 the displacement is the mode shape, at full amplitude at the corner (1, 0, 0...).
    Vector<Dim> corner = Vector<Dim>::Zero();
    corner(0) = 1;
    EXPECT_NEAR(cube.displacement(corner, 0)(0), U0, 1e-15);
    EXPECT_EQ(SwingingCube<Dim>::modeShape(corner, U0), cube.displacement(corner, 0));
}

// Rollers on X_k = 0 (u_k = 0), skew-symmetric conditions on X_k = 1 (u_j = 0 for j != k).
TYPED_TEST(SwingingCubeTest, satisfiesBoundaryConditions) {
    constexpr int Dim = TypeParam::value;
    const auto cube = paperCube<Dim>();
    std::mt19937 rng(3);
    const double U0 = 5e-4;
    for (int trial = 0; trial < 50; ++trial) {
        const double t = std::uniform_real_distribution<double>(0, cube.period())(rng);
        for (int k = 0; k < Dim; ++k) {
            Vector<Dim> X = randomPoint<Dim>(rng);
            X(k) = 0;
            EXPECT_LT(std::abs(cube.displacement(X, t)(k)), 1e-6 * U0);
            EXPECT_LT(std::abs(cube.velocity(X, t)(k)), 1e-6 * U0 * cube.angularFrequency());
            X(k) = 1;
            for (int j = 0; j < Dim; ++j) {
                if (j != k) {
                    EXPECT_LT(std::abs(cube.displacement(X, t)(j)), 1e-6 * U0);
                }
            }
        }
    }
}

TEST(SwingingCube, rejectsBadParameters) {
    EXPECT_THROW(SwingingCube<3>(0.0, 17e6, 0.3, 5e-4), std::exception);
    EXPECT_THROW(SwingingCube<3>(1100.0, 17e6, 0.5, 5e-4), std::exception);
}
