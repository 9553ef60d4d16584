#pragma once
// Run control from system/controlDict, the way OpenFOAM users know it:
//
//     startFrom       latestTime;     // startTime | latestTime
//     startTime       0;
//     stopAt          endTime;        // endTime | writeNow | noWriteNow
//     endTime         1.0;
//     deltaT          1e-4;
//     adjustTimeStep  yes;            // dt from the solver's stability vote, limited by maxCo, maxDeltaT
//     maxCo           0.3;
//     maxDeltaT       1;
//     minDeltaT       1e-10;          // a smaller adjusted step is a collapse: RunError (default
//                                     // 1e-10 of endTime - startTime; 0: no limit)
//     writeControl    adjustableRunTime;  // timeStep | runTime | adjustableRunTime
//     writeInterval   0.1;
//     purgeWrite      0;              // keep only the newest N written times (0: keep all)
//     writePrecision  6;              // significant digits of time directory names
//     runTimeModifiable yes;          // re-read this file when it changes during the run
//
// Time is advanced as t += dt with dt chosen deterministically from the state, so a run restarted
// from a written time (whose exact t, dt and counters are saved in <time>/state) repeats the
// uninterrupted run bit for bit.
#include "core/Dictionary.hpp"

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace mfdyn {

enum class WriteControl { timeStep, runTime, adjustableRunTime };
enum class StopAt { endTime, writeNow, noWriteNow };

// One model's answer to "how large may the step be?": the smallest wins and its reason is shown.
struct TimeStepVote {
    double deltaT;
    std::string reason;
    // The global id of the particle that limits the step, where the vote knows it (-1: none, or a
    // limit that is not a particle's): the health check names it when the step collapses.
    std::int64_t particle = -1;
};

class Time {
public:
    Time(const std::filesystem::path& controlDictPath, const Dictionary& controlDict);

    // Reads every run-control entry; called at start and whenever controlDict changes.
    void readControls(const Dictionary& controlDict);
    // runTimeModifiable: re-reads controlDict if its modification time changed (checked at most
    // twice a second). Returns a description of the changes, empty when nothing changed.
    // Collective on several ranks: rank 0 looks, and every rank applies rank 0's text.
    std::string checkModified();

    // The start: "startTime" or "latestTime" resolved by the caller to a directory; restore()
    // puts back the exact counters saved in that directory's state.
    const std::string& startFrom() const { return startFrom_; }
    double startTime() const { return startTime_; }
    void start(double value, const std::string& name);
    // restore() checks every value against the name given to start() (the directory's): an error
    // names the state file and line.
    void restore(const Dictionary& state);
    // The start already is at endTime (a restart of a finished run): nothing to do.
    bool finished() const;
    // Entries for <time>/state.
    std::string state() const;

    double value() const { return value_; }
    double deltaT() const { return deltaT_; }
    double endTime() const { return endTime_; }
    std::int64_t timeIndex() const { return timeIndex_; }
    const std::string& timeName() const { return timeName_; }
    std::string nameOf(double t) const;
    double maxCo() const { return maxCo_; }
    // maxCo as the controlDict gives it, or the method's own default when it gives none (tlSph's
    // 0.3; maxCo() alone defaults to 1).
    double maxCo(double methodDefault) const { return maxCoGiven_ ? maxCo_ : methodDefault; }
    bool adjustTimeStep() const { return adjustTimeStep_; }
    int purgeWrite() const { return purgeWrite_; }
    int writePrecision() const { return writePrecision_; }
    StopAt stopAt() const { return stopAt_; }

    // True while the end time is not reached and no stop was asked for.
    bool running() const;
    // The step to take next: the vote (already including the solver's Courant limit scaled by
    // maxCo) when adjustTimeStep, else deltaT checked against the vote (a fixed deltaT above the
    // stable one is a RunError naming the limit); clipped so that the step lands exactly on the
    // end time and, for adjustableRunTime, on write times.
    double chooseDeltaT(const TimeStepVote& stable);
    // The vote the latest chooseDeltaT was given (deltaT 0 before the first): the health check
    // compares it with the first.
    const TimeStepVote& lastVote() const { return lastVote_; }
    // t += dt, index++, and decides whether this is a write time.
    void advance(double dt);
    bool writeTime() const { return writeTime_; }
    // Counts the write (so the next write time is known); called by whoever wrote.
    void wrote() { writeTime_ = false, writtenName_ = timeName_; }

private:
    double nextWriteTime() const;
    // The write times ahead when they can be known at the start (not with adjustTimeStep and
    // writeControl timeStep), ending with endTime.
    std::vector<double> predictedWriteTimes() const;
    // An InputError when two write times ahead get the same name (writePrecision too low).
    void checkWriteNames() const;

    // Rank 0's look at controlDict for checkModified: "+" and its text when it changed since the
    // last look (at most every 0.5 s), else empty.
    std::string modifiedControlDictText();
    std::filesystem::path controlDictPath_;
    std::filesystem::file_time_type controlDictStamp_{};
    double lastCheck_ = 0;

    std::string startFrom_ = "startTime";
    double startTime_ = 0;
    StopAt stopAt_ = StopAt::endTime;
    double endTime_ = 0;
    double fixedDeltaT_ = 0;
    bool adjustTimeStep_ = false;
    double maxCo_ = 1;
    bool maxCoGiven_ = false;
    double maxDeltaT_ = 0;
    double minDeltaT_ = 0;
    WriteControl writeControl_ = WriteControl::timeStep;
    double writeInterval_ = 1;
    int purgeWrite_ = 0;
    int writePrecision_ = 6;
    bool runTimeModifiable_ = true;
    SourceLocation namesWhere_;  // writePrecision's entry (writeInterval's when defaulted)
    std::string namesScope_;

    double value_ = 0;
    double deltaT_ = 0;
    TimeStepVote lastVote_{0.0, "", -1};
    double desiredDeltaT_ = 0;  // the step before clipping to write/end times (limits growth)
    std::int64_t timeIndex_ = 0;
    std::int64_t writeIndex_ = 0;  // write intervals completed (runTime, adjustableRunTime)
    std::string timeName_ = "0";
    std::string writtenName_ = "0";  // the last write's (or the start's) directory name
    bool writeTime_ = false;
};

}  // namespace mfdyn
