// The strength models one by one, against closed forms: the hookean flags (shearFactor,
// deviator), von Mises radial return and hardening slope, Libersky's variant, the Johnson-Cook
// flow stress and plastic heating; and the keyword handling (required keywords, bounds, the
// fallback to the material dictionary).
#include "materials/strength/Strength.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <vector>

namespace mfdyn {
namespace {

template <int Dim>
std::unique_ptr<Strength<Dim>> make(const std::string& text) {
    return Strength<Dim>::New(Dictionary::parse(text, "test"));
}

// One particle with every field.
template <int Dim>
struct Particle {
    explicit Particle(const Strength<Dim>& s, const Tensor<Dim>& gradient)
        : L(gradient), temperature(s.initialTemperature()) {}
    typename Strength<Dim>::Fields fields() {
        typename Strength<Dim>::Fields f;
        f.size = 1;
        f.velocityGradient = &L;
        f.density = &rho;
        f.tau = &tau;
        f.tauRate = &tauRate;
        f.plasticStrain = &epsP;
        f.temperature = &temperature;
        f.plasticWorkRate = &work;
        return f;
    }
    Tensor<Dim> L;
    double rho = 2785.0;
    SymmTensor<Dim> tau, tauRate;
    double epsP = 0.0, temperature = 0.0, work = 0.0;
};

template <int Dim>
Tensor<Dim> uniaxial(double rate) {
    Tensor<Dim> l = Tensor<Dim>::Zero();
    l(0, 0) = rate;
    return l;
}

const std::string al2024 = "shearModulus 27.1e9; yieldStress 0.265e9;";
constexpr double shearG = 27.1e9, yield0 = 0.265e9;

// ---- hookean flags -----------------------------------------------------------------------

TEST(HookeanStrength, ShearFactorOneIsTheThesisMisprint) {
    const auto standard = make<3>("type hookean; shearModulus 27.1e9;");
    const auto printed = make<3>("type hookean; shearModulus 27.1e9; shearFactor 1;");
    Tensor<3> g = Tensor<3>::Zero();
    g(0, 1) = g(1, 0) = 1e3;
    Particle<3> a(*standard, g), b(*printed, g);
    standard->update(a.fields(), 1e-8);
    printed->update(b.fields(), 1e-8);
    // tau_xy = 2mu D_xy dt with D_xy = 1e3: exact to rounding.
    EXPECT_NEAR(a.tau(0, 1), 2 * shearG * 1e-5, 1e-12 * shearG * 1e-5);
    EXPECT_NEAR(b.tau(0, 1), shearG * 1e-5, 1e-12 * shearG * 1e-5);
    EXPECT_THROW(make<3>("type hookean; shearModulus 27.1e9; shearFactor 3;"), InputError);
}

// In 2D, `deviator three` is plane strain: the in-plane components and the implied tau_zz equal
// the 3D run with D_zz = 0; `deviator dimension` (the thesis) has the 2D deviator instead.
TEST(HookeanStrength, DeviatorThreeIsPlaneStrain) {
    const auto plane = make<2>("type hookean; shearModulus 27.1e9; deviator three;");
    const auto thesis = make<2>("type hookean; shearModulus 27.1e9;");
    const auto solid = make<3>("type hookean; shearModulus 27.1e9;");
    Particle<2> p(*plane, uniaxial<2>(1e3)), t(*thesis, uniaxial<2>(1e3));
    Particle<3> s(*solid, uniaxial<3>(1e3));
    for (int k = 0; k < 10; ++k) {
        plane->update(p.fields(), 1e-8);
        thesis->update(t.fields(), 1e-8);
        solid->update(s.fields(), 1e-8);
    }
    const double eps = 1e-4, tol = 1e-12 * shearG * eps;
    EXPECT_NEAR(p.tau(0, 0), s.tau(0, 0), tol);
    EXPECT_NEAR(p.tau(1, 1), s.tau(1, 1), tol);
    EXPECT_NEAR(-(p.tau(0, 0) + p.tau(1, 1)), s.tau(2, 2), tol);
    EXPECT_NEAR(p.tau(0, 0), 2 * shearG * eps * 2.0 / 3.0, tol);
    EXPECT_NEAR(plane->equivalentStress(p.tau), solid->equivalentStress(s.tau), tol);
    EXPECT_NEAR(plane->equivalentStrainRate(p.L), solid->equivalentStrainRate(s.L), 1e-12);
    EXPECT_EQ(plane->impliedComponents(), 1);
    // The thesis's 1/d: D' = D - tr(D)/2 I in the plane.
    EXPECT_NEAR(t.tau(0, 0), 2 * shearG * eps * 0.5, tol);
    EXPECT_NEAR(t.tau(1, 1), -2 * shearG * eps * 0.5, tol);
    EXPECT_THROW(make<2>("type hookean; shearModulus 27.1e9; deviator two;"), InputError);
}

// The Courant speed's M (Strength::longitudinalStiffness) is the law's own normal stress per unit
// uniaxial strain, tau_xx = M eps in an elastic step: 4G/3 in 3D and in plane strain, G for the
// thesis's 2D deviator, 2G/3 with the printed shearFactor 1, and 0 without a deviator.
template <int Dim>
void expectUniaxialModulus(const std::string& text, double expected) {
    const auto law = make<Dim>(text);
    EXPECT_NEAR(law->longitudinalStiffness(), expected, 1e-12 * shearG) << text;
    if (!law->allocatesStress()) return;
    Particle<Dim> p(*law, uniaxial<Dim>(1e3));
    law->update(p.fields(), 1e-8);  // eps = 1e-5, far below yield (sigma_Y/G = 1e-2)
    EXPECT_NEAR(p.tau(0, 0) / 1e-5, law->longitudinalStiffness(), 1e-9 * shearG) << text;
}

TEST(HookeanStrength, LongitudinalStiffnessIsTheUniaxialStrainModulus) {
    expectUniaxialModulus<3>("type hookean; shearModulus 27.1e9;", 4.0 / 3.0 * shearG);
    expectUniaxialModulus<3>("type hookean; shearModulus 27.1e9; shearFactor 1;", 2.0 / 3.0 * shearG);
    expectUniaxialModulus<3>("type vonMises; " + al2024, 4.0 / 3.0 * shearG);
    expectUniaxialModulus<2>("type vonMises; deviator three; " + al2024, 4.0 / 3.0 * shearG);
    expectUniaxialModulus<2>("type hookean; shearModulus 27.1e9;", shearG);
    expectUniaxialModulus<1>("type hookean; shearModulus 27.1e9; deviator three;", 4.0 / 3.0 * shearG);
    expectUniaxialModulus<3>("type none;", 0.0);
}

TEST(HookeanStrength, OneDimensionNeedsDeviatorThree) {
    const auto thesis = make<1>("type hookean; shearModulus 27.1e9;");
    const auto strain = make<1>("type hookean; shearModulus 27.1e9; deviator three;");
    Particle<1> t(*thesis, uniaxial<1>(1e3)), u(*strain, uniaxial<1>(1e3));
    thesis->update(t.fields(), 1e-7);
    strain->update(u.fields(), 1e-7);
    EXPECT_EQ(t.tau(0, 0), 0.0);  // 1/d in 1D: no deviator at all
    EXPECT_NEAR(u.tau(0, 0), 4.0 / 3.0 * shearG * 1e-4, 1e-12 * shearG * 1e-4);
    // Uniaxial strain: sigmaEq = |tau_xx - tau_yy| = 2G eps.
    EXPECT_NEAR(strain->equivalentStress(u.tau), 2 * shearG * 1e-4, 1e-12 * shearG * 1e-4);
}

// ---- vonMises ----------------------------------------------------------------------------

TEST(VonMisesStrength, OneStepRadialReturn) {
    const auto s = make<3>("type vonMises; " + al2024);
    Particle<3> p(*s, uniaxial<3>(1e4));
    const double dt = 1e-6;  // strain 1e-2: trial sigma* = 3G (2/3) 1e-2 = 2G 1e-2 >> sigma_Y
    s->update(p.fields(), dt);
    const double trial = 2 * shearG * 1e-2;
    EXPECT_NEAR(s->equivalentStress(p.tau), yield0, 1e-12 * yield0);
    EXPECT_NEAR(p.epsP, (trial - yield0) / (3 * shearG), 1e-12 * p.epsP);
    EXPECT_NEAR(p.work * dt, yield0 * p.epsP, 1e-12 * yield0 * p.epsP);
    // The return is radial: the deviator keeps its direction diag(2, -1, -1).
    EXPECT_NEAR(p.tau(1, 1), -0.5 * p.tau(0, 0), 1e-12 * yield0);
    EXPECT_NEAR(p.tau(0, 0), 2.0 / 3.0 * yield0, 1e-12 * yield0);
}

TEST(VonMisesStrength, LiberskyVariantLandsInsideTheSurface) {
    const auto s = make<3>("type vonMises; libersky yes; " + al2024);
    Particle<3> p(*s, uniaxial<3>(1e4));
    s->update(p.fields(), 1e-6);
    const double trial = 2 * shearG * 1e-2;
    // tau* min(1, sigma_Y^2/(3 J2)): sigmaEq = sigma_Y^2 / sigma*.
    EXPECT_NEAR(s->equivalentStress(p.tau), yield0 * yield0 / trial, 1e-12 * yield0);
    EXPECT_LT(s->equivalentStress(p.tau), yield0);
}

// Uniaxial strain at a constant rate: elastic slope dSigmaEq/dEpsEq = 3G, then
// sigma = sigma_Y0 + H epsP with dSigmaEq/dEpsEq = 3G H/(3G + H); H is recovered from the
// loading curve alone (two points past yield), and from sigma against epsP.
TEST(VonMisesStrength, HardeningSlopeFromUniaxialLoading) {
    const double hardening = 2.5e9;
    const auto s = make<3>("type vonMises; hardeningModulus 2.5e9; " + al2024);
    Particle<3> p(*s, uniaxial<3>(1e3));
    const double dt = 1e-7;
    const double epsDotEq = s->equivalentStrainRate(p.L);
    EXPECT_NEAR(epsDotEq, 2.0 / 3.0 * 1e3, 1e-12);
    std::vector<double> epsEq, sigma, epsP;
    for (int k = 1; k <= 400; ++k) {  // total strain 4e-2, yield at about 3.3e-3
        s->update(p.fields(), dt);
        epsEq.push_back(k * dt * epsDotEq);
        sigma.push_back(s->equivalentStress(p.tau));
        epsP.push_back(p.epsP);
    }
    EXPECT_NEAR(sigma[9], 3 * shearG * epsEq[9], 1e-12 * sigma[9]);  // still elastic at 1e-3
    const double slope = (sigma[399] - sigma[199]) / (epsEq[399] - epsEq[199]);
    const double recovered = 3 * shearG * slope / (3 * shearG - slope);
    // Exact for linear hardening; the differences lose ~ sigma/dSigma ~ 10 digits of 16.
    EXPECT_NEAR(recovered, hardening, 1e-6 * hardening);
    EXPECT_NEAR((sigma[399] - sigma[199]) / (epsP[399] - epsP[199]), hardening, 1e-6 * hardening);
    EXPECT_NEAR(sigma[399], yield0 + hardening * epsP[399], 1e-12 * sigma[399]);
    EXPECT_DOUBLE_EQ(s->yieldStress(0.1, 0.0, 0.0), yield0 + 0.1 * hardening);
}

// ---- johnsonCook -------------------------------------------------------------------------

// Johnson & Cook 1983 Table 1, 2024-T351: A 265 MPa, B 426 MPa, n 0.34, C 0.015, m 1; Tmelt 775 K.
std::string jc2024(const std::map<std::string, std::string>& changes = {}) {
    std::map<std::string, std::string> keys{{"shearModulus", "27.1e9"},
                                            {"A", "265e6"},
                                            {"B", "426e6"},
                                            {"n", "0.34"},
                                            {"C", "0.015"},
                                            {"m", "1"},
                                            {"Tmelt", "775"},
                                            {"specificHeat", "875"},
                                            {"Troom", "294"}};
    for (const auto& [k, v] : changes) keys[k] = v;
    std::string text = "type johnsonCook;";
    for (const auto& [k, v] : keys) text += " " + k + " " + v + ";";
    return text;
}

TEST(JohnsonCookStrength, FlowStressIsTheFormula) {
    const auto s = make<3>(jc2024());
    EXPECT_EQ(s->initialTemperature(), 294.0);
    for (double epsP : {0.0, 0.05, 0.3, 1.2})
        for (double rate : {1.0, 50.0, 1e4})
            for (double t : {294.0, 400.0, 700.0}) {
                const double tStar = (t - 294.0) / (775.0 - 294.0);
                const double expected =
                    (265e6 + 426e6 * std::pow(epsP, 0.34)) * (1 + 0.015 * std::log(rate)) * (1 - tStar);
                EXPECT_NEAR(s->yieldStress(epsP, rate, t), expected, 1e-14 * expected)
                    << epsP << " " << rate << " " << t;
            }
    // Rates below epsilonDot0 do not soften; temperatures are clamped to [Troom, Tmelt].
    EXPECT_DOUBLE_EQ(s->yieldStress(0.1, 1e-3, 294.0), s->yieldStress(0.1, 1.0, 294.0));
    EXPECT_DOUBLE_EQ(s->yieldStress(0.1, 1.0, 200.0), s->yieldStress(0.1, 1.0, 294.0));
    EXPECT_EQ(s->yieldStress(0.1, 1.0, 775.0), 0.0);
    EXPECT_EQ(s->yieldStress(0.1, 1.0, 900.0), 0.0);
    const auto m2 = make<3>(jc2024({{"m", "2"}, {"epsilonDot0", "10"}}));
    EXPECT_NEAR(m2->yieldStress(0.0, 1e3, 534.5), 265e6 * (1 + 0.015 * std::log(100.0)) * (1 - 0.25),
                1e-14 * 265e6);
}

// One plastic step: dEpsP solves sigma* - 3G dEpsP = sigma_Y(epsP + dEpsP) at the step's rate and
// starting temperature, the state is on that surface, and T rises by beta sigma_Y dEpsP/(rho c_v).
TEST(JohnsonCookStrength, ImplicitReturnAndPlasticHeating) {
    const auto s = make<3>(jc2024());
    Particle<3> p(*s, uniaxial<3>(1e4));
    p.epsP = 0.02;
    p.temperature = 350.0;
    const double dt = 2e-6;
    s->update(p.fields(), dt);
    const double trial = 2 * shearG * 2e-2;
    const double rate = s->equivalentStrainRate(p.L);
    const double dEps = p.epsP - 0.02;
    const double flow = s->yieldStress(p.epsP, rate, 350.0);
    EXPECT_GT(dEps, 0.0);
    EXPECT_NEAR(s->equivalentStress(p.tau), flow, 1e-12 * flow);
    EXPECT_NEAR(trial - 3 * shearG * dEps, flow, 1e-9 * flow);  // Newton to 1e-15 of sigma*/3G
    EXPECT_NEAR(p.temperature - 350.0, 0.9 * flow * dEps / (2785.0 * 875.0), 1e-12 * p.temperature);
    EXPECT_NEAR(p.work * dt, flow * dEps, 1e-12 * flow * dEps);
}

TEST(JohnsonCookStrength, MeltedMaterialCarriesNoShear) {
    const auto s = make<2>(jc2024());
    Particle<2> p(*s, uniaxial<2>(1e4));
    p.temperature = 800.0;
    s->update(p.fields(), 1e-6);
    EXPECT_EQ(s->equivalentStress(p.tau), 0.0);
}

TEST(JohnsonCookStrength, BoundsAreChecked) {
    for (const auto& [key, value] : std::vector<std::pair<std::string, std::string>>{
             {"Tmelt", "250"}, {"taylorQuinney", "1.5"}, {"n", "0"}, {"specificHeat", "-1"}}) {
        try {
            make<3>(jc2024({{key, value}}));
            ADD_FAILURE() << key << " " << value << " accepted";
        } catch (const InputError& e) {
            EXPECT_NE(std::string(e.what()).find("keyword '" + key + "'"), std::string::npos) << e.what();
        }
    }
}

// ---- keywords ----------------------------------------------------------------------------

// Removing each required keyword in turn gives an InputError naming it.
TEST(StrengthKeywords, MissingRequiredKeywordIsNamed) {
    struct Case {
        std::string type;
        std::vector<std::pair<std::string, std::string>> keys;
    };
    const std::vector<Case> cases{
        {"hookean", {{"shearModulus", "27.1e9"}}},
        {"vonMises", {{"shearModulus", "27.1e9"}, {"yieldStress", "0.265e9"}}},
        {"johnsonCook",
         {{"shearModulus", "27.1e9"},
          {"A", "265e6"},
          {"B", "426e6"},
          {"n", "0.34"},
          {"C", "0.015"},
          {"m", "1"},
          {"Tmelt", "775"},
          {"specificHeat", "875"}}},
    };
    for (const auto& c : cases)
        for (std::size_t skip = 0; skip < c.keys.size(); ++skip) {
            std::string text = "type " + c.type + ";";
            for (std::size_t k = 0; k < c.keys.size(); ++k)
                if (k != skip) text += " " + c.keys[k].first + " " + c.keys[k].second + ";";
            try {
                make<3>(text);
                ADD_FAILURE() << c.type << " without " << c.keys[skip].first << " did not throw";
            } catch (const InputError& e) {
                EXPECT_NE(std::string(e.what()).find("missing keyword '" + c.keys[skip].first + "'"),
                          std::string::npos)
                    << e.what();
            }
            EXPECT_NO_THROW(make<2>(text + " " + c.keys[skip].first + " " + c.keys[skip].second + ";"));
        }
}

TEST(StrengthKeywords, OutOfBoundsAndUnknownType) {
    try {
        make<3>("type vonMises; shearModulus -1e9; yieldStress 1e8;");
        ADD_FAILURE() << "negative shear modulus accepted";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("shearModulus"), std::string::npos) << e.what();
    }
    EXPECT_THROW(make<3>("type vonMises; yieldStress 0; " + std::string("shearModulus 1e9;")), InputError);
    try {
        make<3>("type vonMisses; " + al2024);
        ADD_FAILURE() << "unknown type accepted";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("vonMises"), std::string::npos) << e.what();
    }
}

