// The constitutiveLaw family: tensor cross product identities; for every law P = dW/dF, linear
// elasticity at small strain, objectivity, P(I) = 0; the mixed {p,F,J} pressure; finite-strain J2
// plasticity on an isochoric stretch (consistency, hardening, plastic incompressibility, read-only
// stages); the elastic constants and keyword errors; the p-wave speed of Lee et al. 2016.
#include "materials/constitutive/ConstitutiveLaw.hpp"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <Eigen/LU>

#include <cmath>
#include <random>
#include <string>
#include <vector>

namespace mfdyn {
namespace {

std::unique_ptr<ConstitutiveLaw> make(const std::string& text) {
    return ConstitutiveLaw::New(Dictionary::parse(text, "test"));
}

// The laws as a user writes them, inside a material dictionary (rubber of Lee et al. 2016, s. 8.7).
std::unique_ptr<ConstitutiveLaw> inMaterial(const std::string& material, const std::string& law) {
    const Dictionary materials =
        Dictionary::parse("rubber { " + material + " constitutiveLaw { " + law + " } }", "test");
    return ConstitutiveLaw::New(materials.subDict("rubber").subDict("constitutiveLaw"));
}

const std::string rubber = "rho0 1100; youngsModulus 17e6; poissonRatio 0.45;";
constexpr double rubberMu = 17e6 / 2.9, rubberKappa = 17e6 / 0.3;

// One particle with every field; H and J follow F unless set independently.
struct Particle {
    explicit Particle(const Tensor<3>& f) { setF(f); }
    void setF(const Tensor<3>& f) {
        F = f;
        H = cofactor(f);
        J = f.determinant();
    }
    ConstitutiveLaw::Fields fields() {
        ConstitutiveLaw::Fields r;
        r.size = 1;
        r.F = &F;
        r.H = &H;
        r.J = &J;
        r.P = &P;
        r.pressure = &pressure;
        r.energyDensity = &energy;
        r.plasticState = &cpInv;
        r.plasticStrain = &epsP;
        return r;
    }
    Tensor<3> F, H, P = Tensor<3>::Zero();
    double J = 1.0, pressure = 0.0, energy = 0.0, epsP = 0.0;
    SymmTensor<3> cpInv = SymmTensor<3>::fromFull(Tensor<3>::Identity());
};

Tensor<3> stressOf(const ConstitutiveLaw& law, const Tensor<3>& f) {
    Particle p(f);
    law.stress(p.fields(), false);
    return p.P;
}

double energyOf(const ConstitutiveLaw& law, const Tensor<3>& f) {
    Particle p(f);
    law.stress(p.fields(), false);
    return p.energy;
}

// A random F with det F in (0.7, 1.4): I plus a perturbation of size 0.3.
Tensor<3> randomF(std::mt19937& rng) {
    std::uniform_real_distribution<double> u(-0.15, 0.15);
    for (;;) {
        Tensor<3> f = Tensor<3>::Identity();
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j) f(i, j) += u(rng);
        const double det = f.determinant();
        if (det > 0.7 && det < 1.4) return f;
    }
}

Tensor<3> rotation(double angle, Vector<3> axis) {
    return Eigen::AngleAxisd(angle, axis.normalized()).toRotationMatrix();
}

struct Sample {
    std::string name;
    std::string material, law;
    bool objective = true;
};

// Every law; j2Plasticity with a yield stress far above the stresses reached is hyperelastic.
std::vector<Sample> hyperelastic() {
    return {
        {"linearElastic", rubber, "type linearElastic;", false},
        {"neoHookean", rubber, "type neoHookean;"},
        {"stVenantKirchhoff", rubber, "type stVenantKirchhoff;"},
        {"neoHookeanLogJ", rubber, "type neoHookeanLogJ;"},
        {"mooneyRivlin", rubber, "type mooneyRivlin; zeta 2e6;"},
        {"mooneyRivlinHDominated", rubber, "type mooneyRivlin; hDominated yes;"},
        {"mooneyRivlinOwnConstants", "rho0 1100;", "type mooneyRivlin; zeta 1.5e6; xi 0.4e6; kappa 5e7;"},
        {"j2PlasticityElastic", rubber + " yieldStress 1e12;", "type j2Plasticity;"},
    };
}

// ---- tensor cross product ------------------------------------------------------------------

TEST(ConstitutiveTensorCross, IdentitiesOfTheCofactor) {
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    for (int trial = 0; trial < 20; ++trial) {
        Tensor<3> a, b, f = randomF(rng);
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j) a(i, j) = u(rng), b(i, j) = u(rng);
        // Entries are O(1), products of four: rounding a few 1e-16.
        EXPECT_LT((tensorCross(a, b) - tensorCross(b, a)).norm(), 1e-13);
        const Tensor<3> cof = f.determinant() * f.inverse().transpose();
        EXPECT_LT((0.5 * tensorCross(f, f) - cof).norm(), 1e-13);
        EXPECT_LT((cofactor(f) - cof).norm(), 1e-13);
        EXPECT_NEAR((tensorCross(f, f).cwiseProduct(f)).sum(), 6.0 * f.determinant(), 1e-13);
        // Bilinear, and I x A = tr(A) I - A^T (Bonet, Gil & Ortigosa 2015, Eq. 8).
        EXPECT_LT((tensorCross(a + 2.0 * b, f) - tensorCross(a, f) - 2.0 * tensorCross(b, f)).norm(), 1e-13);
        EXPECT_LT(
            (tensorCross(Tensor<3>::Identity(), a) - (a.trace() * Tensor<3>::Identity() - a.transpose()))
                .norm(),
            1e-13);
    }
}

