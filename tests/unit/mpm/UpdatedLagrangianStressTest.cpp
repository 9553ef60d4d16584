// mpmFsi's updated-Lagrangian material path (libraries/mpm/UpdatedLagrangianStress.hpp): one step
// of one particle against a hand computation, elastic and plastic (uniaxial-strain compression,
// 3D and plane strain), a fluid that carries no deviatoric stress, the CFL wave speed, the energy
// of a reversible cycle, and the materials mpmFsi refuses.
#include "core/Dictionary.hpp"
#include "core/Error.hpp"
#include "materials/MaterialSet.hpp"
#include "mpm/UpdatedLagrangianStress.hpp"
#include "particles/ParticleSet.hpp"

#include <gtest/gtest.h>
#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <string>

namespace mfdyn {
namespace {

// Copper-like numbers, round so that the hand computation below is easy to follow.
constexpr double rho0 = 8930, c0 = 3800, G = 43e9, H = 0.1e9;

std::string solid(double yieldStress, const std::string& deviator = "three") {
    return "materials { copper { rho0 8930; c0 3800; shearModulus 43e9; yieldStress " +
           std::to_string(yieldStress) +
           "; hardeningModulus 0.1e9; equationOfState { type linearBarotropic; } " +
           "strength { type vonMises; deviator " + deviator + "; } } }";
}

template <int Dim>
struct OneParticle {
    Dictionary dict;
    MaterialModels models;
    MaterialSet<Dim> materials;
    ParticleSet<Dim> particles;
    UpdatedLagrangianStress<Dim> path;

    static MaterialModels mpm() {
        MaterialModels m;
        m.method = "mpmFsi";
        m.equationOfState = m.strength = m.constitutiveLaw = ModelUse::optional;
        m.equationOfStateOrConstitutiveLaw = true;
        return m;
    }
    static ParticleSet<Dim>& withMaterial(ParticleSet<Dim>& p) {
        p.integerField("material")[0] = 0;
        p.scalarField("jacobian")[0] = 1.0;
        return p;
    }
    explicit OneParticle(const std::string& text)
        : dict(Dictionary::parse(text, "materialProperties")),
          models(mpm()),
          materials(dict, models),
          particles(1),
          path(materials, withMaterial(particles)) {}

