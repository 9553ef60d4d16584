#include "solver/SolverRun.hpp"

#include "core/CaseLock.hpp"
#include "core/Communicator.hpp"
#include "core/LibraryLoader.hpp"
#include "core/Parallel.hpp"
#include "core/RankZero.hpp"
#include "core/SignalHandler.hpp"
#include "functionObjects/CsvFile.hpp"
#include "functionObjects/FunctionObject.hpp"
#include "particles/Decomposition.hpp"
#include "particles/PvdIndex.hpp"
#include "particles/TimeDirectory.hpp"
#include "particles/TimeDirectoryReader.hpp"
#include "solver/Solver.hpp"

#include <algorithm>
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
    std::error_code ec;  // a self-linked file: ELOOP, which fs::exists(file) threw as filesystem_error
    const bool found = fs::exists(file, ec);
    if (ec) throw InputError("cannot read " + file.string() + ": " + ec.message());
    if (!found)
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

// Every error against a reference in one fixed form, one per line, for people and for mfStudy:
//     error <name>  <value> (exact <x>, relative <r>) at CPU <s> s, step <n>, t = <t>
// <name> is <object>/<field>/<L1|L2|Linf> (value: the norm of the error, exact: the same norm
// of the exact field, relative = value/exact) or <object>/<quantity> (relative =
// (value - exact)/|exact|); "n/a" where there is no exact norm or it is zero. The CPU time, step
// and time are those of the write that measured it; the heading gives the process CPU time at
// the end of the run (the error reached and what it cost).
std::string errorLines(const std::vector<FunctionObjectList::ErrorRecord>& records) {
    if (records.empty()) return "";
    const auto text = [](double v, const char* format) {
        if (!std::isfinite(v)) return std::string("n/a");
        char s[40];
        std::snprintf(s, sizeof s, format, v);
        return std::string(s);
    };
    std::ostringstream s;
    // Not "Error...": a line that starts so is an error message to scripts and mfStudy's diagnosis.
    s << "Compared with the reference (process CPU time at the end of the run "
      << text(processCpuSeconds(), "%.6g") << " s):";
    for (const auto& r : records) {
        s << "\n    error " << r.name << "  " << text(r.value, "%.10g") << " (exact "
          << text(r.exact, "%.10g") << ", relative " << text(r.relative, "%.6g") << ") at CPU "
          << text(r.measured.cpuSeconds, "%.6g") << " s, step "
          << (r.measured.step >= 0 ? std::to_string(r.measured.step) : std::string("n/a"))
          << ", t = " << text(r.measured.time, "%.10g");
    }
    return s.str();
}

// A signal reaches the ranks at different steps (or only some of them): the largest number any
// rank has is every rank's, so all write the same final state and stop after the same step.
int collectiveStopSignal() {
    return int(globalMax(double(SignalHandler::stopRequested())));
}

// The particles of the run, owned by every rank together (ghosts are images, not particles).
std::size_t globalParticleCount(const ParticleSetBase& particles) {
    return globalSum(particles.ownedCount());
}

}  // namespace

SolverRun::SolverRun(const Arguments& args, std::string application)
    : application_(std::move(application)), case_(args.caseDir()), controlDict_(readControlDict(case_)) {
    Log::info(banner(application_, case_.root(), args.commandLine()));
    // Before anything is read that another run could be writing; held until the run ends. Under
    // mpirun by rank 0 for the whole run (the other ranks would find it taken, by their own run);
    // a refusal stops every rank.
    onRankZero([&] { lock_ = std::make_unique<CaseLock>(case_.root(), application_); });
    // Libraries first: their models must be selectable before anything is read.
    LibraryLoader::load(controlDict_, case_.root());
    time_ = std::make_unique<Time>(case_.systemFile("controlDict"), controlDict_);
    // Read now, not where it is used: the never-read check scans controlDict before it could
    // read the switch there, and would report the switch itself, so that strict mode never passed.
    strictDictionaries_ = controlDict_.getOrDefault<bool>("strictDictionaries", false);

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
    startDirectoryValue_ = start->value;
    lastWritten_ = start->name;  // the start directory is input: never written, not even at the end
    // particles.vtp, or the particles.pvtp of a time written on several ranks.
    const fs::path particleFile = timeParticleFile(case_.timeDir(start->name));
    std::error_code ec;  // without it a self-linked particles.vtp threw filesystem_error ("internal")
    if (!fs::exists(particleFile, ec) && !ec)
        throw InputError("cannot find " + particleFile.string() + " (nor " + particleIndexFileName + ")");
    particles_ = std::move(readTimeParticles(case_.timeDir(start->name)).particles);
    time_->start(start->value, start->name);
    // Read (and so checked) now; changed only in prepareOutputs, once the input is known good.
    pvd_ = std::make_unique<PvdIndex>(PvdIndex::read(case_.root() / "particles.pvd"));
    if (fs::exists(case_.timeDir(start->name) / "state", ec) || ec) {  // an unreadable state: say why below
        state_ = Dictionary::read(case_.timeDir(start->name) / "state");
        time_->restore(*state_);
        Log::info("Restarting from time " + start->name + " (step " + std::to_string(time_->timeIndex()) +
                  ")");
    } else {
        Log::info("Starting from time " + start->name);
    }
    Log::info("Read " + std::to_string(particles_->size()) + " particles (" +
              std::to_string(particles_->dimension()) + "D) from " + particleFile.string());
    if (Communicator::distributed()) decompose(particleFile.string());
}

