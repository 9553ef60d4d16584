// The two laws of the material point method's thesis (doc/methods/mpm.md section 1, test U3):
// stVenantKirchhoff and neoHookeanLogJ. Closed forms of uniaxial strain F = diag(f, 1, 1) with
// E = 1e5, nu = 0.3 (mu = 38461.54, lambda = 57692.31), the 1D forms of the note (nu = 0),
// plane-strain sigma_zz from P, the Cauchy stress of the thesis's eq. 47, and the mixed
// formulations' J. (P = dW/dF, P(I) = 0, objectivity and small strain are the contract tests of
// ConstitutiveLawTest.cpp, which list both laws.)
#include "materials/constitutive/ConstitutiveLaw.hpp"

#include <gtest/gtest.h>

#include <Eigen/LU>

#include <cmath>
#include <random>
#include <string>

namespace mfdyn {
namespace {

std::unique_ptr<ConstitutiveLaw> law(const std::string& type, const std::string& constants) {
    const Dictionary d =
        Dictionary::parse("solid { " + constants + " constitutiveLaw { type " + type + "; } }", "test");
    return ConstitutiveLaw::New(d.subDict("solid").subDict("constitutiveLaw"));
}

const std::string block = "rho0 1500; youngsModulus 1e5; poissonRatio 0.3;";
const std::string bar = "rho0 1500; youngsModulus 1e5; poissonRatio 0;";  // the spring, lambda = 0

struct Result {
    Tensor<3> P;
    double pressure = 0, energy = 0;
};

// F with H = cof F and J = det F unless `J` is given (a mixed formulation's independent J).
Result evaluate(const ConstitutiveLaw& l, const Tensor<3>& F, double J = 0) {
    Result r;
    const Tensor<3> H = cofactor(F);
    const double j = J > 0 ? J : F.determinant();
    ConstitutiveLaw::Fields f;
    f.size = 1, f.F = &F, f.H = &H, f.J = &j, f.P = &r.P, f.pressure = &r.pressure,
    f.energyDensity = &r.energy;
    l.stress(f, false);
    return r;
}

Tensor<3> cauchy(const Tensor<3>& P, const Tensor<3>& F) {
    return P * F.transpose() / F.determinant();
}

Tensor<3> stretch(double f) {
    Tensor<3> F = Tensor<3>::Identity();
    F(0, 0) = f;
    return F;
}

// Uniaxial strain f = 1.2: E11 = 0.22, S11 = (lambda + 2 mu) E11, S22 = S33 = lambda E11,
// P11 = f S11, W = (lambda/2 + mu) E11^2; p = kappa E11 (kappa = 83333.33).
TEST(MpmLaws, StVenantKirchhoffUniaxialStrain) {
    const auto stvk = law("stVenantKirchhoff", block);
    const Result r = evaluate(*stvk, stretch(1.2));
    // Closed forms above, evaluated in double precision by hand (python): relative 1e-12.
    EXPECT_NEAR(r.P(0, 0), 35538.461538461524, 1e-12 * 35538.46);
    EXPECT_NEAR(r.P(1, 1), 12692.307692307688, 1e-12 * 12692.31);
    EXPECT_NEAR(r.P(2, 2), 12692.307692307688, 1e-12 * 12692.31);
    EXPECT_NEAR(r.P(0, 1), 0.0, 1e-12 * 35538.46);
    EXPECT_NEAR(r.energy, 3257.6923076923067, 1e-12 * 3257.69);
    EXPECT_NEAR(r.pressure, 1e5 / (3 * (1 - 0.6)) * 0.22, 1e-12 * 18333.3);
    const Tensor<3> s = cauchy(r.P, stretch(1.2));
    EXPECT_NEAR(s(1, 1), 10576.923076923074, 1e-12 * 10576.9);  // lambda E11 / f
}

// sigma = mu/J (B - I) + lambda ln J / J I with J = f: sigma22 = lambda ln f / f, P11 = sigma11,
// P22 = J sigma22 = lambda ln f, W = mu/2 (f^2 - 1) - mu ln f + lambda/2 (ln f)^2.
TEST(MpmLaws, NeoHookeanLogJUniaxialStrain) {
    const auto nh = law("neoHookeanLogJ", block);
    const Result r = evaluate(*nh, stretch(1.2));
    EXPECT_NEAR(r.P(0, 0), 22868.023563811916, 1e-12 * 22868.0);
    EXPECT_NEAR(r.P(1, 1), 10518.551353497378, 1e-12 * 10518.6);
    EXPECT_NEAR(r.P(2, 2), 10518.551353497378, 1e-12 * 10518.6);
    EXPECT_NEAR(r.energy, 2408.0502215336073, 1e-12 * 2408.05);
    EXPECT_NEAR(r.pressure, 8765.459461247816, 1e-12 * 8765.46);  // lambda ln J / J
    const Tensor<3> s = cauchy(r.P, stretch(1.2));
    EXPECT_NEAR(s(1, 1), 8765.459461247816, 1e-12 * 8765.46);
}

// The note's 1D forms (section 4.1, nu = 0, lambda = 0): StVK P = E f (f^2 - 1)/2, with its
// compressive extreme -E/(3 sqrt 3) = -0.19245 E at f = 1/sqrt 3; neo-Hookean P = (E/2)(f^2 - 1)/f.
TEST(MpmLaws, OneDimensionalFormsOfTheNote) {
    const auto stvk = law("stVenantKirchhoff", bar), nh = law("neoHookeanLogJ", bar);
    for (double f : {0.3, 1.0 / std::sqrt(3.0), 0.9, 1.0294, 1.5}) {
        EXPECT_NEAR(evaluate(*stvk, stretch(f)).P(0, 0), 1e5 * f * (f * f - 1) / 2, 1e-10) << f;
        EXPECT_NEAR(evaluate(*nh, stretch(f)).P(0, 0), 0.5e5 * (f * f - 1) / f, 1e-10) << f;
        // No lateral stress without lambda.
        EXPECT_NEAR(evaluate(*stvk, stretch(f)).P(1, 1), 0.0, 1e-10) << f;
        EXPECT_NEAR(evaluate(*nh, stretch(f)).P(1, 1), 0.0, 1e-10) << f;
    }
    const double extreme = evaluate(*stvk, stretch(1.0 / std::sqrt(3.0))).P(0, 0);
    EXPECT_NEAR(extreme, -0.19245008972987526e5, 1e-9);
    // ... and it is an extreme: the tangent vanishes there (softening in compression).
    const double h = 1e-5, fs = 1.0 / std::sqrt(3.0);
    EXPECT_NEAR(evaluate(*stvk, stretch(fs + h)).P(0, 0), evaluate(*stvk, stretch(fs - h)).P(0, 0), 1e-4);
}

// Plane strain (F33 = 1): sigma = P F^T / J has sigma_zz = lambda tr E / J (StVK) and
// lambda ln J / J (neo-Hookean), and sigma is the thesis's eq. 47 / J^-1 F S F^T.
TEST(MpmLaws, PlaneStrainOutOfPlaneStress) {
    const auto stvk = law("stVenantKirchhoff", block), nh = law("neoHookeanLogJ", block);
    const double lambda = stvk->lameLambda(), mu = stvk->shearModulus();
    EXPECT_NEAR(lambda, 57692.30769230768, 1e-9);
    std::mt19937 rng(23);
    std::uniform_real_distribution<double> u(-0.25, 0.25);
    for (int trial = 0; trial < 10; ++trial) {
        Tensor<3> F = Tensor<3>::Identity();
        for (int i = 0; i < 2; ++i)
            for (int j = 0; j < 2; ++j) F(i, j) += u(rng);
        const double J = F.determinant();
        const Tensor<3> E = 0.5 * (F.transpose() * F - Tensor<3>::Identity());
        const Tensor<3> a = cauchy(evaluate(*stvk, F).P, F), b = cauchy(evaluate(*nh, F).P, F);
        const double scale = 1e-12 * (lambda + mu);
        EXPECT_NEAR(a(2, 2), lambda * E.trace() / J, scale) << F;
        EXPECT_NEAR(b(2, 2), lambda * std::log(J) / J, scale) << F;
        EXPECT_NEAR(a(0, 2), 0.0, scale);
        EXPECT_NEAR(b(1, 2), 0.0, scale);
        // The whole tensor against the thesis's formulas.
        const Tensor<3> S = lambda * E.trace() * Tensor<3>::Identity() + 2 * mu * E;
        EXPECT_LT((a - F * S * F.transpose() / J).norm(), scale);
        const Tensor<3> nhSigma = mu / J * (F * F.transpose() - Tensor<3>::Identity()) +
                                  lambda * std::log(J) / J * Tensor<3>::Identity();
        EXPECT_LT((b - nhSigma).norm(), scale);
        // Symmetric Cauchy stress (angular momentum).
        EXPECT_LT((a - a.transpose()).norm(), scale);
        EXPECT_LT((b - b.transpose()).norm(), scale);
    }
}

// Not neoHookean's energy: the same at small strain, 4.765e4 against 5.797e4 (P11) at f = 1.5.
TEST(MpmLaws, NeoHookeanLogJIsNotNeoHookean) {
    const auto logJ = law("neoHookeanLogJ", block), iso = law("neoHookean", block);
    EXPECT_NEAR(evaluate(*logJ, stretch(1.5)).P(0, 0), 47646.09390159606, 1e-8);
    EXPECT_NEAR(evaluate(*iso, stretch(1.5)).P(0, 0), 57973.137358309556, 1e-8);
    const double small = 1 + 1e-6;
    EXPECT_NEAR(evaluate(*logJ, stretch(small)).P(0, 0), evaluate(*iso, stretch(small)).P(0, 0), 1e-6);
}

// Mixed formulations (ConstitutiveLaw.hpp): neoHookeanLogJ puts the supplied J in its volumetric
// part, P = mu (F - F^-T) + lambda ln J / J H, p = lambda ln J / J, so that
// P(J1) - P(J0) = (p(J1) - p(J0)) H (tlSph's {p,F,J} evaluates it as it is). stVenantKirchhoff's
// W is F's alone: the supplied J and H change nothing.
TEST(MpmLaws, MixedFormulationsJacobian) {
    const auto stvk = law("stVenantKirchhoff", block), nh = law("neoHookeanLogJ", block);
    Tensor<3> F = Tensor<3>::Identity();
    F(0, 0) = 1.05, F(1, 1) = 0.97, F(0, 1) = 0.03;
    const double detF = F.determinant(), J1 = 1.02 * detF;
    const Result a = evaluate(*nh, F), b = evaluate(*nh, F, J1);
    const double lambda = nh->lameLambda();
    EXPECT_NEAR(b.pressure, lambda * std::log(J1) / J1, 1e-10);
    EXPECT_LT((b.P - a.P - (b.pressure - a.pressure) * cofactor(F)).norm(), 1e-10 * a.P.norm());
    // The energy's volumetric part moves with J: W(J1) - W(detF) = lambda/2 (ln^2 J1 - ln^2 detF).
    EXPECT_NEAR(b.energy - a.energy,
                0.5 * lambda * (std::log(J1) * std::log(J1) - std::log(detF) * std::log(detF)), 1e-9);
    const Result c = evaluate(*stvk, F), d = evaluate(*stvk, F, J1);
    EXPECT_EQ((c.P - d.P).norm(), 0.0);
    EXPECT_EQ(c.pressure, d.pressure);
    EXPECT_EQ(c.energy, d.energy);
}

}  // namespace
}  // namespace mfdyn
