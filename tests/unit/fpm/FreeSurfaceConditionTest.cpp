// The free-surface conditions of fpm/FreeSurfaceCondition.hpp: the state they leave (p = p_o, S n = 0,
// S traceless with its tangential part kept) and, in the characteristic variant, the outgoing
// characteristic w_out = Z v - sigma n of each direction unchanged by them; and the traction condition on
// the total stress (sigma n = -p_o n, the tangential stress kept).
#include "fpm/FreeSurfaceCondition.hpp"

#include <gtest/gtest.h>

#include <cmath>

using namespace mfdyn;

namespace {

Vector<3> unitNormal() {
    return Vector<3>(0.3, -0.5, 0.8).normalized();
}

SymmTensor<3> someDeviator() {
    Tensor<3> t;
    t << 4.0, 1.5, -2.0, 1.5, -1.0, 0.7, -2.0, 0.7, -3.0;  // symmetric, trace 0
    return SymmTensor<3>::fromFull(t);
}

}  // namespace

TEST(FreeSurfaceCondition, PressureOverwriteLeavesTheVelocityAndDensityAlone) {
    double p = 3.0, rho = 2.0, e = 5.0;
    Vector<3> v(1.0, 2.0, 3.0);
    fpm::applySurfacePressure<3>(1.0, unitNormal(), 4.0, false, p, rho, &e, v);
    EXPECT_EQ(p, 1.0);
    EXPECT_EQ(rho, 2.0);
    EXPECT_EQ(e, 5.0);
    EXPECT_EQ(v, Vector<3>(1.0, 2.0, 3.0));
}

TEST(FreeSurfaceCondition, CharacteristicPressureKeepsTheOutgoingAndEntropyInvariants) {
    // w_out = rho c v.n - sigma_nn = rho c v.n + p (with the rho of the step: Z frozen, as the part
    // freezes its coefficients), and w1 = rho - p / c^2, unchanged while p goes to p_o; v.t unchanged
    const Vector<3> n = unitNormal();
    const double rho0 = 2.0, c = 4.0, pOuter = 1.0, e0 = 5.0;
    double p = 3.0, rho = rho0, e = e0;
    const Vector<3> v0(1.0, 2.0, 3.0);
    Vector<3> v = v0;
    const double outgoing = rho0 * c * n.dot(v0) + p, entropy = rho - p / (c * c);
    fpm::applySurfacePressure<3>(pOuter, n, c, true, p, rho, &e, v);
    EXPECT_EQ(p, pOuter);
    EXPECT_NEAR(rho0 * c * n.dot(v) + p, outgoing, 1e-14 * outgoing);
    EXPECT_NEAR(((v - v0) - n * n.dot(v - v0)).norm(), 0.0, 1e-15);
    EXPECT_NEAR(n.dot(v - v0), (3.0 - 1.0) / (rho0 * c), 1e-15);  // 0.25: outwards under overpressure
    EXPECT_NEAR(rho - p / (c * c), entropy, 1e-15);
    EXPECT_NEAR(rho, 2.0 - 2.0 / 16.0, 1e-15);
    // de = p drho / rho^2 at the means: 2 / (1.9375^2) * (-0.125)
    EXPECT_NEAR(e - e0, 2.0 / (1.9375 * 1.9375) * -0.125, 1e-15);
}

TEST(FreeSurfaceCondition, CharacteristicPressureOnAnIdealGasStaysNearItsIsentrope) {
    // p = (gamma - 1) rho e, c^2 = gamma p / rho: a step of p from 1.05 to 1 (q = dp / p = 0.05) moves
    // (rho, e) along the isentrope p / rho^gamma = const: rho's linear step misses p by O(q^2) (3.4e-4
    // here, bound q^2), the midpoint de keeps the entropy to O(q^3) (1.8e-6, bound q^3)
    const double gamma = 1.4, pOuter = 1.0;
    double rho = 1.0, e = 1.05 / ((gamma - 1.0) * rho), p = 1.05;
    const double entropyBefore = p / std::pow(rho, gamma);
    Vector<2> v = Vector<2>::Zero();
    fpm::applySurfacePressure<2>(pOuter, Vector<2>(0.0, 1.0), std::sqrt(gamma * p / rho), true, p, rho, &e,
                                 v);
    const double pFromState = (gamma - 1.0) * rho * e;
    const double q = 0.05;
    EXPECT_NEAR(pFromState, pOuter, q * q * pOuter);
    EXPECT_NEAR(pFromState / std::pow(rho, gamma), entropyBefore, q * q * q * entropyBefore);
}

