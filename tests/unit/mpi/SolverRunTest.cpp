// SolverRun on three ranks (solver/SolverRun.cpp): the case's own files are rank 0's (the lock,
// particles.pvd, the CSV files), each write is a time in pieces listed as <time>/particles.pvtp,
// a restart reads those pieces, and a signal that reaches one rank stops every rank after the
// same step. The method is the drift of tests/unit/solver/DriftSolverTest.cpp (x = x0 + v t,
// exact), each rank holding the share SolverRun's decomposition gives it.
#include "core/Application.hpp"
#include "core/CaseLock.hpp"
#include "core/Communicator.hpp"
#include "core/Parallel.hpp"
#include "particles/ParticleSet.hpp"
#include "particles/TimeDirectory.hpp"
#include "particles/TimeDirectoryReader.hpp"
#include "particles/VtpWriter.hpp"
#include "solver/Solver.hpp"
#include "solver/SolverRun.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>

namespace mfdyn {
namespace {

namespace fs = std::filesystem;

// The step after which rank 1 raises SIGTERM in itself (a signal that reached one rank only); -1: never.
int sigtermOnRank1AfterStep = -1;

template <int Dim>
class DriftShare final : public Solver {
public:
    // SolverRun's decomposition has kept this rank's share of the particles already.
    static constexpr bool runsOnSeveralRanks = true;
    explicit DriftShare(SolverRun& run)
        : Solver(run),
          owner_(adoptParticleSet<Dim>(run.takeParticles())),
          properties_(openConstant("driftProperties")),
          lengthScale_(properties_.get<double>("lengthScale")),
          x_(owner_->position()),
          v_(owner_->vectorField("velocity")) {}
    TimeStepVote stableTimeStep() override {
        const double vmax =
            std::sqrt(GlobalReduce::max(v_.size(), [&](std::size_t i) { return v_[i].squaredNorm(); }));
        return {time().maxCo() * lengthScale_ / vmax, "Courant"};
    }
    void step(double dt) override {
        for (std::size_t i = 0; i < x_.size(); ++i) x_[i] += dt * v_[i];
        if (++steps_ == sigtermOnRank1AfterStep && Communicator::rank() == 1) std::raise(SIGTERM);
    }
    ParticleSetBase& particles() override { return *owner_; }

private:
    std::unique_ptr<ParticleSet<Dim>> owner_;
    const Dictionary& properties_;
    double lengthScale_;
    std::vector<Vector<Dim>>& x_;
    std::vector<Vector<Dim>>& v_;
    long steps_ = 0;
};

constexpr std::size_t particleCount = 7;

Vector<3> startPosition(std::size_t id) {
    return Vector<3>(0.1 * double(id), -0.3, 1.0 / 3.0);
}
Vector<3> velocity(std::size_t id) {
    return Vector<3>(1.0 + double(id), -0.7 * double(id), 0.25);
}

void writeText(const fs::path& file, const std::string& text) {
    fs::create_directories(file.parent_path());
    std::ofstream(file) << text;
}

std::string readText(const fs::path& file) {
    std::ifstream in(file);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

// A case in rank 0's scratch directory (its pid broadcast, so every rank names the same one),
// with 0/particles.vtp as particleGen writes it: one file, every particle.
fs::path makeCase(const std::string& name, double endTime) {
    int pid = ::getpid();
    Communicator::broadcast(&pid, sizeof pid, 0);
    const fs::path dir = fs::temp_directory_path() / ("mfdynMpi-" + name + "-" + std::to_string(pid));
    if (Communicator::rank() == 0) {
        fs::remove_all(dir);
        writeText(dir / "system/controlDict",
                  "application drift;\nstartFrom latestTime;\nstartTime 0;\nstopAt endTime;\nendTime " +
                      std::to_string(endTime) +
                      ";\ndeltaT 0.01;\nadjustTimeStep yes;\nmaxCo 0.5;\nwriteControl adjustableRunTime;\n"
                      "writeInterval 0.5;\nwritePrecision 6;\nstrictDictionaries yes;\n");
        writeText(dir / "constant/driftProperties", "lengthScale 0.1;\n");
        ParticleSet<3> p(particleCount);
        auto& v = p.vectorField("velocity");
        auto& m = p.scalarField("mass");
        auto& rho = p.scalarField("density");
        for (std::size_t i = 0; i < particleCount; ++i) {
            p.globalId()[i] = std::int64_t(i);
            p.position()[i] = startPosition(i);
            v[i] = velocity(i);
            m[i] = 1.0, rho[i] = 1000;
        }
        fs::create_directories(dir / "0");
        writeVtp(dir / "0" / particleFileName, p, 0.0);
    }
    Communicator::barrier();
    return dir;
}

// Returns once every rank has finished: rank 0 releases the lock and closes its CSV files as its
// SolverRun ends, which may be after the others have returned.
int runDrift(const fs::path& dir) {
    ApplicationInfo info{"drift", "the SolverRun test on several ranks", {}, {}};
    std::string a0 = "drift", a1 = "-case", a2 = dir.string();
    char* argv[] = {a0.data(), a1.data(), a2.data()};
    const Arguments args = Arguments::parse(3, argv, info);
    const int status = runSolver<DriftShare>(args, "drift");
    Communicator::barrier();
    return status;
}

void setEndTime(const fs::path& dir, double endTime) {
    if (Communicator::rank() == 0) {
        std::string text = readText(dir / "system/controlDict");
        const std::size_t at = text.find("endTime ");
        text.replace(at, text.find(';', at) - at, "endTime " + std::to_string(endTime));
        writeText(dir / "system/controlDict", text);
    }
    Communicator::barrier();
}

// The particles at `time` are where the exact drift puts them, in id order, whichever ranks wrote them.
void expectDriftedTo(const fs::path& timeDir, double time) {
    const ParticleFile file = readTimeParticles(timeDir);
    ASSERT_EQ(file.particles->size(), particleCount);
    const auto& p = particleSetCast<3>(*file.particles);
    for (std::size_t i = 0; i < particleCount; ++i) {
        EXPECT_EQ(p.globalId()[i], std::int64_t(i));
        // The steps sum to `time` to round-off; a step lost or taken twice moves a particle ~0.05.
        EXPECT_LT((p.position()[i] - (startPosition(i) + time * velocity(i))).norm(), 1e-12) << "id " << i;
    }
}

std::size_t lineCount(const std::string& text) {
    return std::size_t(std::count(text.begin(), text.end(), '\n'));
}

TEST(SolverRunOnRanks, WritesPiecesListsTheIndexAndRestartsFromThem) {
    const fs::path dir = makeCase("run", 0.5);
    ASSERT_EQ(runDrift(dir), 0);
    expectDriftedTo(dir / "0.5", 0.5);
    EXPECT_TRUE(fs::exists(dir / "0.5" / "particles.pvtp"));
    EXPECT_TRUE(fs::exists(dir / "0.5" / "state"));
    EXPECT_FALSE(fs::exists(dir / CaseLock::fileName)) << "rank 0's lock is released at the end";

    // The run's own files were written once, by rank 0: one header and one row, the particles of
    // every rank counted.
    const std::string summary = readText(dir / "postProcessing/runSummary/0/runSummary.csv");
    EXPECT_EQ(lineCount(summary), 2u) << summary;
    std::string header, row;
    std::istringstream(summary) >> header >> row;
    EXPECT_EQ(header, "time,field,L1,L2,Linf,wallTime,steps,particles,threads,particleStepsPerSecond");
    std::vector<std::string> cells;
    std::istringstream cellStream(row);
    for (std::string cell; std::getline(cellStream, cell, ',');) cells.push_back(cell);
    EXPECT_EQ(cells.size(), 10u) << row;
    if (cells.size() == 10u)
        EXPECT_EQ(cells[7], std::to_string(particleCount)) << "the global count, not rank 0's share";
    // health.csv (on by default): its header once and each time once, as one writer leaves it.
    std::istringstream health(readText(dir / "postProcessing/health/0/health.csv"));
    std::string healthHeader;
    std::getline(health, healthHeader);
    EXPECT_EQ(healthHeader.rfind("time,", 0), 0u) << healthHeader;
    double previous = -1;
    std::size_t rows = 0;
    for (std::string line; std::getline(health, line); ++rows) {
        const double t = std::stod(line.substr(0, line.find(',')));
        EXPECT_GT(t, previous) << "a row written twice: " << line;
        previous = t;
    }
    EXPECT_GE(rows, 1u);

    // A restart on the same ranks reads the pieces and lists its time as an index too.
    setEndTime(dir, 1.0);
    ASSERT_EQ(runDrift(dir), 0);
    expectDriftedTo(dir / "1", 1.0);
    const std::string pvd = readText(dir / "particles.pvd");
    EXPECT_NE(pvd.find("file=\"0/particles.vtp\""), std::string::npos) << pvd;
    EXPECT_NE(pvd.find("file=\"0.5/particles.pvtp\""), std::string::npos) << pvd;
    EXPECT_NE(pvd.find("file=\"1/particles.pvtp\""), std::string::npos) << pvd;
    EXPECT_EQ(pvd.find("particles.vtp\"", pvd.find("0.5/")), std::string::npos) << pvd;
    Communicator::barrier();
    if (Communicator::rank() == 0) fs::remove_all(dir);
}

// Last in this file: a signal handler, once it has fired, stays fired for the process.
TEST(SolverRunOnRanks, ASignalToOneRankStopsEveryRankAfterTheSameStep) {
    const fs::path dir = makeCase("signal", 1.0);
    sigtermOnRank1AfterStep = 20;
    const int status = runDrift(dir);
    sigtermOnRank1AfterStep = -1;
    EXPECT_EQ(status, 128 + SIGTERM) << "every rank ends as stopped by SIGTERM";
    // Every rank wrote the state after step 20: one time directory besides 0, complete, and exact.
    std::vector<std::string> times;
    for (const auto& e : fs::directory_iterator(dir))
        if (e.is_directory() && e.path().filename() != "0" && e.path().filename() != "system" &&
            e.path().filename() != "constant" && e.path().filename() != "postProcessing")
            times.push_back(e.path().filename().string());
    ASSERT_EQ(times.size(), 1u);
    const std::string state = readText(dir / times[0] / "state");
    std::istringstream index(state.substr(std::min(state.find("timeIndex"), state.size())));
    std::string keyword, steps;
    index >> keyword >> steps;
    EXPECT_EQ(steps, "20;") << "written after the step the signal came in: " << state;
    const ParticleFile file = readTimeParticles(dir / times[0]);
    ASSERT_TRUE(file.hasTime);
    expectDriftedTo(dir / times[0], file.time);
    Communicator::barrier();
    if (Communicator::rank() == 0) fs::remove_all(dir);
}

}  // namespace
}  // namespace mfdyn
