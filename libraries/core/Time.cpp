#include "core/Time.hpp"

#include "core/Log.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
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

std::string hexDouble(double x) {
    char s[64];
    std::snprintf(s, sizeof s, "%a", x);
    return s;
}

double parseHexDouble(const Dictionary& state, const std::string& key) {
    const std::string text = state.get<std::string>(key);
    char* end = nullptr;
    const double x = std::strtod(text.c_str(), &end);
    if (*end != '\0') throw state.error(key, "expected an exact (hexadecimal) real, found '" + text + "'");
    return x;
}

double positive(const Dictionary& dict, const std::string& key, double value) {
    if (!(value > 0)) throw dict.error(key, key + " must be positive, found " + std::to_string(value));
    return value;
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
    startTime_ = dict.getOrDefault<double>("startTime", 0.0);
    stopAt_ = readChoice<StopAt>(
        dict, "stopAt", StopAt::endTime,
        {{"endTime", StopAt::endTime}, {"writeNow", StopAt::writeNow}, {"noWriteNow", StopAt::noWriteNow}});
    endTime_ = dict.get<double>("endTime");
    fixedDeltaT_ = positive(dict, "deltaT", dict.get<double>("deltaT"));
    adjustTimeStep_ = dict.getOrDefault<bool>("adjustTimeStep", false);
    maxCo_ = positive(dict, "maxCo", dict.getOrDefault<double>("maxCo", 1.0));
    maxDeltaT_ = positive(dict, "maxDeltaT", dict.getOrDefault<double>("maxDeltaT", 1e300));
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
    runTimeModifiable_ = dict.getOrDefault<bool>("runTimeModifiable", true);
    if (!adjustTimeStep_) deltaT_ = desiredDeltaT_ = fixedDeltaT_;
}

std::string Time::checkModified() {
    if (!runTimeModifiable_) return {};
    const double now =
        std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
    if (now - lastCheck_ < 0.5) return {};
    lastCheck_ = now;
    std::error_code ec;
    const auto stamp = fs::last_write_time(controlDictPath_, ec);
    if (ec || stamp == controlDictStamp_) return {};
    controlDictStamp_ = stamp;

    const double oldEnd = endTime_, oldInterval = writeInterval_;
    const StopAt oldStop = stopAt_;
    // A half-edited file must not kill a long run: keep the old controls and say why.
    try {
        readControls(Dictionary::read(controlDictPath_));
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
}

void Time::restore(const Dictionary& state) {
    value_ = parseHexDouble(state, "timeExact");
    deltaT_ = parseHexDouble(state, "deltaTExact");
    desiredDeltaT_ = parseHexDouble(state, "desiredDeltaTExact");
    timeIndex_ = state.get<long long>("timeIndex");
    writeIndex_ = state.get<long long>("writeIndex");
    timeName_ = nameOf(value_);
    state.markAllRead();
}

std::string Time::state() const {
    std::ostringstream s;
    s.precision(17);
    s << "time               " << value_ << ";\n"
      << "timeExact          \"" << hexDouble(value_) << "\";\n"
      << "deltaTExact        \"" << hexDouble(deltaT_) << "\";\n"
      << "desiredDeltaTExact \"" << hexDouble(desiredDeltaT_) << "\";\n"
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
    // An infinite vote means "no limit" (particles at rest); zero, negative or NaN means the state is broken.
    if (!(stable.deltaT > 0))
        throw RunError("the stable time step (" + stable.reason + ") is " + std::to_string(stable.deltaT) +
                       " at time " + timeName_ + ", step " + std::to_string(timeIndex_));
    double dt;
    if (adjustTimeStep_) {
        // Grow by at most 20% a step: a sudden jump would let a transient outrun the vote.
        const double previous = desiredDeltaT_ > 0 ? desiredDeltaT_ : fixedDeltaT_;
        dt = std::min({stable.deltaT, maxDeltaT_, 1.2 * previous});
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
}

}  // namespace mfdyn
