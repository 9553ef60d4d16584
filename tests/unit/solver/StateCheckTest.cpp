// Solver::checkState: every rank throws the same text, describing the bad particle of lowest
// global id on any rank, whatever the order of particles in memory; ghosts are not counted (they
// are images of particles judged where they are owned). On one process the global hooks return
// their argument, so what can fail is which particle is described, the count, and whether the
// message went through the one hook an MPI build fills (GlobalReduce::firstMessage).
#include "core/Application.hpp"
#include "core/Parallel.hpp"
#include "particles/ParticleSet.hpp"
#include "particles/TimeDirectory.hpp"
#include "solver/Solver.hpp"
#include "solver/SolverRun.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <numeric>

#include <unistd.h>

namespace mfdyn {
namespace {

namespace fs = std::filesystem;

// A method whose particles carry a `bad` flag from the start file; the first step checks it.
// constant/checkProperties: ghostOfLowestBad yes|no (a mirror ghost of that particle, with its
// flag, added before the check as a boundary condition would).
template <int Dim>
class CheckSolver final : public Solver {
public:
    explicit CheckSolver(SolverRun& run)
        : Solver(run),
          owner_(adoptParticleSet<Dim>(run.takeParticles())),
          ghost_(openConstant("checkProperties").get<bool>("ghostOfLowestBad")),
          bad_(owner_->scalarField("bad")) {}
    TimeStepVote stableTimeStep() override { return {0.1, "fixed"}; }
    void step(double) override {
        if (ghost_) {
            const auto& id = owner_->globalId();
            std::size_t lowest = owner_->size();
            for (std::size_t i = 0; i < owner_->size(); ++i)
                if (bad_[i] > 0 && (lowest == owner_->size() || id[i] < id[lowest])) lowest = i;
            owner_->addGhosts({lowest}, {Tensor<Dim>::Identity()});
        }
        messagesBefore = globalReductionCount.load();
        checkState(
            "check", bad_.size(), [&](std::size_t i) { return bad_[i] > 0; },
            [&](std::size_t i, double count) {
                return "particle " + std::to_string(owner_->globalId()[i]) + " is bad; " +
                       std::to_string(std::int64_t(count)) + " particles affected";
            });
    }
    ParticleSetBase& particles() override { return *owner_; }
    static inline std::uint64_t messagesBefore = 0;

private:
    std::unique_ptr<ParticleSet<Dim>> owner_;
    bool ghost_;
    std::vector<double>& bad_;
};

void writeFile(const fs::path& file, const std::string& text) {
    fs::create_directories(file.parent_path());
    std::ofstream(file) << text;
}

// Six particles with ids 10..15, stored in memory in the order `order` (order[k] is the id at
// index k); ids 14, 12 and 13 are bad, so the lowest bad id is 12.
fs::path makeCase(const std::string& name, const std::vector<std::int64_t>& order, bool ghost) {
    const fs::path dir =
        fs::temp_directory_path() / ("mfdyn-check-" + name + "-" + std::to_string(::getpid()));
    fs::remove_all(dir);
    writeFile(dir / "system/controlDict",
              "application check;\nstartFrom startTime;\nstartTime 0;\nstopAt endTime;\nendTime 1;\n"
              "deltaT 0.1;\nwriteControl timeStep;\nwriteInterval 100;\n");
    writeFile(dir / "constant/checkProperties",
              std::string("ghostOfLowestBad ") + (ghost ? "yes" : "no") + ";\n");
    ParticleSet<2> p(order.size());
    auto& bad = p.scalarField("bad");
    for (std::size_t k = 0; k < order.size(); ++k) {
        p.globalId()[k] = order[k];
        p.position()[k] = Vector<2>(0.1 * double(order[k]), 0);
        bad[k] = (order[k] == 12 || order[k] == 13 || order[k] == 14) ? 1 : 0;
    }
    writeTimeDirectory(dir, "0", p);
    return dir;
}

std::string runCheck(const fs::path& dir) {
    ApplicationInfo info{"check", "the state check test", {}, {}};
    std::string a0 = "check", a1 = "-case", a2 = dir.string();
    char* argv[] = {a0.data(), a1.data(), a2.data()};
    try {
        runSolver<CheckSolver>(Arguments::parse(3, argv, info), "check");
    } catch (const RunError& e) {
        return e.what();
    }
    return "no error";
}

TEST(StateCheck, TheBadParticleOfLowestGlobalIdIsDescribedWhateverTheOrderInMemory) {
    // Every arrangement of the six ids: before, the first bad particle in memory was described
    // (14 or 13 for most of them).
    std::vector<std::int64_t> order(6);
    std::iota(order.begin(), order.end(), 10);
    int arrangements = 0;
    do {
        if (++arrangements % 37 != 1) continue;  // 20 of the 720, spread over all of them
        const fs::path dir = makeCase("order", order, false);
        const std::string message = runCheck(dir);
        EXPECT_NE(message.find("phase check, step 1, t = 0: particle 12 is bad; 3 particles affected"),
                  std::string::npos)
            << message;
        // Two global calls: the count, and the one message every rank throws.
        EXPECT_EQ(globalReductionCount.load() - CheckSolver<2>::messagesBefore, 2u);
        fs::remove_all(dir);
    } while (std::next_permutation(order.begin(), order.end()));
    EXPECT_EQ(arrangements, 720);
}

TEST(StateCheck, AGhostOfABadParticleIsNotCountedAgain) {
    // The ghost is a copy of particle 12 (flag included) after the owned particles: still three
    // bad particles, and the owned 12 is the one described.
    const fs::path dir = makeCase("ghost", {15, 14, 13, 12, 11, 10}, true);
    const std::string message = runCheck(dir);
    EXPECT_NE(message.find("particle 12 is bad; 3 particles affected"), std::string::npos) << message;
    fs::remove_all(dir);
}

}  // namespace
}  // namespace mfdyn
