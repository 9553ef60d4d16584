// tlSph's body force is the shared bodyForce family (issue 15 item 4): E_a = rho0 a(x, t).
//
// A free, unstressed body under uniform gravity falls as one: F = I, P = 0 and p uniform make the
// internal force and the Laplacians of the JST dissipation vanish exactly, so every particle sees
// dv/dt = g. The TVD RK2 of a constant acceleration is exact:
//     v* = v + dt g,            x* = x + dt v
//     v' = (v + v* + dt g)/2 = v + dt g
//     x' = (x + x* + dt v*)/2 = x + dt v + dt^2 g / 2
// so x(t) = x0 + v0 t + g t^2 / 2 up to rounding. Each step rounds x, v and the time at a few
// ulps of their size: after N steps the error is at most about 4 N eps max(|x|, |v| t, |g| t^2)
// (eps = 2.2e-16). Here N < 200 and the sizes are below 1, so 1e-12 is above any rounding by
// a factor of 5 and far below a real error: a step's g t term missed or doubled moves x by
// |g| t dt ~ 1e-4.
#include "core/Application.hpp"
#include "particles/ParticleSet.hpp"
#include "particles/TimeDirectory.hpp"
#include "particles/VtpReader.hpp"
#include "solver/SolverRun.hpp"
#include "tlSph/TlDissipation.hpp"
#include "tlSph/TlSphSolver.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include <unistd.h>

using namespace mfdyn;

namespace {

namespace fs = std::filesystem;

void writeFile(const fs::path& file, const std::string& text) {
    fs::create_directories(file.parent_path());
    std::ofstream(file) << text;
}

const Vector<3> v0(0.3, -0.2, 0.1);
const Vector<3> g(0.5, -9.81, 0.25);

// A 4 x 4 x 4 block of steel, spacing 0.1, moving at v0, with `properties` as tlSphProperties.
fs::path makeCase(const std::string& name, const std::string& properties) {
    const fs::path dir =
        fs::temp_directory_path() / ("mfdyn-tlsph-" + name + "-" + std::to_string(::getpid()));
    fs::remove_all(dir);
    writeFile(dir / "system/controlDict",
              "application tlSph;\nstartFrom startTime;\nstartTime 0;\nstopAt endTime;\nendTime 0.002;\n"
              "deltaT 1e-5;\nadjustTimeStep yes;\nmaxCo 0.3;\nwriteControl adjustableRunTime;\n"
              "writeInterval 0.002;\nwritePrecision 8;\n");
    writeFile(dir / "constant/tlSphProperties", properties);
    writeFile(dir / "constant/materialProperties",
              "materials { steel { rho0 8000; youngsModulus 2e11; poissonRatio 0.3; "
              "constitutiveLaw { type linearElastic; } } }\n");
    ParticleSet<3> p(64);
    auto& v = p.vectorField("velocity");
    auto& m = p.scalarField("mass");
    auto& rho = p.scalarField("density");
    for (std::size_t i = 0; i < 64; ++i) {
        p.globalId()[i] = std::int64_t(i);
        p.position()[i] = 0.1 * Vector<3>(double(i % 4), double(i / 4 % 4), double(i / 16));
        v[i] = v0;
        rho[i] = 8000, m[i] = 8000 * 1e-3;
    }
    writeTimeDirectory(dir, "0", p);
    return dir;
}

int runTlSph(const fs::path& dir) {
    ApplicationInfo info{"tlSph", "the tlSph body-force test", {}, {}};
    std::string a0 = "tlSph", a1 = "-case", a2 = dir.string();
    char* argv[] = {a0.data(), a1.data(), a2.data()};
    const Arguments args = Arguments::parse(3, argv, info);
    return runSolver<TlSphSolver>(args, "tlSph");
}

const std::string base =
    "formulation pF;\nkernel { type wendlandC2; }\n"
    "dissipation { type jst; momentum (0.03125 0.125); }\n";

// A dissipation model defined here, outside the library, selected by name: D(p) = rho0 a_push, a
// uniform push that stands in for gravity (no Laplacian asked for).
class TestPush final : public TlDissipation {
public:
    static KeywordSchema keywords() { return KeywordSchema(familyName, "testPush"); }
    explicit TestPush(const Dictionary& dict) { keywords().read(dict); }
    bool actsOnMomentum() const override { return true; }
    void evaluate(const Block& b) const override {
        for (std::size_t a = 0; a < b.size; ++a)
            for (int i = 0; i < b.dimension; ++i) b.dissipationP[a * b.dimension + i] = b.rho0[a] * g[i];
    }
    std::string describe() const override { return "testPush"; }
};
MFDYN_REGISTER(TlDissipation, TestPush, "testPush", "test: D(p) = rho0 g");

// Runs `dir` and checks x = X + v0 t + g t^2/2, v = v0 + g t at t = 0.002 (see the top).
void expectFall(const fs::path& dir) {
    const ParticleFile result = readVtp(dir / "0.002" / particleFileName);
    const auto& set = particleSetCast<3>(*result.particles);
    const auto& x = set.position();
    const auto& X = set.requireField<Vector<3>>("referencePosition");
    const auto& v = set.requireField<Vector<3>>("velocity");
    ASSERT_EQ(x.size(), 64u);
    const double t = 0.002;
    for (std::size_t i = 0; i < 64; ++i) {
        EXPECT_LT((x[i] - (X[i] + v0 * t + 0.5 * g * t * t)).norm(), 1e-12) << "particle " << i;
        EXPECT_LT((v[i] - (v0 + g * t)).norm(), 1e-12) << "particle " << i;
    }
}

}  // namespace

// (issue 15 item 6a) The solver hands the model its block and applies the D(p) it writes: with the
// momentum projections off (they would remove a uniform force), the push moves the body as gravity.
TEST(BodyForce, aDissipationModelDefinedOutsideTheLibraryIsSelectedByNameAndItsDpApplied) {
    const fs::path dir = makeCase("userDissipation",
                                  "formulation pF;\nkernel { type wendlandC2; }\n"
                                  "dissipation { type testPush; }\n"
                                  "projection { momentum no; dissipation no; }\n");
    ASSERT_EQ(runTlSph(dir), 0);
    expectFall(dir);
    fs::remove_all(dir);
}

TEST(BodyForce, aFreeBodyUnderUniformGravityFallsExactlyAsAParticle) {
    const fs::path dir =
        makeCase("gravity", base + "bodyForce { type uniformGravity; g (0.5 -9.81 0.25); }\n");
    ASSERT_EQ(runTlSph(dir), 0);
    expectFall(dir);
    fs::remove_all(dir);
}

TEST(BodyForce, theOldGravityKeywordIsAnInputErrorNamingBodyForce) {
    const fs::path dir = makeCase("oldGravity", base + "gravity (0 -9.81 0);\n");
    try {
        runTlSph(dir);
        ADD_FAILURE() << "gravity in tlSphProperties was accepted";
    } catch (const InputError& e) {
        const std::string what = e.what();
        EXPECT_NE(what.find("tlSphProperties:4"), std::string::npos) << what;  // the gravity line
        EXPECT_NE(what.find("bodyForce { type uniformGravity;"), std::string::npos) << what;
        EXPECT_NE(what.find("valid types: "), std::string::npos) << what;
    }
    EXPECT_FALSE(fs::exists(dir / "0.002"));
    fs::remove_all(dir);
}
