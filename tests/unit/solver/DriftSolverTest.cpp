// The solver template (issue 15): a whole method on the shared scaffolding, as a new method
// starts. Particles drift at their constant velocity, so the answer is exact: x = x0 + v t.
// Everything a method needs beyond its physics comes from Solver: its dictionary opened and
// checked for never-read entries, the mass check, named phase timing, the state check every
// process agrees on, the topology hook before each step and a file beside particles.vtp.
#include "core/Application.hpp"
#include "particles/ParticleSet.hpp"
#include "particles/TimeDirectory.hpp"
#include "particles/VtpReader.hpp"
#include "particles/VtpWriter.hpp"
#include "solver/Solver.hpp"
#include "solver/SolverRun.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>

#include <unistd.h>

namespace mfdyn {
namespace {

// ---- the method: 40 lines ---------------------------------------------------------------------
// constant/driftProperties: lengthScale 0.1;   // Co = |v| dt / lengthScale
template <int Dim>
class DriftSolver final : public Solver {
public:
    explicit DriftSolver(SolverRun& run)
        : Solver(run),
          owner_(adoptParticleSet<Dim>(run.takeParticles())),
          properties_(openConstant("driftProperties")),
          lengthScale_(properties_.get<double>("lengthScale")),
          x_(owner_->position()),
          v_(owner_->vectorField("velocity")) {
        if (!(lengthScale_ > 0)) throw properties_.error("lengthScale", "lengthScale must be positive");
        checkPositiveMassAndDensity(*owner_, requireScalarField(*owner_, "mass", "particle masses"),
                                    requireScalarField(*owner_, "density", "particle densities"));
    }
    void preStep() override { ++preSteps_; }
    TimeStepVote stableTimeStep() override {
        const double vmax =
            std::sqrt(GlobalReduce::max(v_.size(), [&](std::size_t i) { return v_[i].squaredNorm(); }));
        return {vmax > 0 ? time().maxCo() * lengthScale_ / vmax : std::numeric_limits<double>::infinity(),
                "Courant"};
    }
    void step(double dt) override {
        {
            auto timed = phase("drift");
            parallelFor(x_.size(), [&](std::size_t i) { x_[i] += dt * v_[i]; });
        }
        checkState(
            "drift", x_.size(), [&](std::size_t i) { return !x_[i].allFinite(); },
            [&](std::size_t i, double count) {
                return "particle " + std::to_string(owner_->globalId()[i]) + " left the finite numbers; " +
                       std::to_string(count) + " particles affected";
            });
    }
    ParticleSetBase& particles() override { return *owner_; }
    std::vector<ExtraFile> extraOutput() const override {
        return {{"driftLog", "preSteps " + std::to_string(preSteps_) + ";\n"}};
    }

private:
    std::unique_ptr<ParticleSet<Dim>> owner_;
    const Dictionary& properties_;
    double lengthScale_;
    std::vector<Vector<Dim>>& x_;
    std::vector<Vector<Dim>>& v_;
    long preSteps_ = 0;
};
// ---- end of the method -----------------------------------------------------------------------

namespace fs = std::filesystem;

void writeFile(const fs::path& file, const std::string& text) {
    fs::create_directories(file.parent_path());
    std::ofstream(file) << text;
}

// A case of five particles in 3D with different velocities, run to t = 1 in steps of Co 0.5.
fs::path makeCase(const std::string& name, const std::string& properties, double mass = 1.0) {
    const fs::path dir =
        fs::temp_directory_path() / ("mfdyn-drift-" + name + "-" + std::to_string(::getpid()));
    fs::remove_all(dir);
    writeFile(dir / "system/controlDict",
              "application drift;\nstartFrom startTime;\nstartTime 0;\nstopAt endTime;\nendTime 1;\n"
              "deltaT 0.01;\nadjustTimeStep yes;\nmaxCo 0.5;\nwriteControl adjustableRunTime;\n"
              "writeInterval 0.5;\nwritePrecision 6;\nstrictDictionaries yes;\n");
    writeFile(dir / "constant/driftProperties", properties);
    ParticleSet<3> p(5);
    auto& v = p.vectorField("velocity");
    auto& m = p.scalarField("mass");
    auto& rho = p.scalarField("density");
    for (std::size_t i = 0; i < 5; ++i) {
        p.globalId()[i] = std::int64_t(i);
        p.position()[i] = Vector<3>(0.1 * double(i), -0.3, 1.0 / 3.0);
        v[i] = Vector<3>(1.0 + double(i), -0.7 * double(i), 0.25);
        m[i] = i == 4 ? mass : 1.0, rho[i] = 1000;
    }
    writeTimeDirectory(dir, "0", p);
    return dir;
}

int runDrift(const fs::path& dir) {
    ApplicationInfo info{"drift", "the solver template test", {}, {}};
    std::string a0 = "drift", a1 = "-case", a2 = dir.string();
    char* argv[] = {a0.data(), a1.data(), a2.data()};
    const Arguments args = Arguments::parse(3, argv, info);
    return runSolver<DriftSolver>(args, "drift");
}

TEST(SolverTemplate, DriftingParticlesLandWhereTheExactAnswerSays) {
    const fs::path dir = makeCase("exact", "lengthScale 0.1;\n");
    ASSERT_EQ(runDrift(dir), 0);
    // x(1) = x0 + v: the steps sum to 1 to round-off, so 1e-12 is far below any real error
    // (a step lost or taken twice moves a particle by about |v| dt ~ 0.05).
    const ParticleFile result = readVtp(dir / "1" / particleFileName);
    const auto& x = particleSetCast<3>(*result.particles).position();
    ASSERT_EQ(x.size(), 5u);
    for (std::size_t i = 0; i < 5; ++i) {
        const Vector<3> exact =
            Vector<3>(0.1 * double(i), -0.3, 1.0 / 3.0) + Vector<3>(1.0 + double(i), -0.7 * double(i), 0.25);
        EXPECT_LT((x[i] - exact).norm(), 1e-12) << "particle " << i;
    }
    // The hook ran before every step, and its file was written with the time directory: the
    // fastest particle (|v| = 5.8) limits dt to 0.5 * 0.1 / 5.8, so at least 116 steps to t = 1.
    std::ifstream log(dir / "1" / "driftLog");
    std::string word;
    long preSteps = 0;
    log >> word >> preSteps;
    EXPECT_EQ(word, "preSteps");
    EXPECT_GE(preSteps, 116);
    EXPECT_LE(preSteps, 120);  // the write times at 0.5 and 1 may each add a shortened step
    fs::remove_all(dir);
}

TEST(SolverTemplate, ARunStartsFromATimeWrittenInPieces) {
    // 0/ as a run on three ranks leaves a time (particles.pvtp and one piece per rank, ids dealt
    // out id % 3): one process reads every piece, and writes its own times as particles.vtp.
    const fs::path dir = makeCase("pieces", "lengthScale 0.1;\n");
    const ParticleFile whole = readVtp(dir / "0" / particleFileName);
    std::vector<std::string> pieces;
    for (int rank = 0; rank < 3; ++rank) {
        auto piece = whole.particles->clone();
        std::vector<std::size_t> mine;
        for (std::size_t i = 0; i < piece->size(); ++i)
            if (piece->requireField<std::int64_t>("globalId")[i] % 3 == rank) mine.push_back(i);
        piece->keep(mine);
        pieces.push_back(particlePieceFileName(rank));
        writeVtp(dir / "0" / pieces.back(), *piece, 0.0);
    }
    writePvtp(dir / "0" / particleIndexFileName, *whole.particles, pieces);
    fs::remove(dir / "0" / particleFileName);

    ASSERT_EQ(runDrift(dir), 0);
    const ParticleFile result = readVtp(dir / "1" / particleFileName);
    const auto& x = particleSetCast<3>(*result.particles).position();
    ASSERT_EQ(x.size(), 5u);
    for (std::size_t i = 0; i < 5; ++i) {
        const Vector<3> exact =
            Vector<3>(0.1 * double(i), -0.3, 1.0 / 3.0) + Vector<3>(1.0 + double(i), -0.7 * double(i), 0.25);
        EXPECT_LT((x[i] - exact).norm(), 1e-12) << "particle " << i;  // as in the test above
    }
    std::ifstream in(dir / "particles.pvd");
    const std::string pvd((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    EXPECT_NE(pvd.find("file=\"0/particles.pvtp\""), std::string::npos) << "the start as it is: " << pvd;
    EXPECT_NE(pvd.find("file=\"0.5/particles.vtp\""), std::string::npos) << pvd;
    EXPECT_NE(pvd.find("file=\"1/particles.vtp\""), std::string::npos) << pvd;
    EXPECT_FALSE(fs::exists(dir / "1" / particleIndexFileName));
    fs::remove_all(dir);
}

TEST(SolverTemplate, TheMethodsDictionaryIsCheckedForNeverReadEntries) {
    // strictDictionaries yes: an entry the method did not read fails the run before any step,
    // because openConstant recorded driftProperties for the check.
    const fs::path dir = makeCase("unread", "lengthScale 0.1;\nlenghtScale 0.2;\n");
    try {
        runDrift(dir);
        FAIL() << "a never-read entry under strictDictionaries must be an InputError";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("'lenghtScale' was never read"), std::string::npos) << e.what();
    }
    EXPECT_FALSE(fs::exists(dir / "0.5"));
    fs::remove_all(dir);
}

TEST(SolverTemplate, ANonPositiveMassIsAnInputErrorNamingTheParticle) {
    const fs::path dir = makeCase("mass", "lengthScale 0.1;\n", -1.0);
    try {
        runDrift(dir);
        FAIL() << "a negative mass must be refused";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("particle 4 has mass -1"), std::string::npos) << e.what();
    }
    fs::remove_all(dir);
}

TEST(SolverTemplate, ATinyNegativeMassIsShownAsItIs) {
    // std::to_string wrote -1e-20 as -0.000000, a message that contradicts itself.
    const fs::path dir = makeCase("tinyMass", "lengthScale 0.1;\n", -1e-20);
    try {
        runDrift(dir);
        FAIL() << "a negative mass must be refused";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("particle 4 has mass -1e-20 and density 1000:"),
                  std::string::npos)
            << e.what();
    }
    fs::remove_all(dir);
}

}  // namespace
}  // namespace mfdyn
