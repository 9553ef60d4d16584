#pragma once
// One run of a solver application on a case: opens the case, loads `libs`, reads the start time's
// particles, and runs the shared time loop. An application is
//
//     int main(int argc, char** argv) {
//         return mfdyn::runApplication(argc, argv, info, [](const mfdyn::Arguments& args) {
//             return mfdyn::runSolver<mfdyn::ParticleFlightSolver>(args, "particleFlight");
//         });
//     }
//
// where ParticleFlightSolver<Dim> is constructed from a SolverRun&.
//
// Earlier results are never touched before the input is known good. The constructor only reads
// (controlDict, libraries, the start time's particles and state, particles.pvd) and takes the
// case lock (core/CaseLock.hpp); the solver and its models are constructed next (runSolver);
// run() constructs the function objects and checks for never-read entries, and only then
// prepares the outputs: stale temporaries are swept, time directories later than the start are
// moved into abandoned.<N>/ and particles.pvd is cut after the start's exact time. The start
// directory is input and is never written.
//
// Under mpirun every rank runs this loop; the case's own files are rank 0's (the lock, the sweep
// and moves, particles.pvd, purgeWrite, the CSV files), each time is written in pieces
// (particles/TimeDirectory.hpp), and the start is read whole on every rank, however many ranks
// wrote it (particles/TimeDirectoryReader.hpp).
#include "core/Application.hpp"
#include "core/Case.hpp"
#include "core/Dictionary.hpp"
#include "core/Log.hpp"
#include "core/Time.hpp"
#include "particles/ParticleSet.hpp"

#include <memory>
#include <optional>
#include <string>

namespace mfdyn {

class CaseLock;
class Decomposition;
class PvdIndex;
class Solver;

class SolverRun {
public:
    SolverRun(const Arguments& args, std::string application);
    ~SolverRun();

    const std::string& application() const { return application_; }
    const Case& runCase() const { return case_; }
    Time& time() { return *time_; }
    const Time& time() const { return *time_; }
    const Dictionary& controlDict() const { return controlDict_; }
    const std::string& startTimeName() const { return startTimeName_; }
    int dimension() const { return particles_->dimension(); }
    // The particles read from the start time; the solver takes them over.
    std::unique_ptr<ParticleSetBase> takeParticles() { return std::move(particles_); }
    // The start time's state dictionary, if the start is a restart.
    const Dictionary* restartState() const { return state_ ? &*state_ : nullptr; }

    // The domain decomposition of a run on several ranks (system/decomposeParDict), which has
    // already kept this rank's share of the particles; nullptr on one process.
    Decomposition* decomposition() { return decomposition_.get(); }

    // Under mpirun with more than one rank: an InputError, the same on every rank.
    void refuseSeveralRanks() const;

    // The time loop; returns the exit status.
    int run(Solver& solver);

private:
    void decompose(const std::string& particleFile);
    void prepareOutputs();
    void write(Solver& solver);
    void purge();
    void checkUnusedEntries(const Solver& solver) const;
    // stepsRun: the steps of this run (not since t = 0), for the particle-steps/s figure.
    void summary(const Solver& solver, double steppingSeconds, std::int64_t stepsRun);

    std::string application_;
    Case case_;
    Dictionary controlDict_;
    std::unique_ptr<CaseLock> lock_;
    std::unique_ptr<Time> time_;
    std::string startTimeName_;
    double startDirectoryValue_ = 0;  // the start directory's name as a number (not its exact time)
    // particles.pvd, read once at start and rewritten (atomically) from memory at each write:
    // re-reading it at every write would cost time quadratic in the number of writes.
    std::unique_ptr<PvdIndex> pvd_;
    std::unique_ptr<ParticleSetBase> particles_;
    std::unique_ptr<Decomposition> decomposition_;
    std::optional<Dictionary> decomposeParDict_;
    std::optional<Dictionary> state_;
    Stopwatch clock_;
    double writeSeconds_ = 0;
    double setUpSeconds_ = 0;
    std::string lastWritten_;
    bool strictDictionaries_ = false;  // controlDict's strictDictionaries: never-read entries are errors
};

// A solver runs on several ranks when its class says `static constexpr bool runsOnSeveralRanks =
// true;` (issue 21: impactSph); any other is refused under mpirun before it is constructed (its
// set-up would see one rank's share of the particles) and before anything is written.
template <template <int> class SolverType>
constexpr bool runsOnSeveralRanks() {
    if constexpr (requires { SolverType<1>::runsOnSeveralRanks; })
        return SolverType<1>::runsOnSeveralRanks;
    else
        return false;
}

template <template <int> class SolverType>
int runSolver(const Arguments& args, const std::string& application) {
    SolverRun run(args, application);
    if (!runsOnSeveralRanks<SolverType>()) run.refuseSeveralRanks();
    return withDimension(run.dimension(), [&](auto dim) {
        SolverType<decltype(dim)::value> solver(run);
        return run.run(solver);
    });
}

}  // namespace mfdyn