// Several ranks: each keeps its share of the particles every rank has read. The settings come
// from system/decomposeParDict, which is optional (recursive coordinate bisection, rebalanced
// past 1.2 times the mean load).
void SolverRun::decompose(const std::string& particleFile) {
    Decomposition::Settings settings;
    const fs::path dictFile = case_.systemFile("decomposeParDict");
    std::error_code ec;
    if (fs::exists(dictFile, ec)) {
        decomposeParDict_ = Dictionary::read(dictFile);
        settings.method = decomposeParDict_->getOrDefault<std::string>("method", settings.method);
        const auto& methods = Partitioner::methods();
        if (std::find(methods.begin(), methods.end(), settings.method) == methods.end())
            throw decomposeParDict_->error(
                "method", "unknown partitioning method '" + settings.method + "'; valid methods: rcb, hsfc");
        settings.maxImbalance =
            decomposeParDict_->getOrDefault<double>("maxImbalance", settings.maxImbalance);
        if (!(settings.maxImbalance >= 1.0))
            throw decomposeParDict_->error("maxImbalance",
                                           "maxImbalance must be at least 1 (the heaviest rank's "
                                           "load over the mean that triggers a rebalance)");
    }
    decomposition_ = std::make_unique<Decomposition>(settings, particles_->dimension());
    decomposition_->distribute(*particles_, particleFile);
    Log::info("Decomposed over " + std::to_string(Communicator::size()) + " ranks (" + settings.method +
              (Decomposition::cutField(*particles_) == "referencePosition"
                   ? ", cut in the reference configuration"
                   : "") +
              ")");
}

SolverRun::~SolverRun() = default;

void SolverRun::refuseSeveralRanks() const {
    if (decomposition_)
        throw InputError(
            application_ +
            " does not run on several ranks yet (impactSph, tlSph, mpmFsi and fpmSolid do); run it "
            "without mpirun, on one process");
}

void SolverRun::prepareOutputs() {
    if (const std::size_t n = removeStaleTemporaries(case_.root()))
        Log::info("Cleared " + std::to_string(n) + " temporaries left in " + case_.root().string() +
                  " by killed runs");
    // Later times were written by an earlier run that went on from another state (a longer run,
    // or one before particleGen was rerun): startFrom latestTime would take them up, so they are
    // moved aside, not deleted, and not left where they are.
    std::vector<std::string> later;
    std::set<std::string> laterSet;
    for (const auto& t : case_.timeDirectories())
        if (t.value > startDirectoryValue_ && t.name != startTimeName_) {
            later.push_back(t.name);
            laterSet.insert(t.name);
        }
    auto inLater = [&](const std::string& file) {
        return laterSet.count(file.substr(0, file.find('/'))) > 0;
    };
    // The index keeps what precedes the start's exact time (from its state on a restart: the
    // directory name is rounded to writePrecision and may be below it) and nothing in a moved
    // time. It is rewritten before the move, so that it never points into a moved directory.
    PvdIndex pvd(pvd_->file());
    bool listsStart = false;
    // The start's own particle file: particles.pvtp where a run on several ranks wrote it.
    const std::string startFile =
        startTimeName_ + "/" + timeParticleFile(case_.timeDir(startTimeName_)).filename().string();
    for (const auto& e : pvd_->entries()) {
        if (e.time > time_->value() || inLater(e.file)) continue;
        pvd.add(e.time, e.file, e.part);
        listsStart = listsStart || e.file == startFile;
    }
    if (!listsStart) pvd.add(time_->value(), startFile);
    if (pvd.entries().size() != pvd_->entries().size() || !listsStart) pvd.write();
    if (!later.empty()) {
        const fs::path aside = moveAsideTimeDirectories(case_.root(), later);
        // Their own index beside them, so the abandoned series still opens in ParaView.
        PvdIndex abandoned(aside / "particles.pvd");
        for (const auto& e : pvd_->entries())
            if (inLater(e.file)) abandoned.add(e.time, e.file, e.part);
        if (!abandoned.entries().empty()) abandoned.write();
        // The earliest ten: a long run can leave thousands.
        std::string names;
        for (std::size_t k = 0; k < later.size() && k < 10; ++k) names += " " + later[k];
        if (later.size() > 10) names += " and " + std::to_string(later.size() - 10) + " more";
        Log::info("Moved " + std::to_string(later.size()) + " time directories later than the start time " +
                  startTimeName_ + " (" + names.substr(1) + "), left by an earlier run, to " +
                  aside.string() + "/");
    }
    *pvd_ = std::move(pvd);
}

