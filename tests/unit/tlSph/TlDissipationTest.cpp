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

// D(p) and D(J) of `m` on two particles in 2D with given Laplacians, c_p = 100, h = 0.1.
struct Evaluated {
    std::vector<double> p, J;
};
Evaluated evaluate(const TlDissipation& m) {
    const std::vector<double> rho0{1000, 2000}, lapP{1, -2, 3, 4}, lap2P{10, 20, -30, 40}, lapJ{0.5, -0.25},
        lap2J{5, 6};
    Evaluated out{std::vector<double>(4, -99.0), std::vector<double>(2, -99.0)};
    TlDissipation::Block b;
    b.size = 2, b.dimension = 2, b.waveSpeed = 100, b.spacing = 0.1, b.rho0 = rho0.data();
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
    // The RK2 stability floor eps4 > maxCo^3/8 is the jst model's warning.
    EXPECT_EQ(paper->stabilityWarning(0.3), "");  // 1/8 > 0.3^3/8
    EXPECT_NE(model("type jst; momentum (0 0.003);")->stabilityWarning(0.3).find("maxCo^3/8"),
              std::string::npos);
}

TEST(TlDissipationContract, BadEntriesNameTheEntry) {
    const std::string length = errorOf("type jst; momentum (0 0.125 1);");
    EXPECT_NE(length.find("momentum"), std::string::npos) << length;
    EXPECT_NE(length.find("expected 2 values"), std::string::npos) << length;
    const std::string negative = errorOf("type jst; jacobian (0 -1);");
    EXPECT_NE(negative.find(">= 0"), std::string::npos) << negative;
    const std::string missing = errorOf("type artificialViscosity;");
    EXPECT_NE(missing.find("missing keyword 'viscosity'"), std::string::npos) << missing;
}