// ---- every law -----------------------------------------------------------------------------

TEST(ConstitutiveLawContract, StressIsTheDerivativeOfTheEnergy) {
    std::mt19937 rng(11);
    for (const auto& s : hyperelastic()) {
        const auto law = inMaterial(s.material, s.law);
        for (int trial = 0; trial < 5; ++trial) {
            const Tensor<3> f = randomF(rng);
            const Tensor<3> p = stressOf(*law, f);
            // Central differences: truncation h^2 W''' ~ 1e-12 mu, rounding 1e-16 W/h ~ 1e-10 mu,
            // against |P| ~ 0.1 mu (measured 1e-10 to 3e-9).
            const double h = 1e-6;
            Tensor<3> fd;
            for (int i = 0; i < 3; ++i)
                for (int j = 0; j < 3; ++j) {
                    Tensor<3> plus = f, minus = f;
                    plus(i, j) += h;
                    minus(i, j) -= h;
                    fd(i, j) = (energyOf(*law, plus) - energyOf(*law, minus)) / (2.0 * h);
                }
            EXPECT_LT((fd - p).norm(), 1e-6 * p.norm()) << s.name << "\nP\n" << p << "\ndW/dF\n" << fd;
        }
    }
}

TEST(ConstitutiveLawContract, SmallStrainIsLinearElasticity) {
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    for (const auto& s : hyperelastic()) {
        const auto law = inMaterial(s.material, s.law);
        const double mu = law->shearModulus(), lambda = law->lameLambda();
        Tensor<3> grad;
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j) grad(i, j) = u(rng);
        const double eps = 1e-7;
        const Tensor<3> e = 0.5 * eps * (grad + grad.transpose());
        const Tensor<3> linear = lambda * e.trace() * Tensor<3>::Identity() + 2.0 * mu * e;
        const Tensor<3> p = stressOf(*law, Tensor<3>::Identity() + eps * grad);
        // Second-order terms, O(kappa eps^2) against O(mu eps): ~1e-6 with kappa/mu = 10 (measured
        // 5e-7 to 9e-7); rounding of the cancelling O(mu) terms ~1e-9.
        EXPECT_LT((p - linear).norm(), 1e-5 * linear.norm()) << s.name;
        EXPECT_LT(stressOf(*law, Tensor<3>::Identity()).norm(), 1e-9 * mu) << s.name;
    }
}

TEST(ConstitutiveLawContract, StressFreeReferenceState) {
    for (const auto& s : hyperelastic()) {
        const auto law = inMaterial(s.material, s.law);
        Particle p(Tensor<3>::Identity());
        law->stress(p.fields(), true);
        // O(mu) terms cancel: rounding only.
        EXPECT_LT(p.P.norm(), 1e-15 * 64 * law->bulkModulus()) << s.name;
        EXPECT_EQ(p.pressure, 0.0) << s.name;
        EXPECT_LT(std::abs(p.energy), 1e-15 * 64 * law->bulkModulus()) << s.name;
    }
}