TEST(FreeSurfaceCondition, TractionProjectionIsTracelessWithZeroTractionAndKeepsTheTangentialPart) {
    const Vector<3> n = unitNormal();
    SymmTensor<3> S = someDeviator();
    const Tensor<3> before = S.full();
    Vector<3> v(0.5, 0.0, -0.5);
    fpm::applySurfaceTraction<3>(n, 50.0, 1.2, false, S, v);
    const Tensor<3> after = S.full();
    EXPECT_NEAR((after * n).norm(), 0.0, 1e-14);
    EXPECT_NEAR(after.trace(), 0.0, 1e-14);
    EXPECT_EQ(v, Vector<3>(0.5, 0.0, -0.5));
    // the tangential-tangential part is the old one less its trace spread over the plane
    const Tensor<3> P = Tensor<3>::Identity() - n * n.transpose();
    const Tensor<3> tangential = P * before * P;
    EXPECT_NEAR((after - (tangential - tangential.trace() / 2.0 * P)).norm(), 0.0, 1e-14);
}

TEST(FreeSurfaceCondition, CharacteristicTractionKeepsTheOutgoingInvariantOfEachDirection) {
    const Vector<3> n = unitNormal();
    const double mu = 50.0, rho = 1.2;
    const double zShear = std::sqrt(mu * rho), zNormal = std::sqrt(4.0 / 3.0 * mu * rho);
    SymmTensor<3> S = someDeviator();
    const Vector<3> traction = S.full() * n;
    const Vector<3> v0(0.5, 0.0, -0.5);
    Vector<3> v = v0;
    fpm::applySurfaceTraction<3>(n, mu, rho, true, S, v);
    const Tensor<3> P = Tensor<3>::Identity() - n * n.transpose();
    const Vector<3> tractionAfter = S.full() * n;
    // along the surface: Z_s P v - P sigma n; along n: Z_n v.n - n.sigma n (the shear part's sigma = S)
    EXPECT_NEAR((zShear * P * v - P * tractionAfter - (zShear * P * v0 - P * traction)).norm(), 0.0, 1e-13);
    EXPECT_NEAR(zNormal * n.dot(v) - n.dot(tractionAfter) - (zNormal * n.dot(v0) - n.dot(traction)), 0.0,
                1e-13);
    EXPECT_GT((v - v0).norm(), 0.1);  // a real correction: |S n| / Z is about 0.5 here
}

TEST(FreeSurfaceCondition, TwoDimensionalNormalImpedanceIsSqrtMuRho) {
    // in 2D S_nn' = 2 mu (1 - 1/2) dv_n/dn = mu dv_n/dn: both directions at sqrt(mu rho)
    const Vector<2> n(1.0, 0.0);
    SymmTensor<2> S;
    S(0, 0) = 2.0;
    S(1, 1) = -2.0;
    S(0, 1) = 1.0;
    Vector<2> v = Vector<2>::Zero();
    fpm::applySurfaceTraction<2>(n, 4.0, 1.0, true, S, v);
    EXPECT_NEAR(v(0), -2.0 / 2.0, 1e-15);
    EXPECT_NEAR(v(1), -1.0 / 2.0, 1e-15);
    EXPECT_NEAR(S(0, 0), 0.0, 1e-15);
    EXPECT_NEAR(S(0, 1), 0.0, 1e-15);
    EXPECT_NEAR(S(1, 1), 0.0, 1e-15);  // traceless with S n = 0: nothing left in 2D
}

TEST(FreeSurfaceCondition, TotalStressTractionKeepsTheTangentialStress3D) {
    // sigma n = -p_o n after, sigma's tangential block P sigma P unchanged, S traceless, p = -tr sigma / 3
    const Vector<3> n = unitNormal();
    const double pOuter = 0.7;
    SymmTensor<3> S = someDeviator();
    double p = 2.5, rho = 1.2;
    const Tensor<3> I = Tensor<3>::Identity(), P = I - n * n.transpose();
    const Tensor<3> sigmaBefore = S.full() - p * I;
    Vector<3> v(0.5, 0.0, -0.5);
    fpm::applySurfaceStress<3>(pOuter, n, 1.0 / 3.0, 50.0, 4.0, false, p, S, rho, nullptr, v);
    const Tensor<3> sigma = S.full() - p * I;
    EXPECT_NEAR((sigma * n + pOuter * n).norm(), 0.0, 1e-14);
    EXPECT_NEAR((P * sigma * P - P * sigmaBefore * P).norm(), 0.0, 1e-14);
    EXPECT_NEAR(S.full().trace(), 0.0, 1e-14);
    EXPECT_NEAR(p, -sigma.trace() / 3.0, 1e-14);
    EXPECT_EQ(v, Vector<3>(0.5, 0.0, -0.5));
    EXPECT_EQ(rho, 1.2);
}