// Parameters come from the strength dictionary first, then from the material around it.
TEST(StrengthKeywords, FallBackToTheMaterialDictionary) {
    const Dictionary materials = Dictionary::parse(
        "target { rho0 2785; shearModulus 27.1e9; yieldStress 0.265e9; strength { type vonMises; } }"
        "projectile { shearModulus 25e9; yieldStress 0.55e9;"
        "             strength { type vonMises; yieldStress 0.3e9; } }"
        "bare { strength { type vonMises; yieldStress 0.3e9; } }",
        "constant/materialProperties");
    const auto target = Strength<2>::New(materials.subDict("target").subDict("strength"));
    EXPECT_EQ(target->shearModulus(), 27.1e9);
    EXPECT_EQ(target->yieldStress(0.0, 0.0, 0.0), 0.265e9);
    const auto projectile = Strength<2>::New(materials.subDict("projectile").subDict("strength"));
    EXPECT_EQ(projectile->shearModulus(), 25e9);
    EXPECT_EQ(projectile->yieldStress(0.0, 0.0, 0.0), 0.3e9);  // the strength dictionary wins
    try {
        Strength<2>::New(materials.subDict("bare").subDict("strength"));
        ADD_FAILURE() << "missing shear modulus accepted";
    } catch (const InputError& e) {
        const std::string what = e.what();
        EXPECT_NE(what.find("missing keyword 'shearModulus'"), std::string::npos) << what;
        EXPECT_NE(what.find("bare"), std::string::npos) << what;  // names the material
    }
}

}  // namespace
}  // namespace mfdyn