TEST(ConstitutiveLawContract, Objectivity) {
    std::mt19937 rng(5);
    auto samples = hyperelastic();
    samples.push_back(
        {"j2PlasticityYielding", rubber + " yieldStress 1e6;", "type j2Plasticity; hardeningModulus 1e6;"});
    for (const auto& s : samples) {
        if (!s.objective) continue;
        const auto law = inMaterial(s.material, s.law);
        for (int trial = 0; trial < 5; ++trial) {
            const Tensor<3> f = randomF(rng);
            const Tensor<3> q = rotation(0.3 + trial, Vector<3>(1.0, 2.0 - trial, 0.5));
            const Tensor<3> p = stressOf(*law, f), pq = stressOf(*law, q * f);
            EXPECT_LT((pq - q * p).norm(), 1e-12 * p.norm()) << s.name;
            EXPECT_NEAR(energyOf(*law, q * f), energyOf(*law, f), 1e-12 * law->bulkModulus()) << s.name;
        }
    }
    // linearElastic is not: a rotation alone stresses it.
    const auto linear = inMaterial(rubber, "type linearElastic;");
    EXPECT_GT(stressOf(*linear, rotation(0.1, Vector<3>(0, 0, 1))).norm(), 1e-3 * rubberMu);
}

// ---- mixed formulations --------------------------------------------------------------------

TEST(ConstitutiveMixed, IndependentJacobianSetsThePressure) {
    const auto law = inMaterial(rubber, "type neoHookean;");
    std::mt19937 rng(13);
    Particle p(randomF(rng));
    p.J = 0.97 * p.F.determinant();
    law->stress(p.fields(), false);
    EXPECT_EQ(p.pressure, rubberKappa * (p.J - 1.0));
    // P uses the supplied J: neoHookean's formula with it, written out.
    const double jm23 = std::pow(p.J, -2.0 / 3.0);
    const Tensor<3> expected =
        rubberMu * jm23 * p.F +
        (-rubberMu / 3.0 * jm23 / p.J * p.F.squaredNorm() + rubberKappa * (p.J - 1.0)) * p.H;
    EXPECT_LT((p.P - expected).norm(), 1e-13 * expected.norm());
    // ... and the supplied H for j2Plasticity's pressure term.
    const auto j2 = inMaterial(rubber + " yieldStress 1e12;", "type j2Plasticity;");
    Particle a(p.F), b(p.F);
    b.H = 1.01 * a.H;
    j2->stress(a.fields(), false);
    j2->stress(b.fields(), false);
    EXPECT_LT((b.P - a.P - 0.01 * a.pressure * a.H).norm(), 1e-12 * a.P.norm());
}

// neoHookean is mooneyRivlin with xi = 0, zeta = mu/2.
TEST(ConstitutiveMixed, NeoHookeanIsMooneyRivlinWithoutXi) {
    const auto neo = inMaterial(rubber, "type neoHookean;");
    const auto mr = inMaterial(rubber, "type mooneyRivlin; zeta " + std::to_string(rubberMu / 2) + ";");
    std::mt19937 rng(17);
    const Tensor<3> f = randomF(rng);
    EXPECT_LT((stressOf(*neo, f) - stressOf(*mr, f)).norm(), 1e-6 * stressOf(*neo, f).norm());
}

// ---- j2Plasticity --------------------------------------------------------------------------

Tensor<3> isochoricStretch(double l) {
    return Vector<3>(l, 1.0 / std::sqrt(l), 1.0 / std::sqrt(l)).asDiagonal();
}

// Von Mises equivalent of the Cauchy stress sigma = P F^T / J.
double vonMises(const Particle& p) {
    const Tensor<3> sigma = p.P * p.F.transpose() / p.F.determinant();
    const Tensor<3> dev = sigma - sigma.trace() / 3.0 * Tensor<3>::Identity();
    return std::sqrt(1.5) * dev.norm();
}

const std::string metal = "rho0 7800; shearModulus 80e9; bulkModulus 160e9; yieldStress 100e6;";
constexpr double metalMu = 80e9, metalYield = 100e6;