TEST(FreeSurfaceCondition, TotalStressTractionInPlaneStrainKeepsSigmaZ) {
    // deviator three in 2D: S_zz = -tr S, sigma_zz = -p + S_zz is tangential to the surface and kept;
    // a plate's top surface (n = y) keeps its bending stress sigma_xx
    const Vector<2> n(0.0, 1.0);
    SymmTensor<2> S;
    S(0, 0) = 3.0;
    S(1, 1) = 0.5;
    S(0, 1) = 1.0;
    double p = -1.0, rho = 1000.0;
    const double sigmaXX = S(0, 0) - p, sigmaZZ = -(S(0, 0) + S(1, 1)) - p;
    Vector<2> v = Vector<2>::Zero();
    fpm::applySurfaceStress<2>(0.0, n, 1.0 / 3.0, 7e5, 57.0, false, p, S, rho, nullptr, v);
    EXPECT_NEAR(S(0, 0) - p, sigmaXX, 1e-13);
    EXPECT_NEAR(-(S(0, 0) + S(1, 1)) - p, sigmaZZ, 1e-13);
    EXPECT_NEAR(S(1, 1) - p, 0.0, 1e-13);
    EXPECT_NEAR(S(0, 1), 0.0, 1e-15);
    EXPECT_NEAR(p, -(sigmaXX + sigmaZZ) / 3.0, 1e-13);
}

TEST(FreeSurfaceCondition, CharacteristicTotalStressKeepsTheFullSystemsInvariants) {
    // w_out = Z v - sigma n with Z = rho c_L along n (rho c_L^2 = rho c^2 + 4/3 mu in 3D) and
    // sqrt(mu rho) along the surface; the entropy wave rho - p / c^2 kept
    const Vector<3> n = unitNormal();
    const double mu = 50.0, c = 4.0, pOuter = 0.3;
    SymmTensor<3> S = someDeviator();
    double p = 2.5, rho = 1.2;
    const double rho0 = rho, p0 = p;
    const double zNormal = std::sqrt(rho * (rho * c * c + 4.0 / 3.0 * mu)), zShear = std::sqrt(mu * rho);
    const Tensor<3> I = Tensor<3>::Identity(), P = I - n * n.transpose();
    const Vector<3> tractionBefore = (S.full() - p * I) * n;
    const Vector<3> v0(0.5, 0.0, -0.5);
    Vector<3> v = v0;
    fpm::applySurfaceStress<3>(pOuter, n, 1.0 / 3.0, mu, c, true, p, S, rho, nullptr, v);
    const Vector<3> traction = (S.full() - p * I) * n;
    EXPECT_NEAR(zNormal * n.dot(v) - n.dot(traction) - (zNormal * n.dot(v0) - n.dot(tractionBefore)), 0.0,
                1e-13);
    EXPECT_NEAR((zShear * P * v - P * traction - (zShear * P * v0 - P * tractionBefore)).norm(), 0.0, 1e-13);
    EXPECT_NEAR(rho - p / (c * c), rho0 - p0 / (c * c), 1e-14);
    EXPECT_GT((v - v0).norm(), 0.1);
}

TEST(FreeSurfaceCondition, TotalStressWithoutShearStiffnessIsThePressureCondition) {
    const Vector<3> n = unitNormal();
    SymmTensor<3> S{};
    double p = 2.5, rho = 1.2, pRef = 2.5, rhoRef = 1.2;
    Vector<3> v(0.5, 0.0, -0.5), vRef = v;
    fpm::applySurfaceStress<3>(0.3, n, 1.0 / 3.0, 0.0, 4.0, true, p, S, rho, nullptr, v);
    fpm::applySurfacePressure<3>(0.3, n, 4.0, true, pRef, rhoRef, nullptr, vRef);
    EXPECT_EQ(p, pRef);
    EXPECT_EQ(rho, rhoRef);
    EXPECT_EQ(v, vRef);
}
