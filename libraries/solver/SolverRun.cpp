#include "solver/SolverRun.hpp"

#include "core/LibraryLoader.hpp"
#include "core/Parallel.hpp"
#include "core/SignalHandler.hpp"
#include "functionObjects/CsvFile.hpp"
#include "functionObjects/FunctionObject.hpp"
#include "particles/PvdIndex.hpp"
#include "particles/TimeDirectory.hpp"
#include "particles/VtpReader.hpp"
#include "solver/Solver.hpp"

#include <cmath>
#include <cstdio>
#include <iostream>
#include <set>
#include <sstream>

namespace mfdyn {

namespace fs = std::filesystem;

namespace {

Dictionary readControlDict(const Case& c) {
    const fs::path file = c.systemFile("controlDict");
    if (!fs::exists(file))
        throw InputError("cannot find " + file.string() + ": is '" + c.root().string() +
                         "' a case directory?");
    return Dictionary::read(file);
}

std::string progressLine(const Time& time, double elapsed, double startTime) {
    char s[200];
    const double done = time.value() - startTime, left = time.endTime() - time.value();
    const double eta = done > 0 ? elapsed * left / done : 0;
    std::snprintf(s, sizeof s, "Step %-8lld t = %-12.6g dt = %-10.4g elapsed %-8s left ~%s",
                  static_cast<long long>(time.timeIndex()), time.value(), time.deltaT(),
                  formatSeconds(elapsed).c_str(), formatSeconds(eta).c_str());
    return s;
}

}  // namespace

SolverRun::SolverRun(const Arguments& args, std::string application)
    : application_(std::move(application)), case_(args.caseDir()), controlDict_(readControlDict(case_)) {
    Log::info(banner(application_, case_.root(), args.commandLine()));
    // Libraries first: their models must be selectable before anything is read.
    LibraryLoader::load(controlDict_, case_.root());
    time_ = std::make_unique<Time>(case_.systemFile("controlDict"), controlDict_);

    std::optional<TimeDirectory> start;
    if (time_->startFrom() == "latestTime") {
        start = case_.latestTime();
        if (!start)
            throw InputError("startFrom latestTime, but " + case_.root().string() + " has no time directory");
    } else {
        start = case_.findTime(time_->startTime());
        if (!start)
            throw controlDict_.error("startTime", "no time directory for startTime " +
                                                      time_->nameOf(time_->startTime()) + " in " +
                                                      case_.root().string() + " (run particleGen first?)");
    }
    startTimeName_ = start->name;
    const fs::path particleFile = case_.timeDir(start->name) / "particles.vtp";
    if (!fs::exists(particleFile)) throw InputError("cannot find " + particleFile.string());
    particles_ = std::move(readVtp(particleFile).particles);
    time_->start(start->value, start->name);
    removeStaleTemporaries(case_.root());
    // Results later than the start belong to an abandoned future: drop them from the index.
    PvdIndex pvd = PvdIndex::read(case_.root() / "particles.pvd");
    pvd.truncateAfter(start->value);
    if (!pvd.entries().empty()) pvd.write();
    if (fs::exists(case_.timeDir(start->name) / "state")) {
        state_ = Dictionary::read(case_.timeDir(start->name) / "state");
        time_->restore(*state_);
        Log::info("Restarting from time " + start->name + " (step " + std::to_string(time_->timeIndex()) +
                  ")");
    } else {
        Log::info("Starting from time " + start->name);
    }
    Log::info("Read " + std::to_string(particles_->size()) + " particles (" +
              std::to_string(particles_->dimension()) + "D) from " + particleFile.string());
}

SolverRun::~SolverRun() = default;

void SolverRun::write(Solver& solver) {
    Stopwatch watch;
    const Time& time = *time_;
    std::string state = "// Restart state of " + application_ + " at time " + time.timeName() +
                        " (read by startFrom latestTime)\n" + time.state() + solver.solverState();
    writeTimeDirectory(case_.root(), time.timeName(), solver.particles(), {{"state", state}}, time.value());
    PvdIndex pvd = PvdIndex::read(case_.root() / "particles.pvd");
    pvd.add(time.value(), time.timeName() + "/particles.vtp");
    pvd.write();
    lastWritten_ = time.timeName();
    time_->wrote();
    purge();
    writeSeconds_ += watch.seconds();
}

void SolverRun::purge() {
    const int keep = time_->purgeWrite();
    if (keep <= 0) return;
    auto times = case_.timeDirectories();
    // The initial conditions are never purged: they are the case's input, not a result.
    if (!times.empty() && times.front().name == "0") times.erase(times.begin());
    if (int(times.size()) <= keep) return;
    const PvdIndex old = PvdIndex::read(case_.root() / "particles.pvd");
    std::set<std::string> removed;
    for (std::size_t k = 0; k + keep < times.size(); ++k) {
        removeTimeDirectory(case_.root(), times[k].name);
        removed.insert(times[k].name + "/" + particleFileName);
    }
    PvdIndex pvd(old.file());
    for (const auto& entry : old.entries())
        if (!removed.count(entry.file)) pvd.add(entry.time, entry.file);
    pvd.write();
}

void SolverRun::checkUnusedEntries(const Solver& solver) const {
    std::vector<const Dictionary*> dicts{&controlDict_};
    for (const Dictionary* d : solver.dictionaries()) dicts.push_back(d);
    std::ostringstream s;
    int count = 0;
    for (const Dictionary* d : dicts) {
        for (const UnusedEntry& u : d->unusedEntries()) {
            ++count;
            s << "\n    " << u.where.str() << ": '" << u.scopedKey << "' was never read";
            if (!u.suggestion.empty()) s << " (did you mean '" << u.suggestion << "'?)";
        }
    }
    if (count == 0) return;
    if (controlDict_.getOptional<bool>("strictDictionaries").value_or(false))
        throw InputError(std::to_string(count) +
                         " dictionary entries were never read (strictDictionaries yes):" + s.str());
    Log::warning(std::to_string(count) + " dictionary entries were never read:" + s.str());
}

int SolverRun::run(Solver& solver) {
    Time& time = *time_;
    if (state_) solver.restoreSolverState(*state_);
    FunctionObjectList functions(controlDict_, solver);
    if (auto named = controlDict_.getOptional<std::string>("application"); named && *named != application_)
        Log::warning("controlDict names application '" + *named + "' but this is " + application_);
    checkUnusedEntries(solver);

    const ParticleSetBase& particles = solver.particles();
    Log::info("Fields (" + formatBytes(double(particles.bytesPerParticle())) + " per particle):\n" +
              particles.fieldSummary());
    std::string defaults;
    for (const Dictionary* d : solver.dictionaries())
        for (const auto& e : d->defaultsUsed()) defaults += "\n    " + e;
    for (const auto& e : controlDict_.defaultsUsed()) defaults += "\n    " + e;
    if (!defaults.empty()) Log::info("Defaults used:" + defaults);

    SignalHandler::install();
    setUpSeconds_ = clock_.seconds();
    Stopwatch stepping;
    const double startTime = time.value();
    const std::int64_t startIndex = time.timeIndex();
    functions.execute(false);

    Log::info("\nStarting time loop at t = " + time.timeName() + ", end time " + time.nameOf(time.endTime()) +
              "\n");
    double lastProgress = 0;
    int stopSignal = 0;
    bool stoppedByControl = false;
    while (time.running()) {
        const TimeStepVote vote = solver.stableTimeStep();
        const double dt = time.chooseDeltaT(vote);
        try {
            solver.step(dt);
        } catch (const RunError&) {
            // The state that failed is written for diagnosis, under the time it would have reached.
            time.advance(dt);
            write(solver);
            Log::info("Wrote the failing state to " + time.timeName() + "/");
            throw;
        }
        time.advance(dt);

        stopSignal = SignalHandler::stopRequested();
        if (auto changes = time.checkModified(); !changes.empty()) Log::info(changes);
        if (time.stopAt() != StopAt::endTime) {
            stoppedByControl = true;
            if (time.stopAt() == StopAt::writeNow) write(solver);
            functions.execute(time.stopAt() == StopAt::writeNow);
            Log::info(std::string("stopAt ") +
                      (time.stopAt() == StopAt::writeNow ? "writeNow" : "noWriteNow") +
                      " at t = " + time.timeName());
            break;
        }
        const bool writing = time.writeTime() || stopSignal != 0;
        if (writing) write(solver);
        functions.execute(writing);

        const double elapsed = stepping.seconds();
        if (writing || (Log::interactive() && elapsed - lastProgress > 1.0)) {
            lastProgress = elapsed;
            Log::info(progressLine(time, elapsed, startTime) + "  [" + vote.reason + "]" +
                      (writing ? "  wrote " + time.timeName() : ""));
        }
        if (stopSignal) {
            Log::info(std::string("\nStopped by ") + SignalHandler::name(stopSignal) +
                      " at t = " + time.timeName() + ", step " + std::to_string(time.timeIndex()) +
                      "; the state is written in " + (case_.root() / time.timeName()).string() +
                      "/ (resume with startFrom latestTime)");
            break;
        }
    }
    if (!stopSignal && !stoppedByControl && lastWritten_ != time.timeName()) write(solver);
    (void)startIndex;
    summary(solver, stepping.seconds(), startTime);

    // Error norms beside the run time that bought them.
    const auto norms = functions.errorNorms();
    const double wall = clock_.seconds();
    const std::size_t n = solver.particles().size();
    const std::int64_t steps = time.timeIndex() - startIndex;
    std::ostringstream s;
    for (const auto& line : functions.summary()) s << "\n    " << line;
    if (!s.str().empty()) Log::info("Diagnostics:" + s.str());
    if (!norms.empty()) {
        std::ostringstream t;
        char row[256];
        std::snprintf(row, sizeof row, "Error norms (bought with %s wall time, %lld steps, %zu particles):",
                      formatSeconds(wall).c_str(), static_cast<long long>(steps), n);
        t << row;
        for (const auto& e : norms) {
            std::snprintf(row, sizeof row, "\n    %-20s %-14s t = %-10.6g L1 %.4e  L2 %.4e  Linf %.4e",
                          e.source.c_str(), e.field.c_str(), e.time, e.L1, e.L2, e.Linf);
            t << row;
        }
        Log::info(t.str());
    }
    CsvFile csv(case_.postProcessing() / "runSummary" / startTimeName_ / "runSummary.csv",
                {"time", "field", "L1", "L2", "Linf", "wallTime", "steps", "particles", "threads",
                 "particleStepsPerSecond"});
    const double rate = wall > 0 ? double(n) * double(steps) / stepping.seconds() : 0;
    if (norms.empty())
        csv.row(time.value(), "none", {0, 0, 0, wall, double(steps), double(n), double(threadCount()), rate});
    for (const auto& e : norms)
        csv.row(e.time, e.source + "/" + e.field,
                {e.L1, e.L2, e.Linf, wall, double(steps), double(n), double(threadCount()), rate});
    Log::info(stopSignal ? "End (stopped by signal)" : "End");
    return 0;
}

void SolverRun::summary(const Solver& solver, double steppingSeconds, double startTime) {
    const Time& time = *time_;
    const std::size_t n = const_cast<Solver&>(solver).particles().size();
    (void)startTime;
    std::ostringstream s;
    char line[200];
    std::snprintf(line, sizeof line,
                  "\nSummary\n    wall time            %s (set-up %s, time loop %s, writing %s)\n",
                  formatSeconds(clock_.seconds()).c_str(), formatSeconds(setUpSeconds_).c_str(),
                  formatSeconds(steppingSeconds).c_str(), formatSeconds(writeSeconds_).c_str());
    s << line;
    s << "    steps                " << time.timeIndex() << " to t = " << time.timeName() << "\n";
    s << "    particles            " << n << "\n";
    std::snprintf(line, sizeof line, "    particle-steps/s     %.4g (%d threads)\n",
                  steppingSeconds > 0 ? double(n) * double(time.timeIndex()) / steppingSeconds : 0.0,
                  threadCount());
    s << line;
    s << "    peak memory          " << formatBytes(double(peakMemoryBytes())) << "\n";
    for (const auto& [phase, seconds] : solver.phaseTimes()) {
        std::snprintf(line, sizeof line, "    phase %-14s %s (%.1f%%)\n", phase.c_str(),
                      formatSeconds(seconds).c_str(),
                      steppingSeconds > 0 ? 100 * seconds / steppingSeconds : 0.0);
        s << line;
    }
    for (const auto& extra : solver.summary(steppingSeconds)) s << "    " << extra << "\n";
    if (Log::warningCount()) s << "    warnings             " << Log::warningCount() << "\n";
    Log::info(s.str());
}

}  // namespace mfdyn