void SolverRun::write(Solver& solver) {
    Stopwatch watch;
    const Time& time = *time_;
    if (time.timeName() == startTimeName_) {
        char exact[32];
        std::snprintf(exact, sizeof exact, "%.17g", time.value());
        throw Error("the time " + std::string(exact) + " to write would be named '" + time.timeName() +
                    "' at writePrecision " + std::to_string(time.writePrecision()) +
                    ", the name of the start directory, which is input and is never overwritten: raise "
                    "writePrecision in " +
                    case_.systemFile("controlDict").string());
    }
    std::string state = "// Restart state of " + application_ + " at time " + time.timeName() +
                        " (read by startFrom latestTime)\n" + time.state() + solver.solverState();
    const std::vector<ExtraFile> pieces = solver.pieceOutput();
    std::vector<ExtraFile> files{{"state", state}};
    for (auto& file : solver.extraOutput()) files.push_back(std::move(file));
    writeTimeDirectory(case_.root(), time.timeName(), solver.particles(), files, time.value(), pieces);
    // The index and the purge are the case's files: rank 0's alone (it keeps the index in memory).
    onRankZero([&] {
        pvd_->add(time.value(), time.timeName() + "/" + writtenParticleFileName());
        // A grid method's image files (grid.vti, or on several ranks the index grid.pvti of the
        // ranks' pieces) are further parts of the same time, so ParaView opens the grid with the
        // particles (PvdIndex.hpp); the state and other files are not VTK.
        int part = 0;
        for (const auto& [name, contents] : files)
            if (name.ends_with(".vti") || name.ends_with(".pvti"))
                pvd_->add(time.value(), time.timeName() + "/" + name, ++part);
        pvd_->write();
    });
    lastWritten_ = time.timeName();
    time_->wrote();
    onRankZero([&] { purge(); });
    writeSeconds_ += watch.seconds();
}

void SolverRun::purge() {
    const int keep = time_->purgeWrite();
    if (keep <= 0) return;
    auto times = case_.timeDirectories();
    // The initial conditions are never purged: they are the case's input, not a result.
    if (!times.empty() && times.front().name == "0") times.erase(times.begin());
    if (int(times.size()) <= keep) return;
    std::set<std::string> removed;  // time directories
    for (std::size_t k = 0; k + keep < times.size(); ++k) {
        removeTimeDirectory(case_.root(), times[k].name);
        removed.insert(times[k].name);
    }
    // Every part of a removed time goes (its particles.vtp and its grid.vti alike).
    PvdIndex pvd(pvd_->file());
    for (const auto& entry : pvd_->entries())
        if (!removed.count(entry.file.substr(0, entry.file.find('/'))))
            pvd.add(entry.time, entry.file, entry.part);
    pvd.write();
    *pvd_ = std::move(pvd);
}

namespace {

// Whether `file` lies in one of the toolkit's etc/ directories (#includeEtc's search path).
bool inEtc(const std::shared_ptr<const std::string>& file, const std::vector<fs::path>& etc) {
    if (!file) return false;
    std::error_code ec;
    const fs::path path = fs::weakly_canonical(*file, ec);
    if (ec) return false;
    for (const fs::path& dir : etc) {
        const fs::path root = fs::weakly_canonical(dir, ec);
        if (ec) continue;
        const auto [end, _] = std::mismatch(root.begin(), root.end(), path.begin(), path.end());
        if (end == root.end()) return true;
    }
    return false;
}

}  // namespace

