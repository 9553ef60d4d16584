// The rotation part of the split (doc/methods/fpm.md §3.4): M = exp(dt W) by Rodrigues in 3D with
// the small-angle guard, the plane rotation in 2D, S <- M S M^T.
#include "fpm/RotationPart.hpp"

#include <gtest/gtest.h>
#include <Eigen/Dense>

#include <cmath>

namespace mfdyn {
namespace {

// exp(A) by its Taylor series to convergence (|A| <= 2 here: 60 terms reach round-off).
Tensor<3> seriesExponential(const Tensor<3>& A) {
    Tensor<3> sum = Tensor<3>::Identity(), term = Tensor<3>::Identity();
    for (int k = 1; k < 60; ++k) {
        term = term * A / double(k);
        sum += term;
    }
    return sum;
}

Tensor<3> skew(double w1, double w2, double w3) {
    Tensor<3> W;
    W << 0, -w3, w2, w3, 0, -w1, -w2, w1, 0;
    return W;
}

TEST(RotationPart, RodriguesEqualsTheSeriesExponentialAndIsARotation) {
    // Angles from 1e-9 (the guard) through 1e-3 (its edge, both sides) to 1.9 rad.
    for (double scale : {1e-9, 1e-5, 9.99e-4, 1.001e-3, 0.1, 1.9}) {
        const Tensor<3> W = skew(0.3, -0.5, 0.8).normalized() * std::sqrt(2.0);  // |w| = 1
        const double dt = scale;
        const Tensor<3> M = fpm::spinExponential<3>(W, dt);
        const Tensor<3> exact = seriesExponential(dt * W);
        EXPECT_LT((M - exact).cwiseAbs().maxCoeff(), 4e-16) << "theta " << scale;
        EXPECT_LT((M * M.transpose() - Tensor<3>::Identity()).cwiseAbs().maxCoeff(), 4e-16)
            << "theta " << scale;
        EXPECT_NEAR(M.determinant(), 1.0, 4e-16) << "theta " << scale;
    }
}

TEST(RotationPart, TheSymmetricPartOfTheGradientIsIgnoredAndZeroSpinIsIdentity) {
    Tensor<3> L = skew(0.2, 0.1, -0.4);
    Tensor<3> D;
    D << 1, 2, 3, 2, 5, 6, 3, 6, 9;  // symmetric: no spin
    EXPECT_LT((fpm::spinExponential<3>(L + D, 0.01) - fpm::spinExponential<3>(L, 0.01)).cwiseAbs().maxCoeff(),
              1e-16);
    EXPECT_EQ(fpm::spinExponential<3>(D, 0.01), Tensor<3>::Identity());
}

TEST(RotationPart, AxisRotationIsTheExponentialOfItsSpin) {
    // axisRotation(n, omega, dt) = exp(dt omega [n]x), the motion of x under v = omega n x x.
    const Vector<3> n = Vector<3>(1, -2, 0.5).normalized();
    const double omega = 1.7, dt = 0.3;
    const Tensor<3> W = omega * skew(n(0), n(1), n(2));
    EXPECT_LT((fpm::axisRotation(n, omega, dt) - seriesExponential(dt * W)).cwiseAbs().maxCoeff(), 1e-15);
    // about -z at omega 1: v = (x2, -x1, 0), the thesis's §6.3.1 field
    const Vector<3> x(1, 2, 3);
    const Tensor<3> Q = fpm::axisRotation(-Vector<3>::UnitZ(), 1.0, 1e-7);
    EXPECT_LT(((Q * x - x) / 1e-7 - Vector<3>(2, -1, 0)).norm(), 1e-6);
}

TEST(RotationPart, ThePlaneRotationIn2D) {
    Tensor<2> L;
    L << 0, 1, -1, 0;  // v = (x2, -x1)
    const Tensor<2> M = fpm::spinExponential<2>(L, 0.25);
    EXPECT_NEAR(M(0, 0), std::cos(0.25), 1e-16);
    EXPECT_NEAR(M(0, 1), std::sin(0.25), 1e-16);
    EXPECT_NEAR(M(1, 0), -std::sin(0.25), 1e-16);
    const Tensor<3> M3 = fpm::spinExponential<3>(skew(0, 0, -1), 0.25);
    EXPECT_LT((M3.topLeftCorner<2, 2>() - M).cwiseAbs().maxCoeff(), 1e-16);
}

TEST(RotationPart, TheThesisStressRotationToTwelveAndAHalfSeconds) {
    // §4.9: S0 = diag(10, -10, 0), W = skew of grad (x2, -x1, 0); 12500 steps of 0.001 give
    // S11 = 10 cos 2t, S21 = -10 sin 2t, the invariants kept. Measured: 1.3e-12.
    Tensor<3> L = Tensor<3>::Zero();
    L(0, 1) = 1, L(1, 0) = -1;
    SymmTensor<3> S;
    S(0, 0) = 10, S(1, 1) = -10;
    const Tensor<3> M = fpm::spinExponential<3>(L, 0.001);
    for (int k = 0; k < 12500; ++k) S = fpm::rotated(S, M);
    const double t = 12.5;
    EXPECT_NEAR(S(0, 0), 10 * std::cos(2 * t), 1e-11);
    EXPECT_NEAR(S(1, 0), -10 * std::sin(2 * t), 1e-11);
    EXPECT_NEAR(S(1, 1), -10 * std::cos(2 * t), 1e-11);
    EXPECT_EQ(S(2, 2), 0.0);
    EXPECT_EQ(S(0, 2), 0.0);
    EXPECT_NEAR(S.full().squaredNorm(), 200.0, 1e-10);
}

TEST(RotationPart, TheStepIsTheJaumannRateToFirstOrder) {
    // (M S M^T - S) / dt -> W S - S W (the note's §7 item 1: +RS - SR).
    const Tensor<3> W = skew(0.4, -0.3, 0.2);
    Tensor<3> s;
    s << 1, 2, 3, 2, -4, 5, 3, 5, 3;
    SymmTensor<3> S = SymmTensor<3>::fromFull(s);
    const double dt = 1e-7;
    const Tensor<3> rate = (fpm::rotated(S, fpm::spinExponential<3>(W, dt)).full() - s) / dt;
    EXPECT_LT((rate - (W * s - s * W)).cwiseAbs().maxCoeff(), 1e-6);
}

}  // namespace
}  // namespace mfdyn
