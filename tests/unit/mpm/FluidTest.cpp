// mpmFsi's Newtonian fluid (materials/viscosity/Newtonian.cpp on the updated-Lagrangian path,
// mpm/UpdatedLagrangianStress.hpp): Tait's p(J = 1) = 0, simple shear sigma_xy = mu gamma_dot,
// the trace and the plane-strain sigma_zz of a compression, the dissipation into e, the viscous
// time-step vote rho dx^2 / (4 mu), and the materials refused.
#include "core/Dictionary.hpp"
#include "core/Error.hpp"
#include "materials/MaterialSet.hpp"
#include "mpm/UpdatedLagrangianStress.hpp"
#include "particles/ParticleSet.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

namespace mfdyn {
namespace {

constexpr double rho0 = 997.5, B = 2e6, gammaTait = 7, mu = 0.01;

std::string water(const std::string& extra = "viscosity { type newtonian; mu 0.01; }") {
    return "materials { water { equationOfState { type tait; rho0 997.5; B 2e6; gamma 7; } " + extra + " } }";
}

MaterialModels mpm() {
    MaterialModels m;
    m.method = "mpmFsi";
    m.equationOfState = m.strength = m.constitutiveLaw = m.viscosity = ModelUse::optional;
    m.equationOfStateOrConstitutiveLaw = true;
    return m;
}

struct Fluid {
    Dictionary dict;
    MaterialSet<2> materials;
    ParticleSet<2> particles;
    UpdatedLagrangianStress<2> path;