void SolverRun::checkUnusedEntries(const Solver& solver) const {
    std::vector<const Dictionary*> dicts{&controlDict_};
    if (decomposeParDict_) dicts.push_back(&*decomposeParDict_);
    for (const Dictionary* d : solver.dictionaries()) dicts.push_back(d);
    // A shared data sheet (etc/materials/copperTaylorBar) states more properties than any one
    // model reads (E and nu beside the shear and bulk moduli): what the chosen models left of it
    // is said, not warned of, and strict mode does not count it. A case's own entries all count.
    const std::vector<fs::path> etc = etcDirectories();
    std::ostringstream s, sheet;
    int count = 0, sheetCount = 0;
    for (const Dictionary* d : dicts) {
        for (const UnusedEntry& u : d->unusedEntries()) {
            if (inEtc(u.where.file, etc)) {
                ++sheetCount;
                sheet << "\n    " << u.where.str() << ": '" << u.scopedKey << "'";
                continue;
            }
            ++count;
            s << "\n    " << u.where.str() << ": '" << u.scopedKey << "' was never read";
            if (!u.suggestion.empty()) s << " (did you mean '" << u.suggestion << "'?)";
        }
    }
    if (sheetCount)
        Log::info(
            std::to_string(sheetCount) +
            " entries of the toolkit's data files (etc/) are not used by the models chosen:" + sheet.str());
    if (count == 0) return;
    if (strictDictionaries_)
        throw InputError(std::to_string(count) +
                         " dictionary entries were never read (strictDictionaries yes):" + s.str());
    Log::warning(std::to_string(count) + " dictionary entries were never read:" + s.str());
}

