#include "core/Time.hpp"

#include "core/ExactReal.hpp"
#include "core/Log.hpp"
#include "core/Parallel.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <fstream>
#include <optional>
#include <sstream>

namespace mfdyn {

namespace fs = std::filesystem;

namespace {

// Relative tolerance for "this step lands on that time": far above accumulated round-off of
// t += dt over millions of steps, far below any meaningful time step.
constexpr double landing = 1e-9;

template <class Enum>
Enum readChoice(const Dictionary& dict, const std::string& key, Enum fallback,
                const std::vector<std::pair<std::string, Enum>>& choices) {
    if (!dict.found(key)) {
        for (const auto& [name, value] : choices)
            if (value == fallback) dict.noteDefault(key + " " + name);
        return fallback;
    }
    const std::string word = dict.get<std::string>(key);
    std::vector<std::string> names;
    for (const auto& [name, value] : choices) {
        if (name == word) return value;
        names.push_back(name);
    }
    std::string valid;
    for (const auto& n : names) valid += (valid.empty() ? "" : " | ") + n;
    std::string message = "'" + word + "' is not a valid " + key + "; valid choices: " + valid;
    if (auto guess = closestMatch(word, names); !guess.empty()) message += " (did you mean '" + guess + "'?)";
    throw dict.error(key, message);
}

std::string show(double x) {
    std::ostringstream s;
    s.precision(17);
    s << x;
    return s.str();
}

// A run-control real must be a number: 1e999 reads as inf and would run forever or never.
double finite(const Dictionary& dict, const std::string& key, double value) {
    if (!std::isfinite(value)) throw dict.error(key, key + " must be a finite number, found " + show(value));
    return value;
}

double positive(const Dictionary& dict, const std::string& key, double value) {
    if (!(value > 0) || !std::isfinite(value))
        throw dict.error(key, key + " must be positive and finite, found " + show(value));
    return value;
}

// Significant digits in a time name: "0.125" 3, "1e-05" 1, "100" 3.
int significantDigits(const std::string& name) {
    std::string mantissa = name.substr(0, name.find_first_of("eE"));
    std::string digits;
    for (char c : mantissa)
        if (c >= '0' && c <= '9') digits += c;
    const auto first = digits.find_first_not_of('0');
    return first == std::string::npos ? 1 : int(digits.size() - first);
}

}  // namespace

Time::Time(const fs::path& controlDictPath, const Dictionary& controlDict)
    : controlDictPath_(controlDictPath) {
    readControls(controlDict);
    std::error_code ec;
    controlDictStamp_ = fs::last_write_time(controlDictPath_, ec);
}

void Time::readControls(const Dictionary& dict) {
    startFrom_ = dict.getOrDefault<std::string>("startFrom", "startTime");
    if (startFrom_ != "startTime" && startFrom_ != "latestTime") {
        std::string message =
            "'" + startFrom_ + "' is not a valid startFrom; valid choices: startTime | latestTime";
        if (auto g = closestMatch(startFrom_, {"startTime", "latestTime"}); !g.empty())
            message += " (did you mean '" + g + "'?)";
        throw dict.error("startFrom", message);
    }
    startTime_ = finite(dict, "startTime", dict.getOrDefault<double>("startTime", 0.0));
    stopAt_ = readChoice<StopAt>(
        dict, "stopAt", StopAt::endTime,
        {{"endTime", StopAt::endTime}, {"writeNow", StopAt::writeNow}, {"noWriteNow", StopAt::noWriteNow}});
    endTime_ = finite(dict, "endTime", dict.get<double>("endTime"));
    // An end at or before the start has nothing to run: refused rather than rewriting the start.
    // (A restart whose latest time already is endTime is another matter: see finished().)
    if (!(endTime_ > startTime_))
        throw dict.error("endTime", "endTime " + show(endTime_) + " is not after startTime " +
                                        show(startTime_) + ": nothing to run; set endTime above startTime");
    fixedDeltaT_ = positive(dict, "deltaT", dict.get<double>("deltaT"));
    adjustTimeStep_ = dict.getOrDefault<bool>("adjustTimeStep", false);
    maxCo_ = positive(dict, "maxCo", dict.getOrDefault<double>("maxCo", 1.0));
    maxCoGiven_ = dict.found("maxCo");
    maxDeltaT_ = positive(dict, "maxDeltaT", dict.getOrDefault<double>("maxDeltaT", 1e300));
    // A step so small that the run could not end (1e10 steps over the run by default) is a
    // collapse, not a slow run: huge accelerations or a tiny length scale used to run forever.
    // minDeltaT 0 switches the check off.
    if (dict.found("minDeltaT")) {
        minDeltaT_ = finite(dict, "minDeltaT", dict.get<double>("minDeltaT"));
        if (minDeltaT_ < 0)
            throw dict.error("minDeltaT", "minDeltaT must be >= 0 (0: no limit), found " + show(minDeltaT_));
    } else {
        minDeltaT_ = 1e-10 * (endTime_ - startTime_);
        dict.noteDefault("minDeltaT " + show(minDeltaT_) + " (1e-10 of endTime - startTime)");
    }
    if (!adjustTimeStep_ && fixedDeltaT_ < minDeltaT_)
        throw dict.error("deltaT", "deltaT " + show(fixedDeltaT_) + " is below minDeltaT " +
                                       show(minDeltaT_) + ": the run would take " +
                                       show(std::ceil((endTime_ - startTime_) / fixedDeltaT_)) +
                                       " steps; raise deltaT, or set minDeltaT (0: no limit)");
    writeControl_ = readChoice<WriteControl>(dict, "writeControl", WriteControl::timeStep,
                                             {{"timeStep", WriteControl::timeStep},
                                              {"runTime", WriteControl::runTime},
                                              {"adjustableRunTime", WriteControl::adjustableRunTime}});
    writeInterval_ = positive(dict, "writeInterval", dict.get<double>("writeInterval"));
    if (writeControl_ == WriteControl::timeStep && writeInterval_ != std::floor(writeInterval_))
        throw dict.error("writeInterval",
                         "with writeControl timeStep, writeInterval is a whole number of steps");
    purgeWrite_ = dict.getOrDefault<int>("purgeWrite", 0);
    if (purgeWrite_ < 0)
        throw dict.error("purgeWrite", "purgeWrite must be 0 (keep all) or a positive count");
    writePrecision_ = dict.getOrDefault<int>("writePrecision", 6);
    if (writePrecision_ < 1 || writePrecision_ > 17)
        throw dict.error("writePrecision", "writePrecision must be between 1 and 17 significant digits");
    // Where a clash of write-time names is reported: at writePrecision, or writeInterval.
    const Entry* named = dict.peek("writePrecision");
    namesWhere_ = named ? named->where : dict.peek("writeInterval")->where;
    namesScope_ = dict.scope();
    runTimeModifiable_ = dict.getOrDefault<bool>("runTimeModifiable", true);
    if (!adjustTimeStep_) deltaT_ = desiredDeltaT_ = fixedDeltaT_;
}

std::string Time::modifiedControlDictText() {
    const double now =
        std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
    if (now - lastCheck_ < 0.5) return {};
    lastCheck_ = now;
    std::error_code ec;
    const auto stamp = fs::last_write_time(controlDictPath_, ec);
    if (ec || stamp == controlDictStamp_) return {};
    controlDictStamp_ = stamp;
    std::ifstream in(controlDictPath_, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    return "+" + text.str();  // marked: an emptied file is a change too (and fails to parse)
}

std::string Time::checkModified() {
    if (!runTimeModifiable_) return {};
    // On several ranks rank 0 alone watches the clock and the file, and every rank parses rank
    // 0's text: ranks that each watched on their own clock took an edit at different steps, and a
    // rank with another endTime, stopAt or writeInterval left the loop or wrote alone (a hang;
    // test mpi.modified). One small collective a step.
    std::string changed = Communicator::rank() == 0 ? modifiedControlDictText() : std::string();
    changed = globalFirstMessage(Communicator::rank() == 0 ? 0 : noMessageKey, std::move(changed));
    if (changed.empty()) return {};
    const double oldEnd = endTime_, oldInterval = writeInterval_;
    const StopAt oldStop = stopAt_;
    // A half-edited file must not kill a long run: keep the old controls and say why. The new
    // ones are read into a copy, so an error half way leaves none of them half applied.
    try {
        Time next(*this);
        next.readControls(Dictionary::parse(std::string_view(changed).substr(1), controlDictPath_.string()));
        *this = next;
    } catch (const Error& e) {
        Log::warning(
            std::string("controlDict changed but could not be re-read; keeping the old controls:\n") +
            e.what());
        return {};
    }
    std::ostringstream changes;
    if (endTime_ != oldEnd) changes << " endTime " << oldEnd << " -> " << endTime_ << ";";
    if (writeInterval_ != oldInterval)
        changes << " writeInterval " << oldInterval << " -> " << writeInterval_ << ";";
    if (stopAt_ != oldStop) changes << " stopAt changed;";
    // The write counter follows a new interval from the present time.
    if (writeInterval_ != oldInterval && writeControl_ != WriteControl::timeStep)
        writeIndex_ = std::int64_t(std::floor(value_ / writeInterval_ * (1 + landing)));
    std::string text = changes.str();
    return text.empty() ? "controlDict re-read (no run-control change)" : "controlDict re-read:" + text;
}

void Time::start(double value, const std::string& name) {
    value_ = value;
    timeName_ = name;
    timeIndex_ = 0;
    writeIndex_ = std::int64_t(std::floor(value / writeInterval_ * (1 + landing)));
    if (writeControl_ == WriteControl::timeStep) writeIndex_ = 0;
    if (!adjustTimeStep_) deltaT_ = desiredDeltaT_ = fixedDeltaT_;
    writtenName_ = name;
    checkWriteNames();
}

void Time::restore(const Dictionary& state) {
    const double value = readExactReal(state, "timeExact");
    if (value < 0) throw state.error("timeExact", "the time " + show(value) + " is negative");
    // The directory's name is the time rounded to its digits: a state that disagrees was copied
    // from elsewhere or damaged, and would put the run at a time other than the one it claims.
    double named = 0;
    char* end = nullptr;
    named = std::strtod(timeName_.c_str(), &end);
    if (!timeName_.empty() && *end == '\0' && std::isfinite(named)) {
        const int digits = significantDigits(timeName_);
        const double scale =
            named == 0 ? 0 : std::pow(10.0, std::floor(std::log10(std::abs(named))) - digits + 1);
        if (std::abs(value - named) > 0.5 * scale * (1 + 1e-9))
            throw state.error("timeExact", "the time " + show(value) +
                                               " does not match the directory name '" + timeName_ +
                                               "': the state belongs to another time");
    }
    const double dt = readExactReal(state, "deltaTExact");
    if (!(dt > 0)) throw state.error("deltaTExact", "the time step " + show(dt) + " is not positive");
    const double desired = readExactReal(state, "desiredDeltaTExact");
    if (desired < 0)
        throw state.error("desiredDeltaTExact", "the time step " + show(desired) + " is negative");
    const long long index = state.get<long long>("timeIndex");
    if (index < 0) throw state.error("timeIndex", "the step index " + std::to_string(index) + " is negative");
    const long long writes = state.get<long long>("writeIndex");
    if (writes < 0)
        throw state.error("writeIndex", "the write index " + std::to_string(writes) + " is negative");
    value_ = value, deltaT_ = dt, desiredDeltaT_ = desired, timeIndex_ = index, writeIndex_ = writes;
    timeName_ = nameOf(value_);
    state.markAllRead();
}

bool Time::finished() const {
    return !(value_ < endTime_ - landing * std::max(std::abs(endTime_), deltaT_));
}

std::vector<double> Time::predictedWriteTimes() const {
    // Only the last million writes are looked at: the names crowd together at the largest times.
    constexpr double most = 1e6;
    std::vector<double> times;
    if (finished()) return times;
    const double end = endTime_ - landing * std::abs(endTime_);
    if (writeControl_ == WriteControl::timeStep) {
        if (adjustTimeStep_) return {};  // steps unknown until run
        const double spacing = fixedDeltaT_ * writeInterval_;
        const double count = std::floor((endTime_ - value_) / spacing);
        const double first = std::max(1.0, count - most);
        for (double k = first; value_ + k * spacing < end; ++k) times.push_back(value_ + k * spacing);
    } else {
        const double count = std::floor(endTime_ / writeInterval_) - double(writeIndex_);
        const double first = double(writeIndex_) + std::max(1.0, count - most);
        for (double k = first; k * writeInterval_ < end; ++k)
            if (k * writeInterval_ > value_) times.push_back(k * writeInterval_);
    }
    times.push_back(endTime_);
    return times;
}

namespace {
// The first pair of consecutive times (after `startName`) that `precision` digits name alike.
std::optional<std::pair<double, double>> collision(const std::vector<double>& times, double start,
                                                   const std::string& startName, int precision) {
    char a[64], b[64];
    std::snprintf(a, sizeof a, "%s", startName.c_str());
    double previous = start;
    for (double t : times) {
        std::snprintf(b, sizeof b, "%.*g", precision, t);
        if (std::strcmp(a, b) == 0) return std::make_pair(previous, t);
        std::memcpy(a, b, sizeof a);
        previous = t;
    }
    return std::nullopt;
}
}  // namespace

void Time::checkWriteNames() const {
    const auto times = predictedWriteTimes();
    const auto clash = collision(times, value_, timeName_, writePrecision_);
    if (!clash) return;
    int needed = writePrecision_ + 1;
    while (needed < 17 && collision(times, value_, timeName_, needed)) ++needed;
    throw InputError(namesWhere_, namesScope_,
                     "writePrecision " + std::to_string(writePrecision_) + " names the write times " +
                         show(clash->first) + " and " + show(clash->second) + " alike ('" +
                         nameOf(clash->second) +
                         "'): the second write would replace the first. Set writePrecision " +
                         std::to_string(needed) + " (or more), or a larger writeInterval");
}

std::string Time::state() const {
    std::ostringstream s;
    s.precision(17);
    s << "time               " << value_ << ";\n"
      << "timeExact          \"" << exactRealText(value_) << "\";\n"
      << "deltaTExact        \"" << exactRealText(deltaT_) << "\";\n"
      << "desiredDeltaTExact \"" << exactRealText(desiredDeltaT_) << "\";\n"
      << "timeIndex          " << timeIndex_ << ";\n"
      << "writeIndex         " << writeIndex_ << ";\n";
    return s.str();
}

std::string Time::nameOf(double t) const {
    char s[64];
    std::snprintf(s, sizeof s, "%.*g", writePrecision_, t);
    return s;
}

bool Time::running() const {
    if (stopAt_ != StopAt::endTime) return false;
    return value_ < endTime_ - landing * std::max(std::abs(endTime_), deltaT_);
}

double Time::nextWriteTime() const {
    return double(writeIndex_ + 1) * writeInterval_;
}

double Time::chooseDeltaT(const TimeStepVote& stable) {
    lastVote_ = stable;
    // An infinite vote means "no limit" (particles at rest); zero, negative or NaN means the state is broken.
    if (!(stable.deltaT > 0))
        throw RunError("the stable time step (" + stable.reason + ") is " + std::to_string(stable.deltaT) +
                       " at time " + timeName_ + ", step " + std::to_string(timeIndex_));
    double dt;
    if (adjustTimeStep_) {
        // Grow by at most 20% a step: a sudden jump would let a transient outrun the vote.
        const double previous = desiredDeltaT_ > 0 ? desiredDeltaT_ : fixedDeltaT_;
        dt = std::min({stable.deltaT, maxDeltaT_, 1.2 * previous});
        if (dt < minDeltaT_) {
            std::ostringstream s;
            s << "the time step collapsed: dt = " << dt << " (" << stable.reason << ") at time " << timeName_
              << ", step " << timeIndex_ << ", is below minDeltaT " << minDeltaT_
              << "; at this step the run would need " << (endTime_ - value_) / dt
              << " more steps. Look for what makes the step so small (a huge "
              << "acceleration or speed, a tiny length scale), or set minDeltaT in "
              << controlDictPath_.string() << " (0: no limit)";
            throw RunError(s.str());
        }
    } else {
        dt = fixedDeltaT_;
        if (dt > stable.deltaT * (1 + 1e-12)) {
            std::ostringstream s;
            s << "deltaT " << dt << " exceeds the stable time step " << stable.deltaT << " (" << stable.reason
              << ") at time " << timeName_ << ", step " << timeIndex_
              << "; lower deltaT or set adjustTimeStep yes in controlDict";
            throw RunError(s.str());
        }
    }
    desiredDeltaT_ = dt;

    // Land exactly on the write times (adjustableRunTime) by spreading the remaining interval over
    // equal steps rather than leaving one sliver step, and on the end time with the last step.
    // The last step before a landing is always `target - t` exactly, so a run that ends at a
    // write time and is restarted from it takes the same steps as one that never stopped.
    auto landOn = [&](double target, bool spread) {
        const double remaining = target - value_;
        if (remaining <= 0) return;
        if (remaining <= dt * (1 + landing)) {
            dt = remaining;
        } else if (spread) {
            // A whole number of steps to within round-off is taken as that number: ceil() of
            // 2000.0000001 would keep dt and leave a sliver step before every write.
            const double ratio = remaining / dt;
            double steps = std::round(ratio);
            if (std::abs(ratio - steps) > landing * ratio) steps = std::ceil(ratio);
            if (steps < 1e9) dt = remaining / steps;
        }
    };
    if (writeControl_ == WriteControl::adjustableRunTime) landOn(nextWriteTime(), true);
    landOn(endTime_, false);
    deltaT_ = dt;
    return dt;
}

void Time::advance(double dt) {
    deltaT_ = dt;
    value_ += dt;
    ++timeIndex_;
    const bool atEnd = !running();
    switch (writeControl_) {
        case WriteControl::timeStep:
            writeTime_ = timeIndex_ % std::int64_t(writeInterval_) == 0;
            break;
        case WriteControl::runTime:
        case WriteControl::adjustableRunTime: {
            const auto index = std::int64_t(std::floor(value_ / writeInterval_ * (1 + landing) + landing));
            writeTime_ = index > writeIndex_;
            if (writeTime_) writeIndex_ = index;
            break;
        }
    }
    // The final state is always written: a run's end is what users look at first.
    if (atEnd) writeTime_ = true;
    // Snap the name (not the value) to the write time it landed on, so directories read 0.1, not
    // 0.0999999999.
    timeName_ = nameOf(value_);
    // Writes start-up could not foresee (adjustTimeStep with writeControl timeStep, a changed
    // writeInterval) are checked here, before the directory of an earlier time is replaced.
    if (!writeTime_ || timeName_ != writtenName_) return;
    std::string message = "the write at t = " + show(value_) + " (step " + std::to_string(timeIndex_) +
                          ") would be named '" + timeName_ +
                          "', like the previous write: it would replace that directory. writePrecision " +
                          std::to_string(writePrecision_) + " is too low for times this close; raise it in " +
                          controlDictPath_.string() + " and restart from the latest time";
    // Called while a failed step is handled (to write the failing state): that failure is what
    // the user must read, so it leads, and its state is not written.
    if (const std::exception_ptr failure = std::current_exception()) {
        try {
            std::rethrow_exception(failure);
        } catch (const std::exception& e) {
            message = std::string(e.what()) + "\n(the failing state is not written: " + message + ")";
        } catch (...) {
        }
    }
    throw RunError(message);
}

}  // namespace mfdyn
