#pragma once
// The base of every method's solver. A solver is a RunContext (what function objects see) plus
// the two things the time loop asks of it each step:
//
//     TimeStepVote stableTimeStep()   how large the next step may be, and what limits it
//     void step(double dt)            advance the state by dt (the method's named phases)
//
// The loop itself (SolverRun::run) is shared: time control, writes and restart, function
// objects, signals, progress and the summary are the same for every method.
#include "core/Dictionary.hpp"
#include "core/Time.hpp"
#include "functionObjects/RunContext.hpp"
#include "particles/ParticleSet.hpp"

#include <string>
#include <utility>
#include <vector>

namespace mfdyn {

class SolverRun;

class Solver : public RunContext {
public:
    explicit Solver(SolverRun& run);
    ~Solver() override;

    virtual TimeStepVote stableTimeStep() = 0;
    virtual void step(double dt) = 0;

    virtual ParticleSetBase& particles() = 0;
    const FieldStore& fields() const override { return const_cast<Solver*>(this)->particles(); }

    // Extra entries for <time>/state beyond the time counters, and their restore.
    virtual std::string solverState() const { return {}; }
    virtual void restoreSolverState(const Dictionary&) {}
    // The dictionaries this solver read, for the never-read-entry check at the end of set-up.
    virtual std::vector<const Dictionary*> dictionaries() const { return {}; }
    // Seconds spent in each named phase, for the summary.
    virtual std::vector<std::pair<std::string, double>> phaseTimes() const { return {}; }
    // Extra lines for the summary (pair interactions per second, ...), given the time-loop seconds.
    virtual std::vector<std::string> summary(double /*loopSeconds*/) const { return {}; }

    const Case& runCase() const override;
    const Time& time() const override;
    const std::string& startTimeName() const override;

protected:
    SolverRun& run_;
};

}  // namespace mfdyn