int SolverRun::run(Solver& solver) {
    Time& time = *time_;
    // A restart of a finished run (startFrom latestTime at endTime): not an error, and nothing is
    // written (no function-object rows, no summary) so the results stay as that run left them.
    if (time.finished()) {
        Log::info("Nothing to do: the run already reached endTime " + time.nameOf(time.endTime()) +
                  " (start time " + time.timeName() + "); raise endTime in " +
                  case_.systemFile("controlDict").string() + " to continue it\nEnd");
        return 0;
    }
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

    // Everything is read and constructed: only now may earlier results change. Rank 0 changes them;
    // onRankZero is also the barrier that keeps the other ranks from writing before it is done.
    onRankZero([&] { prepareOutputs(); });
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
        TimeStepVote vote{0.0, "", -1};
        double dt = 0;
        try {
            solver.preStep();
            vote = solver.stableTimeStep();
            functions.checkVote(vote);
            dt = time.chooseDeltaT(vote);
        } catch (const RunError&) {
            // A state the vote cannot judge (an equation of state out of range, a collapsed
            // step): the state that failed is the current one, written for diagnosis unless it is.
            if (lastWritten_ != time.timeName()) {
                write(solver);
                Log::info("Wrote the failing state to " + time.timeName() + "/");
            }
            throw;
        }
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

        stopSignal = collectiveStopSignal();
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
        try {
            functions.execute(writing);
        } catch (const RunError&) {
            // A function object that stops the run (conservedQuantities' maxEnergyGrowth): the
            // state it judged is written for diagnosis, as a failing step's is.
            if (!writing) {
                write(solver);
                Log::info("Wrote the failing state to " + time.timeName() + "/");
            }
            throw;
        }

        const double elapsed = stepping.seconds();
        if (writing || (Log::interactive() && elapsed - lastProgress > 1.0)) {
            lastProgress = elapsed;
            Log::info(progressLine(time, elapsed, startTime) + "  [" + vote.reason + "]" +
                      (writing ? "  wrote " + time.timeName() : ""));
        }
        if (const std::string request = stopSignal ? std::string() : functions.stopRequest();
            !request.empty()) {
            // A function object ends the run (planeCrossing's stopAtCrossing): a result, not a
            // failure, so the state is written (and the objects that write with it run) and the
            // status is 0.
            if (!writing) {
                write(solver);
                functions.execute(true);
            }
            Log::info("\nStopped by " + request + " at t = " + time.timeName() + ", step " +
                      std::to_string(time.timeIndex()) + "; the state is written in " +
                      (case_.root() / time.timeName()).string() + "/");
            break;
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
    // A signal after the last step: the state is written all the same, and the status says so.
    if (!stopSignal) stopSignal = collectiveStopSignal();
    summary(solver, stepping.seconds(), time.timeIndex() - startIndex);

    // Error norms beside the run time that bought them.
    const auto norms = functions.errorNorms();
    const double wall = clock_.seconds();
    const std::size_t n = globalParticleCount(solver.particles());
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
    if (const std::string errors = errorLines(functions.errorRecords()); !errors.empty()) Log::info(errors);
    CsvFile csv(case_.postProcessing() / "runSummary" / startTimeName_ / "runSummary.csv",
                {"time", "field", "L1", "L2", "Linf", "wallTime", "steps", "particles", "threads",
                 "particleStepsPerSecond"},
                startTime);
    const double rate = wall > 0 ? double(n) * double(steps) / stepping.seconds() : 0;
    if (norms.empty())
        csv.row(time.value(), "none", {0, 0, 0, wall, double(steps), double(n), double(threadCount()), rate});
    for (const auto& e : norms)
        csv.row(e.time, e.source + "/" + e.field,
                {e.L1, e.L2, e.Linf, wall, double(steps), double(n), double(threadCount()), rate});
    if (!stopSignal) {
        Log::info("End");
        return 0;
    }
    const int status = SignalHandler::exitStatus(stopSignal);
    Log::info(std::string("End (stopped by ") + SignalHandler::name(stopSignal) + ", exit status " +
              std::to_string(status) + ")");
    return status;
}

void SolverRun::summary(const Solver& solver, double steppingSeconds, std::int64_t stepsRun) {
    const Time& time = *time_;
    const std::size_t n = globalParticleCount(const_cast<Solver&>(solver).particles());
    std::ostringstream s;
    char line[200];
    std::snprintf(line, sizeof line,
                  "\nSummary\n    wall time            %s (set-up %s, time loop %s, writing %s)\n",
                  formatSeconds(clock_.seconds()).c_str(), formatSeconds(setUpSeconds_).c_str(),
                  formatSeconds(steppingSeconds).c_str(), formatSeconds(writeSeconds_).c_str());
    s << line;
    // After a restart the step index counts from t = 0; the rate is of the steps this run took.
    // A fresh run's line is unchanged ("N to t = T"): scripts read it.
    s << "    steps                " << stepsRun << " to t = " << time.timeName();
    if (stepsRun != time.timeIndex()) s << " (from step " << time.timeIndex() - stepsRun << ")";
    s << "\n";
    s << "    particles            " << n << "\n";
    // On several ranks: the wall times are rank 0's, the phase times and the memory the largest
    // over the ranks (the slowest rank sets the pace; every rank reaches these reductions, whatever
    // phases it skipped).
    const int ranks = Communicator::size();
    const std::string workers =
        ranks > 1 ? std::to_string(ranks) + " ranks x " + std::to_string(threadCount()) + " threads"
                  : std::to_string(threadCount()) + " threads";
    std::snprintf(line, sizeof line, "    particle-steps/s     %.4g (%s)\n",
                  steppingSeconds > 0 ? double(n) * double(stepsRun) / steppingSeconds : 0.0,
                  workers.c_str());
    s << line;
    s << "    peak memory          " << formatBytes(globalMax(double(peakMemoryBytes())))
      << (ranks > 1 ? " (the largest rank's)" : "") << "\n";
    // A phase the scene does not need is never entered: named once, not timed at 0 s. (A solver's
    // phaseTimes may decorate a name, "updateNeighbours (84 rebuilds)": its first word is the phase.)
    const std::vector<std::string> skipped = solver.skippedPhases();
    auto phases = solver.phaseTimes();
    for (auto& phase : phases) phase.second = globalMax(phase.second);
    if (ranks > 1) s << "    phase times          the slowest rank's\n";
    for (const auto& [phase, seconds] : phases) {
        if (std::find(skipped.begin(), skipped.end(), phase.substr(0, phase.find(' '))) != skipped.end())
            continue;
        std::snprintf(line, sizeof line, "    phase %-14s %s (%.1f%%)\n", phase.c_str(),
                      formatSeconds(seconds).c_str(),
                      steppingSeconds > 0 ? 100 * seconds / steppingSeconds : 0.0);
        s << line;
    }
    if (!skipped.empty()) {
        s << "    phases skipped      ";
        for (std::size_t k = 0; k < skipped.size(); ++k) s << (k ? ", " : " ") << skipped[k];
        s << " (not needed by this scene)\n";
    }
    for (const auto& extra : solver.summary(steppingSeconds)) s << "    " << extra << "\n";
    if (Log::warningCount()) s << "    warnings             " << Log::warningCount() << "\n";
    Log::info(s.str());
}

}  // namespace mfdyn
