#pragma once
// The base of every method's solver. A solver is a RunContext (what function objects see) plus
// the two things the time loop asks of it each step:
//
//     TimeStepVote stableTimeStep()   how large the next step may be, and what limits it
//     void step(double dt)            advance the state by dt (the method's named phases)
//
// The loop itself (SolverRun::run) is shared: time control, writes and restart, function
// objects, signals, progress and the summary are the same for every method. So is the set-up a
// method needs, here, so that a new method writes only its physics:
//
//     openConstant / openOptionalConstant   dictionaries recorded for the never-read check
//     readBoundaryConditions                constant/boundaryConditions, if the case has one
//     checkPositiveMassAndDensity           the start state's masses and densities
//     phase("name")                         a scoped timer feeding the summary's phase lines
//     checkState(phase, n, bad, describe)   a state check every rank agrees on
//     preStep(), extraOutput()              hooks: topology changes, and files beside particles.vtp
//
// tests/unit/solver/DriftSolverTest.cpp is a whole method on these in under 150 lines.
#include "core/Dictionary.hpp"
#include "core/Error.hpp"
#include "core/Log.hpp"
#include "core/Time.hpp"
#include "functionObjects/RunContext.hpp"
#include "particles/ParticleSet.hpp"
#include "particles/TimeDirectory.hpp"

#include <algorithm>
#include <cstdint>
#include <deque>
#include <sstream>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace mfdyn {

class SolverRun;
template <int Dim>
class BoundaryConditionList;

class Solver : public RunContext {
public:
    explicit Solver(SolverRun& run);
    ~Solver() override;

    // Topology changes before the step's time-step vote (particles added or removed, MPM's
    // relocation to the grid): called by the loop at the start of every step.
    virtual void preStep() {}
    virtual TimeStepVote stableTimeStep() = 0;
    virtual void step(double dt) = 0;

    virtual ParticleSetBase& particles() = 0;
    const FieldStore& fields() const override { return const_cast<Solver*>(this)->particles(); }

    // Extra entries for <time>/state beyond the time counters, and their restore.
    virtual std::string solverState() const { return {}; }
    virtual void restoreSolverState(const Dictionary&) {}
    // Files written into each time directory beside particles.vtp, in the same atomic write
    // (a background grid's fields); `state` is the loop's own name.
    virtual std::vector<ExtraFile> extraOutput() const { return {}; }
    // This rank's own files of each time directory, written by every rank beside its particle
    // piece (a grid's piece grid_<rank>.vti, indexed by an extraOutput's grid.pvti); on one
    // process written as the extra files are. Collective: called on every rank, once per write,
    // before extraOutput.
    virtual std::vector<ExtraFile> pieceOutput() const { return {}; }
    // The dictionaries this solver read, for the never-read-entry check at the end of set-up:
    // by default every one opened through openConstant/openOptionalConstant, in that order.
    virtual std::vector<const Dictionary*> dictionaries() const;
    // Seconds spent in each named phase, for the summary: by default those timed by phase().
    virtual std::vector<std::pair<std::string, double>> phaseTimes() const { return phases_; }
    // The declared phases this run never entered (a scene without strength skips "strength"): the
    // summary lists them on one line instead of timing them at 0 s.
    std::vector<std::string> skippedPhases() const;
    // Extra lines for the summary (pair interactions per second, ...), given the time-loop seconds.
    virtual std::vector<std::string> summary(double /*loopSeconds*/) const { return {}; }

    const Case& runCase() const override;
    std::size_t ownedParticles() const override;
    const Time& time() const override;
    const std::string& startTimeName() const override;

protected:
    // constant/<name>, read once and kept for the solver's lifetime (the reference stays valid),
    // recorded for the never-read check.
    const Dictionary& openConstant(const std::string& name);
    // The same for a dictionary a case may leave out: null when constant/<name> does not exist.
    const Dictionary* openOptionalConstant(const std::string& name);

    // constant/boundaryConditions when the case has one (its conditions logged), else an empty
    // list. The selections are made from `particles` as they are now. `hooks`: what the solver
    // calls beyond the constraints; a condition that needs another is refused at its entry
    // (BoundaryConditionList::requireHooks).
    template <int Dim>
    BoundaryConditionList<Dim> readBoundaryConditions(
        const ParticleSet<Dim>& particles, const typename BoundaryConditionList<Dim>::Hooks& hooks);

