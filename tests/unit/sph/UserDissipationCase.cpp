// A dissipation model written outside libraries/sph, as a user library writes one (Dissipation.hpp,
// SphPairLoop.hpp): selected by name from sphProperties, its pair terms run inside impactSph's
// fused pair loop and change the rates as its equations say. A separate test program, so that the
// model is not registered beside the built-in ones of sphTests (whose contract test lists them).
//
// The model `testConstantPair`: for every pair within either support,
//     m_i dv_i/dt += K m_i m_j r̂_ij,   dρ_i/dt += Q,
// and prepare() counts the rate evaluations. The case: two particles at rest, 1D, d = 5 mm apart,
// each of mass m, Tait water at ρ0 (so P = B((ρ/ρ0)^7 − 1) = 0 exactly and every other term of
// the loop is zero: v = 0 gives no continuity term, P = 0 no pressure force). One leapfrog step
// of Δt from rest gives v = Δt f exactly (v^{1/2} = f Δt/2, v^1 = v^{1/2} + f Δt/2):
//     v_0 = −Δt K m,  v_1 = +Δt K m  (r̂_01 = −1),   ρ = ρ0 + Δt Q.
#include "core/Application.hpp"
#include "particles/ParticleSet.hpp"
#include "particles/TimeDirectory.hpp"
#include "particles/VtpReader.hpp"
#include "solver/SolverRun.hpp"
#include "sph/Dissipation.hpp"
#include "sph/SphPairLoop.hpp"
#include "sph/SphSolver.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include <unistd.h>

namespace mfdyn {
namespace {

// ---- the user's model: its schema, its pair terms, its dispatch ------------------------------
class ConstantPairDissipation final : public Dissipation {
public:
    static KeywordSchema keywords() {
        return KeywordSchema(familyName, "testConstantPair")
            .scalar("K", "m/(kg s^2)", "pair force coefficient: m_i dv_i/dt += K m_i m_j r_hat")
            .scalar("Q", "kg/(m^3 s)", "density rate added per pair");
    }
    explicit ConstantPairDissipation(const Dictionary& dict) : Dissipation(dict) {
        const KeywordValues v = keywords().read(dict);
        K_ = v.scalar("K");
        Q_ = v.scalar("Q");
    }
    void computeRates(SphPairLoop<1>& loop) override { loop.run(*this); }
    void computeRates(SphPairLoop<2>& loop) override { loop.run(*this); }
    void computeRates(SphPairLoop<3>& loop) override { loop.run(*this); }

    template <int Dim>
    void prepare(const SphPairLoop<Dim>&) {
        ++rateEvaluations;
    }
    template <int Dim>
    void pair(const SphPairLoop<Dim>& loop, const SphPair<Dim>& q, SphPairSums<Dim>& s) const {
        s.force += (K_ * q.mi * loop.m[q.j]) * q.rhat;
        s.massFlux += Q_;
    }

