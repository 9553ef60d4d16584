// The dissipation family of tlSph (familyName dissipation, methodName tlSph): every type reads
// through a keyword schema; jst defaults to the paper's coefficients (Lee et al. 2016:
// eps_p = (0 1/8), eps_J = (0 0)) and evaluates D(U) = eps2 c h L[U] - eps4 c h^3 L^2[U] on the block
// the solver hands it; artificialViscosity needs its mu_vis and gives (mu_vis/rho0) L[p]; bad
// entries are InputErrors naming the entry.
#include "core/Dictionary.hpp"
#include "core/Error.hpp"
#include "core/Registry.hpp"
#include "tlSph/ArtificialViscosity.hpp"
#include "tlSph/JstDissipation.hpp"
#include "tlSph/NoTlDissipation.hpp"

#include "../SchemaTestTools.hpp"

#include <gtest/gtest.h>

#include <string>

using namespace mfdyn;

namespace {

std::unique_ptr<TlDissipation> model(const std::string& text) {
    return TlDissipation::New(Dictionary::parse(text, "dissipation"));
}

std::string errorOf(const std::string& text) {
    return test::inputErrorOf([&] { model(text); }, text);
}

// D(p) and D(J) of `m` on two particles in 2D with given Laplacians, c_p = 100, c_s = 20, h = 0.1.
struct Evaluated {
    std::vector<double> p, J;
};
Evaluated evaluate(const TlDissipation& m) {
    const std::vector<double> rho0{1000, 2000}, lapP{1, -2, 3, 4}, lap2P{10, 20, -30, 40}, lapJ{0.5, -0.25},
        lap2J{5, 6};
    Evaluated out{std::vector<double>(4, -99.0), std::vector<double>(2, -99.0)};
    TlDissipation::Block b;
    b.size = 2, b.dimension = 2, b.waveSpeed = 100, b.shearSpeed = 20, b.spacing = 0.1, b.rho0 = rho0.data();
    if (m.needsMomentumLaplacian()) b.lapP = lapP.data();
    if (m.needsMomentumBiLaplacian()) b.lap2P = lap2P.data();
    if (m.needsJacobianLaplacian()) b.lapJ = lapJ.data();
    if (m.needsJacobianBiLaplacian()) b.lap2J = lap2J.data();
    if (m.actsOnMomentum()) b.dissipationP = out.p.data();
    if (m.actsOnJacobian()) b.dissipationJ = out.J.data();
    m.evaluate(b);
    return out;
}

}  // namespace

TEST(TlDissipationContract, EveryTypeDeclaresAKeywordSchema) {
    test::expectRegisteredSchemas(
        TlDissipation::familyName,
        {JstDissipation::keywords(), ArtificialViscosity::keywords(), NoTlDissipation::keywords()},
        "libraries/tlSph/", TlDissipation::methodName);
}

TEST(TlDissipationContract, TheFamilyIsTlSphsDissipation) {
    EXPECT_STREQ(TlDissipation::familyName, "dissipation");
    EXPECT_STREQ(TlDissipation::methodName, "tlSph");
}

TEST(TlDissipationContract, DefaultsGivenValuesAndWhatEachModelEvaluates) {
    // The paper's jst: eps4_p = 1/8 only, so L[p] and L^2[p] and nothing of J.
    const auto paper = model("type jst;");
    EXPECT_TRUE(paper->needsMomentumLaplacian());
    EXPECT_TRUE(paper->needsMomentumBiLaplacian());
    EXPECT_FALSE(paper->needsJacobianLaplacian());
    EXPECT_FALSE(paper->actsOnJacobian());
    // D(p) = 0 * c h L[p] - (1/8) c h^3 L^2[p], c h^3 = 0.1: -0.0125 L^2[p].
    const Evaluated e = evaluate(*paper);
    const double k4 = 0.125 * 100 * 0.1 * 0.1 * 0.1;
    EXPECT_EQ(e.p, (std::vector<double>{-k4 * 10, -k4 * 20, k4 * 30, -k4 * 40}));
    EXPECT_EQ(e.J, std::vector<double>(2, -99.0));  // not written
    // Given coefficients: both terms on p and on J; c h = 10.
    const auto given = model("type jst; momentum (0.125 0.0625); jacobian (0.1 0.5);");
    EXPECT_TRUE(given->needsJacobianBiLaplacian());
    const Evaluated g = evaluate(*given);
    EXPECT_DOUBLE_EQ(g.p[0], 0.125 * 10 * 1 - 0.0625 * 0.1 * 10);
    EXPECT_DOUBLE_EQ(g.p[3], 0.125 * 10 * 4 - 0.0625 * 0.1 * 40);
    EXPECT_DOUBLE_EQ(g.J[0], 0.1 * 10 * 0.5 - 0.5 * 0.1 * 5);
    EXPECT_DOUBLE_EQ(g.J[1], 0.1 * 10 * -0.25 - 0.5 * 0.1 * 6);
    // artificialViscosity: (mu_vis / rho0) L[p], per particle's rho0; no bi-Laplacian, no J.
    const auto viscous = model("type artificialViscosity; viscosity 50;");
    EXPECT_FALSE(viscous->needsMomentumBiLaplacian());
    EXPECT_FALSE(viscous->actsOnJacobian());
    const Evaluated v = evaluate(*viscous);
    EXPECT_EQ(v.p, (std::vector<double>{0.05 * 1, 0.05 * -2, 0.025 * 3, 0.025 * 4}));
    // none asks for nothing and acts on nothing.
    const auto none = model("type none;");
    EXPECT_FALSE(none->actsOnMomentum() || none->actsOnJacobian() || none->needsMomentumLaplacian());
    // The RK2 stability floor eps4 > maxCo^3/8 is the jst model's warning (on c_p, whatever c_s/c_p).
    EXPECT_EQ(paper->stabilityWarning(0.3, 0.1, false), "");  // 1/8 > 0.3^3/8
    EXPECT_NE(model("type jst; momentum (0 0.003);")->stabilityWarning(0.3, 0.1, true).find("maxCo^3/8"),
              std::string::npos);
}