    static ParticleSet<2>& withMaterial(ParticleSet<2>& p) {
        p.integerField("material")[0] = 0;
        p.scalarField("jacobian")[0] = 1.0;
        return p;
    }
    explicit Fluid(const std::string& text)
        : dict(Dictionary::parse(text, "materialProperties")),
          materials(dict, mpm()),
          particles(1),
          path(materials, withMaterial(particles)) {}
};

TEST(MpmFluid, TaitPressureVanishesAtRest) {
    Fluid f(water());
    SymmTensor<2> sigma;
    double zz = 1, W = 1;
    f.path.update(0, Tensor<2>::Zero(), 1.0, 1.0, rho0, 0.0, false, sigma, &zz, W);
    EXPECT_EQ(f.particles.scalarField("pressure")[0], 0.0);
    EXPECT_EQ(sigma.full().norm(), 0.0);
    EXPECT_EQ(zz, 0.0);
    // p(J) = B (J^-gamma - 1) from pressureAt, without changing the state.
    EXPECT_NEAR(f.path.pressureAt(0, 0.99, rho0), B * (std::pow(0.99, -gammaTait) - 1), 1e-9 * B);
}

// v_x = gamma_dot y: L = [[0, g], [0, 0]], tr D = 0, J = 1 exactly: sigma_xy = mu g, sigma_xx =
// sigma_yy = sigma_zz = 0, and the dissipation mu g^2 per unit volume heats e by dt mu g^2 / rho0.
TEST(MpmFluid, SimpleShearGivesMuGammaDot) {
    Fluid f(water());
    const double g = 250.0, dt = 1e-5;
    Tensor<2> L = Tensor<2>::Zero();
    L(0, 1) = g;
    SymmTensor<2> sigma;
    double zz = 1, W = 0;
    f.path.update(0, L, 1.0, 1.0, rho0, dt, true, sigma, &zz, W);
    const Tensor<2> s = sigma.full();
    EXPECT_DOUBLE_EQ(s(0, 1), mu * g);
    EXPECT_DOUBLE_EQ(s(1, 0), mu * g);
    EXPECT_EQ(s(0, 0), 0.0);
    EXPECT_EQ(s(1, 1), 0.0);
    EXPECT_EQ(zz, 0.0);
    EXPECT_DOUBLE_EQ(f.particles.scalarField("specificInternalEnergy")[0], dt * mu * g * g / rho0);
    EXPECT_DOUBLE_EQ(W, dt * mu * g * g);
}

// Compression L = diag(-r, -r): tr D = -2r; dev D = diag(-r/3, -r/3) in the plane, 2r/3 out of it.
// sigma_xx = -2 mu r / 3 - p, sigma_zz = -(2 mu / 3) tr D - p = 4 mu r / 3 - p; the 3D trace
// sigma_xx + sigma_yy + sigma_zz = -3 p (Stokes: no bulk viscosity).
TEST(MpmFluid, CompressionTraceAndPlaneStrainZZ) {
    Fluid f(water());
    const double r = 100.0, dt = 1e-6;
    Tensor<2> L = Tensor<2>::Zero();
    L(0, 0) = L(1, 1) = -r;
    const double J = (1 - r * dt) * (1 - r * dt);
    SymmTensor<2> sigma;
    double zz = 0, W = 0;
    f.path.update(0, L, 1.0, J, rho0, dt, true, sigma, &zz, W);
    const double p = B * (std::pow(1 / J, gammaTait) - 1);
    EXPECT_NEAR(f.particles.scalarField("pressure")[0], p, 1e-12 * p);
    const Tensor<2> s = sigma.full();
    EXPECT_NEAR(s(0, 0), -2 * mu * r / 3 - p, 1e-12 * p);
    EXPECT_NEAR(s(1, 1), -2 * mu * r / 3 - p, 1e-12 * p);
    EXPECT_NEAR(zz, 4 * mu * r / 3 - p, 1e-12 * p);
    EXPECT_NEAR(s(0, 0) + s(1, 1) + zz, -3 * p, 1e-12 * p);
}

TEST(MpmFluid, ViscousTimeStepVote) {
    Fluid f(water());
    const double dx = 0.01;
    f.particles.scalarField("jacobian")[0] = 0.998;
    EXPECT_DOUBLE_EQ(f.path.viscousTimeStep(0, rho0, dx), rho0 / 0.998 * dx * dx / (4 * mu));
    Fluid inviscid(water(""));
    EXPECT_EQ(inviscid.path.viscousTimeStep(0, rho0, dx), std::numeric_limits<double>::infinity());
    Fluid zero(water("viscosity { type newtonian; mu 0; }"));
    EXPECT_EQ(zero.path.viscousTimeStep(0, rho0, dx), std::numeric_limits<double>::infinity());
    EXPECT_TRUE(f.path.isFluid(0));
}

std::string errorOf(const std::string& text, const MaterialModels& models) {
    const Dictionary dict = Dictionary::parse(text, "materialProperties");
    try {
        MaterialSet<2> set(dict, models);
    } catch (const InputError& e) {
        return e.what();
    }
    return "";
}

TEST(MpmFluid, RefusedMaterials) {
    // A fluid given a strength law as well as a viscosity.
    const std::string both = errorOf(
        "materials { water { rho0 997.5; shearModulus 1e9; yieldStress 1e6; "
        "equationOfState { type tait; B 2e6; } strength { type vonMises; } "
        "viscosity { type newtonian; mu 0.01; } } }",
        mpm());
    EXPECT_NE(both.find("a fluid given a strength law"), std::string::npos) << both;
    EXPECT_NE(both.find("viscosity"), std::string::npos) << both;
    // `strength none` carries no stress: allowed beside a viscosity.
    EXPECT_EQ(errorOf(water("strength { type none; } viscosity { type newtonian; mu 0.01; }"), mpm()), "");
    // A viscosity on a constitutiveLaw material.
    const std::string law = errorOf(
        "materials { rubber { constitutiveLaw { type neoHookean; rho0 1100; "
        "shearModulus 5e6; bulkModulus 5e7; } "
        "viscosity { type newtonian; mu 0.01; } } }",
        mpm());
    EXPECT_NE(law.find("viscosity on a constitutiveLaw material"), std::string::npos) << law;
    // impactSph and tlSph take none, and say that mpmFsi does.
    const std::string sph = errorOf(
        water(), MaterialModels{"impactSph", ModelUse::required, ModelUse::optional, ModelUse::refused});
    EXPECT_NE(sph.find("impactSph takes no viscosity"), std::string::npos) << sph;
    EXPECT_NE(sph.find("mpmFsi"), std::string::npos) << sph;
    MaterialModels tl;
    tl.method = "tlSph";
    tl.constitutiveLaw = ModelUse::required;
    const std::string tls = errorOf(
        "materials { rubber { constitutiveLaw { type neoHookean; rho0 1100; "
        "shearModulus 5e6; bulkModulus 5e7; } "
        "viscosity { type newtonian; mu 0.01; } } }",
        tl);
    EXPECT_NE(tls.find("tlSph takes no viscosity"), std::string::npos) << tls;
    EXPECT_NE(tls.find("mpmFsi"), std::string::npos) << tls;
    // A negative mu, at its entry.
    const std::string negative = errorOf(water("viscosity { type newtonian; mu -1; }"), mpm());
    EXPECT_NE(negative.find("mu"), std::string::npos) << negative;
    // An unknown type names the choices.
    const std::string unknown = errorOf(water("viscosity { type bingham; }"), mpm());
    EXPECT_NE(unknown.find("newtonian"), std::string::npos) << unknown;
}

}  // namespace
}  // namespace mfdyn