TEST(ConstitutiveJ2Plasticity, PerfectPlasticityStaysOnTheYieldSurface) {
    const auto law = inMaterial(metal, "type j2Plasticity;");
    ASSERT_TRUE(law->usesPlasticState());
    Particle p(Tensor<3>::Identity());
    int yielded = 0;
    for (int step = 1; step <= 200; ++step) {
        p.setF(isochoricStretch(1.0 + 1e-4 * step));  // yield near ln l = 100e6/240e9
        law->stress(p.fields(), true);
        if (p.epsP > 0.0) {
            ++yielded;
            // The return is exact for perfect plasticity: rounding only.
            EXPECT_NEAR(vonMises(p), metalYield, 1e-10 * metalYield) << step;
        } else {
            EXPECT_LT(vonMises(p), metalYield) << step;
        }
        EXPECT_NEAR(p.cpInv.full().determinant(), 1.0, 1e-12) << step;
    }
    EXPECT_GT(yielded, 190);
    // On the surface the elastic stretch le is fixed, mu (le^2 - 1/le) = sigma_Y, and all the
    // logarithmic strain of a step is plastic; but the return in b_e_bar (Simo & Hughes Box 9.1)
    // advances eps_p by sqrt(2/3) dgamma = r d(ln l) (1 + O(d ln l)), r = (2 le^2 + 1/le)/(le^2 +
    // 2/le) = 1 + O(eps_e), not by d(ln l) itself. So eps_p -> r (ln l - ln le) at first order in
    // the step, and eps_p = ln l - sigma_Y/(3 mu) holds only to O(eps_e eps_p) ~ 1e-5.
    double le = 1.0;
    for (int it = 0; it < 50; ++it)
        le -= (le * le - 1.0 / le - metalYield / metalMu) / (2.0 * le + 1.0 / (le * le));
    const double r = (2.0 * le * le + 1.0 / le) / (le * le + 2.0 / le);
    const double limit = r * (std::log(1.02) - std::log(le));
    const double error200 = p.epsP - limit;
    EXPECT_LT(std::abs(error200), 1e-4 * p.epsP);  // step 1e-4: relative error below the step
    // Halving the step halves the error (first order).
    Particle q(Tensor<3>::Identity());
    for (int step = 1; step <= 400; ++step) {
        q.setF(isochoricStretch(1.0 + 0.5e-4 * step));
        law->stress(q.fields(), true);
    }
    EXPECT_NEAR((q.epsP - limit) / error200, 0.5, 0.05);
    const double elastic = metalYield / (3.0 * metalMu);
    EXPECT_NEAR(p.epsP, std::log(1.02) - elastic, 1.2 * elastic * p.epsP);
}

TEST(ConstitutiveJ2Plasticity, LinearHardening) {
    const double hardening = 2e9;
    const auto law = inMaterial(metal, "type j2Plasticity; hardeningModulus 2e9;");
    Particle p(Tensor<3>::Identity());
    for (int step = 1; step <= 500; ++step) {
        p.setF(isochoricStretch(1.0 + 1e-4 * step));
        law->stress(p.fields(), true);
        // Consistency holds exactly at the end of each plastic step.
        if (p.epsP > 0.0) {
            EXPECT_NEAR(vonMises(p), metalYield + hardening * p.epsP, 1e-10 * metalYield) << step;
        }
        EXPECT_NEAR(p.cpInv.full().determinant(), 1.0, 1e-12) << step;
    }
    const double sigma = vonMises(p);
    EXPECT_GT(sigma, metalYield * 1.05);
    // eps_p = ln l - eps_e, eps_e = sigma/(3 mu), to O(eps_e eps_p): the b_e_bar return advances
    // eps_p at 1 + O(eps_e) times the logarithmic rate (see PerfectPlasticityStaysOnTheYieldSurface).
    const double elastic = sigma / (3.0 * metalMu);
    EXPECT_NEAR(p.epsP, std::log(1.05) - elastic, 1.2 * elastic * p.epsP);
}