// momentumSpeed shear (issue 16): the momentum terms take c_s (20 here) instead of c_p (100), the J
// terms keep c_p; the default is the paper's c_p on both, so a plain `jst` is unchanged.
TEST(TlDissipationContract, MomentumSpeedShearScalesTheMomentumTermsWithTheShearSpeed) {
    const std::string coefficients = "momentum (0.125 0.0625); jacobian (0.1 0.5);";
    const Evaluated onP = evaluate(*model("type jst; momentumSpeed pressure; " + coefficients));
    const Evaluated byDefault = evaluate(*model("type jst; " + coefficients));
    EXPECT_EQ(onP.p, byDefault.p);
    EXPECT_EQ(onP.J, byDefault.J);
    const Evaluated onS = evaluate(*model("type jst; momentumSpeed shear; " + coefficients));
    // c_s h = 2, c_s h^3 = 0.02: D(p)_0 = 0.125 * 2 * 1 - 0.0625 * 0.02 * 10.
    EXPECT_DOUBLE_EQ(onS.p[0], 0.125 * 2 * 1 - 0.0625 * 0.02 * 10);
    EXPECT_DOUBLE_EQ(onS.p[3], 0.125 * 2 * 4 - 0.0625 * 0.02 * 40);
    for (int k = 0; k < 4; ++k) EXPECT_DOUBLE_EQ(onS.p[k], 0.2 * onP.p[k]) << k;  // c_s / c_p = 0.2
    EXPECT_EQ(onS.J, onP.J);                                                      // D(J) stays on c_p
    EXPECT_NE(model("type jst; momentumSpeed shear;")->describe().find("momentum on c_s"), std::string::npos);
    EXPECT_EQ(model("type jst;")->describe().find("c_s"), std::string::npos);

    // The pressure waves on c_s see eps4_p c_s/c_p + eps4_J (J evolved): warned below 1/16 (runs
    // blew up there) or when half of it is at the RK2 floor maxCo^3/8 (JstDissipation.cpp).
    // nu 0.45 (c_s/c_p = 1/3.32), {p,F}: 0.125/3.32 = 0.038 < 1/16, warned (conservative: the
    // plate and the bending column ran there).
    const auto shear = model("type jst; momentumSpeed shear;");
    EXPECT_NE(shear->stabilityWarning(0.3, 1 / 3.32, false), "");
    // nu 0.499 (c_s/c_p = 1/22.4) without D(J): 5.6e-3, warned (the 4 mm plate in {p,F,J} with
    // jacobian (0 0) grew its energy 2.5e5-fold by 0.2 s), with the remedies.
    const std::string pF = shear->stabilityWarning(0.3, 1 / 22.4, false);
    EXPECT_NE(pF.find("leaves the pressure waves eps4_p c_s/c_p + eps4_J = 0.005580"), std::string::npos)
        << pF;
    EXPECT_NE(pF.find("momentumSpeed pressure"), std::string::npos) << pF;
    EXPECT_NE(shear->stabilityWarning(0.3, 1 / 22.4, true), "");  // J evolved but eps4_J = 0
    // With eps4_J 1/8 in {p,F,J}: 0.131, no warning; the same model in {p,F} (its D(J) unused) is
    // warned; eps4_J 1/32 (0.037, the plate grew 2.3e3-fold) is warned, 1/16 (0.068, ran) not.
    const auto withJ = model("type jst; momentumSpeed shear; jacobian (0 0.125);");
    EXPECT_EQ(withJ->stabilityWarning(0.3, 1 / 22.4, true), "");
    EXPECT_NE(withJ->stabilityWarning(0.3, 1 / 22.4, false), "");
    EXPECT_NE(
        model("type jst; momentumSpeed shear; jacobian (0 0.03125);")->stabilityWarning(0.3, 1 / 22.4, true),
        "");
    EXPECT_EQ(
        model("type jst; momentumSpeed shear; jacobian (0 0.0625);")->stabilityWarning(0.3, 1 / 22.4, true),
        "");
    // The RK2 floor: at maxCo 0.85 (floor 0.0768) even 0.131 / 2 is below it.
    EXPECT_NE(withJ->stabilityWarning(0.85, 1 / 22.4, true).find("maxCo^3/8 = 0.0767"), std::string::npos);
    // The same coefficients on c_p are not warned (1/8 > 3.375e-3): the warning is the speed's.
    EXPECT_EQ(model("type jst;")->stabilityWarning(0.3, 1 / 22.4, false), "");
}

TEST(TlDissipationContract, BadEntriesNameTheEntry) {
    const std::string length = errorOf("type jst; momentum (0 0.125 1);");
    EXPECT_NE(length.find("momentum"), std::string::npos) << length;
    EXPECT_NE(length.find("expected 2 values"), std::string::npos) << length;
    const std::string negative = errorOf("type jst; jacobian (0 -1);");
    EXPECT_NE(negative.find(">= 0"), std::string::npos) << negative;
    const std::string missing = errorOf("type artificialViscosity;");
    EXPECT_NE(missing.find("missing keyword 'viscosity'"), std::string::npos) << missing;
    const std::string speed = errorOf("type jst; momentumSpeed bulk;");
    EXPECT_NE(speed.find("momentumSpeed"), std::string::npos) << speed;
    EXPECT_NE(speed.find("pressure"), std::string::npos) << speed;  // the valid choices
    EXPECT_NE(speed.find("shear"), std::string::npos) << speed;
}