    // Every particle's mass and density positive (and not NaN); else an InputError naming the
    // first particle that is not.
    static void checkPositiveMassAndDensity(const ParticleSetBase& particles, const std::vector<double>& mass,
                                            const std::vector<double>& density);

    // Named phase timing: `auto timed = phase("computeRates");` adds the seconds until `timed`
    // goes out of scope to that phase. Phases appear in the summary in the order declared, then
    // in the order first timed.
    class ScopedPhase {
    public:
        ScopedPhase(Solver& solver, std::size_t index) : solver_(solver), index_(index) {
            ++solver_.phaseEntries_[index_];
        }
        ScopedPhase(const ScopedPhase&) = delete;
        ScopedPhase& operator=(const ScopedPhase&) = delete;
        ~ScopedPhase() { stop(); }
        // A pause for work timed as another phase (the rates inside an integrator), and the resume.
        void stop() {
            if (running_) solver_.phases_[index_].second += watch_.seconds();
            running_ = false;
        }
        void resume() {
            watch_.restart();
            running_ = true;
        }

    private:
        Solver& solver_;
        std::size_t index_;
        Stopwatch watch_;
        bool running_ = true;
    };
    [[nodiscard]] ScopedPhase phase(std::string_view name) { return ScopedPhase(*this, phaseIndex(name)); }
    // The summary's order, independent of which phase happens to run first.
    void declarePhases(std::initializer_list<std::string_view> names) {
        for (auto name : names) phaseIndex(name);
    }

    // The state check every rank agrees on: the bad owned particles (bad(i) for i < n; ghosts,
    // images of particles owned here or on another rank, are judged where they are owned) are
    // counted with a global sum, so that when any rank has one every rank throws (a throw only
    // where the bad particle lives would leave the others waiting in their next collective).
    // Every rank throws the same text, "phase <phase>, step <k>, t = <t>: " + describe(i, count),
    // where i is the bad particle of lowest global id on any rank, described by the rank that
    // owns it (GlobalReduce::firstMessage): the same particle whatever the ranks and whatever the
    // order of particles in memory (which sorting, appending and removing change).
    template <class Bad, class Describe>
    void checkState(std::string_view phaseName, std::size_t n, Bad&& bad, Describe&& describe) const;

    SolverRun& run_;

private:
    std::size_t phaseIndex(std::string_view name);
    std::string statePrefix(std::string_view phaseName) const;
    // How many i < n have bad(i), summed over every process (the state check's one global
    // reduction: every rank calls it, bad particles or not).
    template <class Bad>
    static double globalCount(std::size_t n, Bad& bad);
    const std::vector<std::int64_t>& globalIds() const;

    std::deque<Dictionary> opened_;  // a deque: references to its elements stay valid
    std::vector<std::pair<std::string, double>> phases_;
    std::vector<std::int64_t> phaseEntries_;  // per phase, how often it was entered
};

}  // namespace mfdyn

#include "core/Parallel.hpp"

template <class Bad>
double mfdyn::Solver::globalCount(std::size_t n, Bad& bad) {
    return GlobalReduce::sum<double>(n, [&](std::size_t i) { return bad(i) ? 1.0 : 0.0; });
}

template <class Bad, class Describe>
void mfdyn::Solver::checkState(std::string_view phaseName, std::size_t n, Bad&& bad,
                               Describe&& describe) const {
    n = std::min(n, ownedParticles());
    const double count = globalCount(n, bad);
    if (count == 0) return;
    // This rank's candidate, its bad particle of lowest global id; only it is described (the
    // descriptions of the others would be thrown away). Two collectives in all, on every rank.
    const std::vector<std::int64_t>& id = globalIds();
    std::size_t first = n;
    for (std::size_t i = 0; i < n; ++i)
        if ((first == n || id[i] < id[first]) && bad(i)) first = i;
    std::string text;
    if (first < n) text = describe(first, count);
    throw RunError(statePrefix(phaseName) +
                   GlobalReduce::firstMessage(first < n ? id[first] : noMessageKey, std::move(text)));
}