// The return's dissipation (plasticDissipation, the health check's budget in tlSph): the returned
// Kirchhoff deviator times the plastic increment, |s| dgamma, which with |s| = sqrt(2/3) sigma_Y on
// the yield surface and d eps_p = sqrt(2/3) dgamma is sigma_Y d eps_p exactly (an isochoric
// stretch: J = 1, Kirchhoff = Cauchy); 0 in an elastic step.
TEST(ConstitutiveJ2Plasticity, PlasticDissipationIsTheYieldStressTimesThePlasticIncrement) {
    const auto law = inMaterial(metal, "type j2Plasticity;");
    Particle p(Tensor<3>::Identity());
    int plasticSteps = 0;
    for (int step = 1; step <= 100; ++step) {
        const double before = p.epsP;
        p.setF(isochoricStretch(1.0 + 2e-4 * step));
        ConstitutiveLaw::Fields f = p.fields();
        double dissipation = -1;
        f.plasticDissipation = &dissipation;
        law->stress(f, true);
        const double increment = p.epsP - before;
        if (increment == 0.0) {
            EXPECT_EQ(dissipation, 0.0) << step;
            continue;
        }
        ++plasticSteps;
        EXPECT_NEAR(dissipation, metalYield * increment, 1e-9 * metalYield * increment) << step;
    }
    EXPECT_GT(plasticSteps, 80);
}

TEST(ConstitutiveJ2Plasticity, StagesLeaveTheStateUntouched) {
    const auto law = inMaterial(metal, "type j2Plasticity; hardeningModulus 2e9;");
    Particle p(Tensor<3>::Identity());
    p.setF(isochoricStretch(1.01));
    law->stress(p.fields(), true);
    ASSERT_GT(p.epsP, 0.0);
    const SymmTensor<3> state = p.cpInv;
    const double epsP = p.epsP;
    Particle stage = p;
    stage.setF(rotation(0.2, Vector<3>(1, 1, 0)) * isochoricStretch(1.02));
    law->stress(stage.fields(), false);
    EXPECT_EQ(stage.cpInv.c, state.c);
    EXPECT_EQ(stage.epsP, epsP);
    // The stage's stress is nevertheless the returned one.
    EXPECT_GT(vonMises(stage), metalYield);
    EXPECT_LT(vonMises(stage), metalYield + 2e9 * 0.02);
    // Advancing from the same state with the same F gives the same stress.
    Particle step = p;
    step.setF(stage.F);
    law->stress(step.fields(), true);
    EXPECT_EQ(step.P, stage.P);
    EXPECT_GT(step.epsP, epsP);
}

TEST(ConstitutiveJ2Plasticity, ElasticUnloadingKeepsThePlasticStrain) {
    const auto law = inMaterial(metal, "type j2Plasticity;");
    Particle p(Tensor<3>::Identity());
    for (int step = 1; step <= 50; ++step) {
        p.setF(isochoricStretch(1.0 + 1e-4 * step));
        law->stress(p.fields(), true);
    }
    const double epsP = p.epsP;
    p.setF(isochoricStretch(1.0 + 1e-4 * 49));
    law->stress(p.fields(), true);
    EXPECT_EQ(p.epsP, epsP);
    EXPECT_LT(vonMises(p), metalYield * 0.99);
}

// ---- elastic constants and keywords --------------------------------------------------------

TEST(ConstitutiveLawKeywords, ElasticConstants) {
    const auto a = make("type neoHookean; rho0 1100; youngsModulus 17e6; poissonRatio 0.45;");
    EXPECT_NEAR(a->shearModulus(), rubberMu, 1e-15 * rubberMu);
    EXPECT_NEAR(a->bulkModulus(), rubberKappa, 1e-15 * rubberKappa);
    EXPECT_NEAR(a->bulkModulus() / a->shearModulus(), 9.666666666666, 1e-9);  // the paper's "10"
    EXPECT_EQ(a->referenceDensity(), 1100.0);
    const auto b = make("type linearElastic; rho0 1000; shearModulus 1e6; bulkModulus 3e6;");
    EXPECT_EQ(b->shearModulus(), 1e6);
    EXPECT_EQ(b->bulkModulus(), 3e6);
    EXPECT_NEAR(b->lameLambda(), 3e6 - 2e6 / 3.0, 1e-9);
    EXPECT_EQ(b->describe(), "linearElastic: rho0 1000, mu 1e+06, kappa 3e+06");
}