    static inline int rateEvaluations = 0;

private:
    double K_ = 0, Q_ = 0;
};

MFDYN_REGISTER(Dissipation, ConstantPairDissipation, "testConstantPair",
               "test: constant pair force and density rate");
// ---- end of the model --------------------------------------------------------------------------

namespace fs = std::filesystem;

constexpr double mass = 5.0, rho0 = 1000.0, d = 5e-3, dt = 1e-6, K = 3.0, Q = 7.0;

void writeFile(const fs::path& file, const std::string& text) {
    fs::create_directories(file.parent_path());
    std::ofstream(file) << text;
}

fs::path makeCase(const std::string& name, const std::string& dissipation) {
    const fs::path dir =
        fs::temp_directory_path() / ("mfdyn-userDissipation-" + name + "-" + std::to_string(::getpid()));
    fs::remove_all(dir);
    writeFile(dir / "system/controlDict",
              "application impactSph;\nstartFrom startTime;\nstartTime 0;\nstopAt endTime;\nendTime 1e-6;\n"
              "deltaT 1e-6;\nadjustTimeStep no;\nmaxCo 0.2;\nwriteControl timeStep;\nwriteInterval 1;\n"
              "writePrecision 17;\nstrictDictionaries yes;\n");
    writeFile(dir / "constant/sphProperties",
              "kernel { type wendlandC2; }\ndensityScheme { type mass; form continuity; gradH no; }\n"
              "smoothingLength { type fixed; eta 1.2; h 0.004; }\ndissipation " +
                  dissipation + "\n");
    writeFile(dir / "constant/materialProperties",
              "materials { water { equationOfState { type tait; rho0 1000; c0 10; gamma 7; } } }\n");
    ParticleSet<1> p(2);
    auto& m = p.scalarField("mass");
    auto& rho = p.scalarField("density");
    p.vectorField("velocity");
    for (std::size_t i = 0; i < 2; ++i) {
        p.globalId()[i] = std::int64_t(i);
        p.position()[i] = Vector<1>(double(i) * d);
        m[i] = mass, rho[i] = rho0;
    }
    writeTimeDirectory(dir, "0", p);
    return dir;
}

int runImpactSph(const fs::path& dir) {
    ApplicationInfo info{"impactSph", "the user dissipation test", {}, {}};
    std::string a0 = "impactSph", a1 = "-case", a2 = dir.string();
    char* argv[] = {a0.data(), a1.data(), a2.data()};
    const Arguments args = Arguments::parse(3, argv, info);
    return runSolver<SphSolver>(args, "impactSph");
}

// The particles of the last time directory.
ParticleFile lastTime(const fs::path& dir) {
    const auto times = listTimeDirectories(dir);
    EXPECT_FALSE(times.empty());
    return readVtp(dir / times.back().second / particleFileName);
}

TEST(UserDissipation, AModelOutsideTheLibraryIsSelectedByNameAndRunsInThePairLoop) {
    ConstantPairDissipation::rateEvaluations = 0;
    const fs::path dir = makeCase("constant", "{ type testConstantPair; K 3; Q 7; }");
    ASSERT_EQ(runImpactSph(dir), 0);
    const ParticleFile result = lastTime(dir);
    auto& set = particleSetCast<1>(*result.particles);
    const auto& v = set.vectorField("velocity");
    const auto& rho = set.scalarField("density");
    ASSERT_EQ(v.size(), 2u);
    // Closed form above; 1e-12 relative leaves room for the division by m_i only (an ulp), while
    // a lost term, a doubled one or a wrong sign is off by 100%.
    const double speed = dt * K * mass;  // 1.5e-5 m/s
    EXPECT_NEAR(v[0][0], -speed, 1e-12 * speed);
    EXPECT_NEAR(v[1][0], +speed, 1e-12 * speed);
    for (std::size_t i = 0; i < 2; ++i) EXPECT_NEAR(rho[i], rho0 + dt * Q, 1e-12 * rho0) << i;
    // One rate evaluation for the one leapfrog step (the step's rates are those of the time-step
    // vote): prepare() ran once, through the virtual dispatch.
    EXPECT_EQ(ConstantPairDissipation::rateEvaluations, 1);
    fs::remove_all(dir);
}

TEST(UserDissipation, WithoutDissipationTheSameCaseStaysAtRest) {
    // The reference of the test above: the model's terms are the only ones that move the pair.
    const fs::path dir = makeCase("none", "{ type none; }");
    ASSERT_EQ(runImpactSph(dir), 0);
    const ParticleFile result = lastTime(dir);
    auto& set = particleSetCast<1>(*result.particles);
    for (std::size_t i = 0; i < 2; ++i) {
        EXPECT_EQ(set.vectorField("velocity")[i][0], 0.0) << i;
        EXPECT_EQ(set.scalarField("density")[i], rho0) << i;
    }
    fs::remove_all(dir);
}

}  // namespace
}  // namespace mfdyn