    // One step from the rest state with velocity gradient L: F = I + dt L, J^n = 1.
    void step(const Tensor<Dim>& L, double dt, SymmTensor<Dim>& sigma, double& sigmaZZ, double& W) {
        const double J = (Tensor<Dim>::Identity() + dt * L).determinant();
        path.update(0, L, particles.scalarField("jacobian")[0], J, rho0, dt, true, sigma, &sigmaZZ, W);
        particles.scalarField("jacobian")[0] = J;
    }
};

// Uniaxial-strain compression at rate r (L = diag(-r, 0, 0), D' = diag(-2r/3, r/3, r/3)), one
// step dt from rest, by hand:
//   J = 1 - r dt, rho = rho0 / J, p = c0^2 (rho - rho0)                      (linearBarotropic)
//   tau* = 2G dt D' = a diag(-2, 1, 1), a = 2G r dt / 3; sigma* = sqrt(3 J2) = 3a = 2G r dt
//   elastic (sigma* <= Y): tau = tau*; plastic: dEpsP = (sigma* - Y)/(3G + H),
//   tau = tau* (Y + H dEpsP)/sigma*                                           (radial return)
//   e = -(0 + p)/2 (J - 1)/rho0 + dt (0 + tau)/2 : D (1 + J)/(2 rho0)        (the header's rule)
//   sigma = -p I + tau, W = rho0 e
struct Hand {
    double J, p, tauXX, tauYY, epsP, e;
};

Hand uniaxial(double r, double dt, double Y) {
    Hand h;
    h.J = 1 - r * dt;
    h.p = c0 * c0 * (rho0 / h.J - rho0);
    const double a = 2 * G * r * dt / 3, trial = 3 * a;
    double factor = 1;
    h.epsP = 0;
    if (trial > Y) {
        h.epsP = (trial - Y) / (3 * G + H);
        factor = (Y + H * h.epsP) / trial;
    }
    h.tauXX = -2 * a * factor, h.tauYY = a * factor;
    h.e = -0.5 * h.p * (h.J - 1) / rho0 + dt * 0.5 * h.tauXX * (-r) * (1 + h.J) / (2 * rho0);
    return h;
}

TEST(UpdatedLagrangianStress, UniaxialCompressionOneStepElasticAndPlastic3D) {
    const double r = 1e4, dt = 1e-8;  // strain increment 1e-4: sigma* = 2G r dt = 8.6 MPa
    for (const double Y : {1e9, 2e6}) {
        SCOPED_TRACE(Y > 1e8 ? "elastic" : "plastic");
        OneParticle<3> one(solid(Y));
        Tensor<3> L = Tensor<3>::Zero();
        L(0, 0) = -r;
        SymmTensor<3> sigma;
        double zz = 0, W = 0;
        one.step(L, dt, sigma, zz, W);
        const Hand h = uniaxial(r, dt, Y);
        const double tol = 1e-12;
        EXPECT_NEAR(sigma(0, 0), -h.p + h.tauXX, tol * std::abs(h.p));
        EXPECT_NEAR(sigma(1, 1), -h.p + h.tauYY, tol * std::abs(h.p));
        EXPECT_NEAR(sigma(2, 2), -h.p + h.tauYY, tol * std::abs(h.p));
        EXPECT_EQ(sigma(0, 1), 0.0);
        EXPECT_NEAR(one.particles.scalarField("pressure")[0], h.p, tol * h.p);
        EXPECT_NEAR(one.particles.scalarField("specificInternalEnergy")[0], h.e, 1e-10 * h.e);
        EXPECT_NEAR(W, rho0 * h.e, 1e-10 * rho0 * h.e);
        EXPECT_NEAR(one.particles.scalarField("plasticStrain")[0], h.epsP, 1e-15);
        // The physics the numbers must show: the stress difference of uniaxial strain is 2G x the
        // strain increment elastically (8.6 MPa), the flow stress Y + H epsP once plastic.
        const double difference = sigma(1, 1) - sigma(0, 0);
        if (Y > 1e8)
            EXPECT_NEAR(difference, 2 * G * r * dt, 1e-9 * 2 * G * r * dt);
        else {
            EXPECT_GT(h.epsP, 0.0);
            EXPECT_NEAR(difference, Y + H * h.epsP, 1e-9 * Y);
        }
    }
}

TEST(UpdatedLagrangianStress, PlaneStrainCarriesTheImpliedOutOfPlaneDeviator) {
    // 2D, deviator three: tau_zz = -(tau_xx + tau_yy) = a (the hand value of tau_yy above), so
    // sigma_zz = sigma_yy; under `deviator dimension` there is no out-of-plane deviator and
    // sigma_zz = -p, with tau = G r dt diag(-1, 1) (the 2D deviator D - tr D/2 I).
    const double r = 1e4, dt = 1e-8;
    const Hand h = uniaxial(r, dt, 1e9);
    Tensor<2> L = Tensor<2>::Zero();
    L(0, 0) = -r;
    {
        OneParticle<2> one(solid(1e9, "three"));
        SymmTensor<2> sigma;
        double zz = 0, W = 0;
        one.step(L, dt, sigma, zz, W);
        EXPECT_NEAR(sigma(0, 0), -h.p + h.tauXX, 1e-12 * h.p);
        EXPECT_NEAR(sigma(1, 1), -h.p + h.tauYY, 1e-12 * h.p);
        EXPECT_NEAR(zz, -h.p + h.tauYY, 1e-12 * h.p);
    }
    {
        OneParticle<2> one(solid(1e9, "dimension"));
        SymmTensor<2> sigma;
        double zz = 0, W = 0;
        one.step(L, dt, sigma, zz, W);
        EXPECT_NEAR(sigma(0, 0), -h.p - G * r * dt, 1e-12 * h.p);
        EXPECT_NEAR(sigma(1, 1), -h.p + G * r * dt, 1e-12 * h.p);
        EXPECT_NEAR(zz, -h.p, 1e-12 * h.p);
    }
}

TEST(UpdatedLagrangianStress, FluidCarriesNoDeviatoricStress) {
    // Water (EOS only) sheared, L = [[0, s], [0, 0]] (no volume change): no deviatoricStress or
    // plasticStrain field is made, sigma stays isotropic (sigma_xy = 0, sigma_xx = sigma_yy =
    // sigma_zz = -p = 0) and e stays 0 (no work); a vonMises solid sheared alike does carry
    // sigma_xy = G s dt (2mu D_xy dt with D_xy = s/2).
    OneParticle<2> water(
        "materials { water { rho0 1000; c0 1480; equationOfState { type linearBarotropic; } } }");
    EXPECT_FALSE(water.particles.hasField("deviatoricStress"));
    EXPECT_FALSE(water.particles.hasField("plasticStrain"));
    EXPECT_TRUE(water.particles.hasField("specificInternalEnergy"));
    Tensor<2> L = Tensor<2>::Zero();
    L(0, 1) = 100;
    SymmTensor<2> sigma;
    sigma(0, 1) = 123;  // overwritten
    double zz = 1, W = 1;
    const double dt = 1e-6;
    const double J = (Tensor<2>::Identity() + dt * L).determinant();
    ASSERT_EQ(J, 1.0);
    water.path.update(0, L, 1.0, J, 1000, dt, true, sigma, &zz, W);
    EXPECT_EQ(sigma(0, 1), 0.0);
    EXPECT_EQ(sigma(0, 0), 0.0);
    EXPECT_EQ(sigma(1, 1), 0.0);
    EXPECT_EQ(zz, 0.0);
    EXPECT_EQ(W, 0.0);

    OneParticle<2> copper(solid(1e9));
    copper.path.update(0, L, 1.0, J, rho0, dt, true, sigma, &zz, W);
    EXPECT_NEAR(sigma(0, 1), G * 100 * dt, 1e-12 * G * 100 * dt);
}

TEST(UpdatedLagrangianStress, WaveSpeedIsThePWaveSpeedAndTheFluidsSoundSpeed) {
    // At rest: c_p = sqrt(c0^2 + 4/3 G / rho0) = 4567.3 m/s for the solid, c0 for the fluid; the
    // CFL vote must use the p-wave speed of a solid (c0 alone would allow a 20% longer step).
    OneParticle<3> copper(solid(1e9));
    SymmTensor<3> sigma;
    double W = 0;
    copper.path.update(0, Tensor<3>::Zero(), 1.0, 1.0, rho0, 0.0, false, sigma, nullptr, W);
    EXPECT_NEAR(copper.path.waveSpeed(0, rho0), std::sqrt(c0 * c0 + 4.0 / 3.0 * G / rho0), 1e-9);
    EXPECT_NEAR(copper.path.waveSpeed(0, rho0), 4567.3, 0.1);
    OneParticle<3> water(
        "materials { water { rho0 1000; c0 1480; equationOfState { type linearBarotropic; } } }");
    water.path.update(0, Tensor<3>::Zero(), 1.0, 1.0, 1000, 0.0, false, sigma, nullptr, W);
    EXPECT_NEAR(water.path.waveSpeed(0, 1000), 1480, 1e-9);
}

TEST(UpdatedLagrangianStress, ElasticCompressionCycleReturnsItsEnergy) {
    // 200 steps of uniaxial-strain compression (J to 0.99) and 200 back at the same rate, elastic:
    // at the turning point the stored energy W = rho0 e is the elastic energy (K + 4/3 G) eps^2/2
    // to first order in eps (K = rho0 c0^2), and it returns to zero at J = 1, since the pressure
    // work is the trapezoidal -int p dV of the discrete volume (exact for p linear in J to
    // round-off) and the deviatoric work the trapezoidal int tau:D.
    OneParticle<3> one(solid(1e9));
    const double r = 1e3, dt = 5e-8;  // strain 5e-5 a step, 1% in 200
    SymmTensor<3> sigma;
    double zz = 0, W = 0, peak = 0;
    for (int k = 0; k < 400; ++k) {
        Tensor<3> L = Tensor<3>::Zero();
        L(0, 0) = k < 200 ? -r : r;
        const double Jold = one.particles.scalarField("jacobian")[0];
        // F is diagonal: J^{n+1} = (1 + dt L_xx) J^n, as the solver's F <- (I + dt L) F.
        const double Jnew = (1 + dt * L(0, 0)) * Jold;
        one.path.update(0, L, Jold, Jnew, rho0, dt, true, sigma, &zz, W);
        one.particles.scalarField("jacobian")[0] = Jnew;
        if (k == 199) peak = W;
    }
    const double eps = 1 - std::pow(1 - r * dt, 200);
    const double M = rho0 * c0 * c0 + 4.0 / 3.0 * G;
    EXPECT_NEAR(peak, 0.5 * M * eps * eps, 0.02 * 0.5 * M * eps * eps);
    EXPECT_LT(std::abs(W), 1e-4 * peak);
}

TEST(UpdatedLagrangianStress, ImpactSphTutorialMaterialsAreTakenUnchanged) {
    // The material dictionaries of impactSph's Taylor bar and hypervelocity impacts, read from the
    // tutorials as they are (Mie-Grueneisen + vonMises, deviator three, #includeEtc constants):
    // each material takes this path, and one plane-strain step of uniaxial compression gives
    // p > 0 (compression), sigma_xx < sigma_yy < 0, and sigma_zz = sigma_yy (under uniaxial strain
    // the implied tau_zz equals tau_yy).
    for (const char* tutorial : {"taylorBar", "hviAlAl", "hviAlCu", "hviAlPb"}) {
        SCOPED_TRACE(tutorial);
        const Dictionary dict = Dictionary::read(std::string(MFDYN_TUTORIALS_DIR) + "/impactSph/" + tutorial +
                                                 "/constant/materialProperties");
        const MaterialModels models = OneParticle<2>::mpm();
        MaterialSet<2> materials(dict, models);
        ParticleSet<2> particles(materials.size());
        auto& material = particles.integerField("material");
        for (std::size_t k = 0; k < materials.size(); ++k) material[k] = std::int64_t(k);
        std::fill(particles.scalarField("jacobian").begin(), particles.scalarField("jacobian").end(), 1.0);
        UpdatedLagrangianStress<2> path(materials, particles);
        ASSERT_TRUE(path.any());
        Tensor<2> L = Tensor<2>::Zero();
        L(0, 0) = -1e4;
        const double dt = 1e-8, J = 1 - 1e-4;
        for (std::size_t k = 0; k < materials.size(); ++k) {
            ASSERT_TRUE(path.handles(std::int64_t(k))) << materials.names()[k];
            const double rho0 = path.referenceDensity(std::int64_t(k));
            SymmTensor<2> sigma;
            double zz = 0, W = 0;
            path.update(k, L, 1.0, J, rho0, dt, true, sigma, &zz, W);
            const double p = particles.scalarField("pressure")[k];
            EXPECT_GT(p, 0.0) << materials.names()[k];
            EXPECT_LT(sigma(0, 0), sigma(1, 1)) << materials.names()[k];
            EXPECT_LT(sigma(1, 1), 0.0) << materials.names()[k];
            EXPECT_NEAR(zz, sigma(1, 1), 1e-9 * p) << materials.names()[k];
            EXPECT_GT(W, 0.0) << materials.names()[k];
        }
    }
}

TEST(UpdatedLagrangianStress, ATemperatureLawStartsAtItsInitialTemperature) {
    // johnsonCook carries a temperature: a fresh start sets it to the law's Troom (300 K here),
    // and a particle file that gives one keeps it.
    const std::string text =
        "materials { steel { rho0 7850; c0 4570; s 1.49; gamma0 2.17; shearModulus 81.8e9;\n"
        "equationOfState { type mieGruneisen; }\nstrength { type johnsonCook; A 350e6; B 275e6; n 0.36; "
        "C 0.022; m 1; epsilonDot0 1; Troom 300; Tmelt 1800; specificHeat 477; } } }";
    OneParticle<3> fresh(text);
    ASSERT_TRUE(fresh.particles.hasField("temperature"));
    EXPECT_EQ(fresh.particles.scalarField("temperature")[0], 300.0);
    EXPECT_TRUE(fresh.particles.hasField("plasticStrain"));
}

TEST(UpdatedLagrangianStress, MaterialsItRefusesAreErrorsAtTheEntry) {
    try {
        OneParticle<2> both(
            "materials { copper { rho0 8930; c0 3800; youngsModulus 117e9; poissonRatio 0.35;\n"
            "equationOfState { type linearBarotropic; }\nconstitutiveLaw { type neoHookean; } } }");
        FAIL() << "a material with both a constitutive law and an equation of state was accepted";
    } catch (const InputError& e) {
        const std::string what = e.what();
        EXPECT_NE(what.find("materialProperties:2:"), std::string::npos) << what;  // the EOS entry
        EXPECT_NE(what.find("names both a constitutiveLaw and an equationOfState"), std::string::npos)
            << what;
    }
    try {
        OneParticle<2> strengthOnly(
            "materials { copper { rho0 8930; youngsModulus 117e9; poissonRatio 0.35;\n"
            "constitutiveLaw { type neoHookean; }\nstrength { type hookean; shearModulus 43e9; } } }");
        FAIL() << "a strength law without an equation of state was accepted";
    } catch (const InputError& e) {
        const std::string what = e.what();
        EXPECT_NE(what.find("materialProperties:3:"), std::string::npos) << what;  // the strength entry
        EXPECT_NE(what.find("strength law without an equationOfState"), std::string::npos) << what;
    }
}

}  // namespace
}  // namespace mfdyn