// Lee et al. 2016: E = 17 MPa, nu = 0.3, rho0 = 1100 kg/m^3 give c_p = 144.2 m/s.
TEST(ConstitutiveLawKeywords, PWaveSpeedOfThePaper) {
    const auto law = inMaterial("rho0 1100; youngsModulus 17e6; poissonRatio 0.3;", "type neoHookean;");
    EXPECT_NEAR(law->pWaveSpeed(), 144.2, 0.05);
}

void expectError(const std::string& material, const std::string& law, const std::vector<std::string>& words) {
    try {
        inMaterial(material, law);
        ADD_FAILURE() << "accepted: " << material << " / " << law;
    } catch (const InputError& e) {
        const std::string what = e.what();
        for (const auto& w : words) EXPECT_NE(what.find(w), std::string::npos) << w << " not in: " << what;
    }
}

TEST(ConstitutiveLawKeywords, Errors) {
    expectError("youngsModulus 17e6; poissonRatio 0.45;", "type neoHookean;", {"'rho0'", "rubber"});
    expectError("rho0 1100; youngsModulus 17e6; poissonRatio 0.5;", "type neoHookean;",
                {"poissonRatio", "0.5"});
    expectError("rho0 1100; youngsModulus 17e6; poissonRatio -1;", "type neoHookean;", {"poissonRatio"});
    expectError("rho0 1100; youngsModulus -17e6; poissonRatio 0.3;", "type neoHookean;", {"youngsModulus"});
    expectError("rho0 1100; youngsModulus 17e6; poissonRatio 0.3; shearModulus 6e6; bulkModulus 1e7;",
                "type neoHookean;",
                {"youngsModulus", "shearModulus", "bulkModulus", "poissonRatio", "test:1"});
    expectError("rho0 1100; youngsModulus 17e6; bulkModulus 1e7;", "type neoHookean;",
                {"youngsModulus", "bulkModulus", "poissonRatio", "shearModulus"});
    expectError("rho0 1100;", "type linearElastic;", {"youngsModulus", "shearModulus"});
    expectError(rubber, "type neoHookeen;", {"neoHookean", "type"});
    expectError(rubber, "type j2Plasticity;", {"'yieldStress'"});
    expectError(rubber, "type mooneyRivlin;", {"'zeta'", "'xi'", "hDominated"});
    expectError(rubber, "type mooneyRivlin; zeta 2e6; xi 1e6;", {"zeta", "mu"});
    expectError(rubber, "type mooneyRivlin; zeta 1e8;", {"zeta"});
    expectError(rubber, "type mooneyRivlin; hDominated yes; xi 1e6;", {"xi", "hDominated"});
    expectError("rho0 1100;", "type mooneyRivlin; zeta 1e6;", {"'kappa'"});
    EXPECT_THROW(make("rho0 1100; youngsModulus 17e6; poissonRatio 0.3;"), InputError);  // no type
}

TEST(ConstitutiveLawKeywords, MooneyRivlinCoefficients) {
    const auto h = inMaterial(rubber, "type mooneyRivlin; hDominated yes;");
    EXPECT_NEAR(h->shearModulus(), rubberMu, 1e-15 * rubberMu);
    // Only xi: zeta from mu; own constants: mu from zeta, xi.
    const double xi = 1e6, zeta = (rubberMu - 3.0 * std::sqrt(3.0) * xi) / 2.0;
    const auto x = inMaterial(rubber, "type mooneyRivlin; xi 1e6;");
    const auto both = inMaterial(rubber, "type mooneyRivlin; xi 1e6; zeta " + std::to_string(zeta) + ";");
    std::mt19937 rng(19);
    const Tensor<3> f = randomF(rng);
    EXPECT_LT((stressOf(*x, f) - stressOf(*both, f)).norm(), 1e-6 * stressOf(*x, f).norm());
    const auto own = make("type mooneyRivlin; rho0 1100; zeta 1.5e6; xi 0.4e6; kappa 5e7;");
    EXPECT_NEAR(own->shearModulus(), 3e6 + 1.2e6 * std::sqrt(3.0), 1e-6);
    EXPECT_EQ(own->bulkModulus(), 5e7);
}

}  // namespace
}  // namespace mfdyn
