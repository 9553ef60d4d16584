// Run control: which steps write, how steps land on write and end times, the stability check,
// and the exact restart state. Times are compared exactly where the design promises exactness.
#include "core/Dictionary.hpp"
#include "core/Time.hpp"

#include <gtest/gtest.h>

#include <unistd.h>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <tuple>
#include <vector>

using namespace mfdyn;

namespace {

// The message of the InputError `text` gives, "" when it gives none.
std::string inputError(const std::string& text, double start = 0, const std::string& startName = "0") {
    try {
        Time time("/nonexistent/controlDict", Dictionary::parse(text, "controlDict"));
        time.start(start, startName);
    } catch (const InputError& e) {
        return e.what();
    }
    return "";
}

bool has(const std::string& text, const std::string& part) {
    return text.find(part) != std::string::npos;
}

Time makeTime(const std::string& text) {
    const Dictionary dict = Dictionary::parse(text, "controlDict");
    Time time("/nonexistent/controlDict", dict);
    time.start(0.0, "0");
    return time;
}

const TimeStepVote unlimited{std::numeric_limits<double>::infinity(), "none"};

// Runs to the end with a constant vote; returns the times written.
std::vector<double> run(Time& time, const TimeStepVote& vote, std::vector<double>* steps = nullptr) {
    std::vector<double> writes;
    while (time.running()) {
        const double dt = time.chooseDeltaT(vote);
        if (steps) steps->push_back(dt);
        time.advance(dt);
        if (time.writeTime()) writes.push_back(time.value()), time.wrote();
    }
    return writes;
}

}  // namespace

TEST(Time, TimeStepControlWritesEveryNthStepAndTheEnd) {
    Time time = makeTime("endTime 1; deltaT 0.1; writeControl timeStep; writeInterval 3;");
    const auto writes = run(time, unlimited);
    ASSERT_EQ(writes.size(), 4u);  // steps 3, 6, 9 and the final step 10
    EXPECT_NEAR(writes[0], 0.3, 1e-15);
    EXPECT_NEAR(writes[2], 0.9, 1e-15);
    EXPECT_EQ(writes[3], 1.0);
    EXPECT_EQ(time.timeIndex(), 10);
}

TEST(Time, RunTimeControlWritesOnTheFirstStepPastEachInterval) {
    Time time = makeTime("endTime 0.3; deltaT 0.04; writeControl runTime; writeInterval 0.1;");
    const auto writes = run(time, unlimited);
    // 0.04, 0.08, 0.12 (write), 0.16, 0.20 (write), 0.24, 0.28, 0.30 (write: interval and end)
    ASSERT_EQ(writes.size(), 3u);
    EXPECT_NEAR(writes[0], 0.12, 1e-15);
    EXPECT_NEAR(writes[1], 0.20, 1e-15);
    EXPECT_EQ(writes[2], 0.3);
}

TEST(Time, AdjustableRunTimeLandsExactlyOnWriteTimesWithEqualSteps) {
    Time time = makeTime("endTime 0.2; deltaT 0.03; writeControl adjustableRunTime; writeInterval 0.1;");
    std::vector<double> steps;
    const auto writes = run(time, unlimited, &steps);
    ASSERT_EQ(writes.size(), 2u);
    EXPECT_NEAR(writes[0], 0.1, 1e-16);
    EXPECT_EQ(writes[1], 0.2);
    // 0.1 / 0.03 -> 4 equal steps of 0.025, not three of 0.03 and a sliver of 0.01.
    ASSERT_EQ(steps.size(), 8u);
    for (double dt : steps) EXPECT_NEAR(dt, 0.025, 1e-15);
}

TEST(Time, LastStepLandsExactlyOnTheEndTime) {
    Time time = makeTime("endTime 1; deltaT 0.3; writeControl timeStep; writeInterval 100;");
    std::vector<double> steps;
    const auto writes = run(time, unlimited, &steps);
    ASSERT_EQ(steps.size(), 4u);
    EXPECT_NEAR(steps.back(), 0.1, 1e-15);
    EXPECT_EQ(time.value(), 1.0);
    ASSERT_EQ(writes.size(), 1u);  // the end is always written
}

TEST(Time, FixedDeltaTAboveTheStableStepIsARunErrorNamingTheLimit) {
    Time time = makeTime("endTime 1; deltaT 0.1; writeControl timeStep; writeInterval 1;");
    try {
        time.chooseDeltaT({0.05, "Courant"});
        FAIL() << "no error";
    } catch (const RunError& e) {
        EXPECT_NE(std::string(e.what()).find("Courant"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("adjustTimeStep"), std::string::npos) << e.what();
    }
    EXPECT_THROW(time.chooseDeltaT({std::nan(""), "NaN vote"}), RunError);
}

TEST(Time, AdjustedStepGrowsAtMostTwentyPercentAndRespectsMaxDeltaT) {
    Time time = makeTime(
        "endTime 10; deltaT 0.001; adjustTimeStep yes; maxDeltaT 0.002; writeControl timeStep; writeInterval "
        "1000;");
    const double first = time.chooseDeltaT({1.0, "vote"});
    EXPECT_NEAR(first, 0.0012, 1e-15);
    time.advance(first);
    const double second = time.chooseDeltaT({1.0, "vote"});
    EXPECT_NEAR(second, 0.00144, 1e-15);
    time.advance(second);
    for (int k = 0; k < 10; ++k) time.advance(time.chooseDeltaT({1.0, "vote"}));
    EXPECT_EQ(time.deltaT(), 0.002);
    EXPECT_NEAR(time.chooseDeltaT({1e-5, "vote"}), 1e-5, 1e-20);  // shrinking is immediate
}

TEST(Time, InvalidChoicesListTheValidOnes) {
    try {
        makeTime("endTime 1; deltaT 0.1; writeControl adjustableRuntime; writeInterval 1;");
        FAIL() << "no error";
    } catch (const InputError& e) {
        const std::string what = e.what();
        EXPECT_NE(what.find("controlDict:1:"), std::string::npos) << what;
        EXPECT_NE(what.find("timeStep | runTime | adjustableRunTime"), std::string::npos) << what;
        EXPECT_NE(what.find("did you mean 'adjustableRunTime'"), std::string::npos) << what;
    }
    EXPECT_THROW(makeTime("endTime 1; deltaT -0.1; writeInterval 1;"), InputError);
    EXPECT_THROW(makeTime("endTime 1; deltaT 0.1; writeControl timeStep; writeInterval 2.5;"), InputError);
    EXPECT_THROW(makeTime("endTime 1; deltaT 0.1; writeInterval 1; startFrom lastTime;"), InputError);
}

TEST(Time, StateRoundTripsExactly) {
    Time time = makeTime(
        "endTime 1; deltaT 0.1; adjustTimeStep yes; writeControl adjustableRunTime; writeInterval 0.3;");
    for (int k = 0; k < 7; ++k) time.advance(time.chooseDeltaT({0.0123456789, "vote"}));
    Time copy = makeTime(
        "endTime 1; deltaT 0.1; adjustTimeStep yes; writeControl adjustableRunTime; writeInterval 0.3;");
    // As SolverRun does: start at the directory the state was written in, then restore it.
    copy.start(time.value(), time.timeName());
    copy.restore(Dictionary::parse(time.state(), "state"));
    EXPECT_EQ(copy.value(), time.value());
    EXPECT_EQ(copy.deltaT(), time.deltaT());
    EXPECT_EQ(copy.timeIndex(), time.timeIndex());
    // The continuation is identical step for step.
    for (int k = 0; k < 20 && time.running(); ++k) {
        const double a = time.chooseDeltaT({0.0123456789, "vote"});
        const double b = copy.chooseDeltaT({0.0123456789, "vote"});
        ASSERT_EQ(a, b);
        time.advance(a), copy.advance(b);
        ASSERT_EQ(time.writeTime(), copy.writeTime());
    }
}

TEST(Time, TimeNamesFollowWritePrecision) {
    Time time = makeTime("endTime 1; deltaT 0.1; writeInterval 1; writePrecision 3;");
    EXPECT_EQ(time.nameOf(0.123456), "0.123");
    EXPECT_EQ(time.nameOf(1e-5), "1e-05");
    EXPECT_EQ(time.nameOf(2), "2");
}

TEST(Time, ConstantStepThatDividesTheWriteIntervalLeavesNoSliverStep) {
    // 1e-6 into 0.002 is 2000 steps up to round-off in the accumulated time: every step must stay
    // 1e-6 to within round-off, and each write land on a multiple of 0.002.
    Time time = makeTime("endTime 0.01; deltaT 1e-6; writeControl adjustableRunTime; writeInterval 0.002;");
    std::vector<double> steps;
    const auto writes = run(time, unlimited, &steps);
    ASSERT_EQ(steps.size(), 10000u);
    for (double dt : steps) ASSERT_NEAR(dt, 1e-6, 1e-15);
    ASSERT_EQ(writes.size(), 5u);
    for (std::size_t k = 0; k < writes.size(); ++k) EXPECT_NEAR(writes[k], 0.002 * double(k + 1), 1e-15);
}

// Issue 14: an end at or before the start used to run no step and still rewrite the start's
// particles (and add a state there), exiting 0.
TEST(Time, EndTimeNotAfterStartTimeIsAnErrorAtEndTimesLine) {
    const std::string equal = inputError("startTime 0.5;\nendTime 0.5;\ndeltaT 0.1; writeInterval 1;");
    EXPECT_TRUE(has(equal, "controlDict:2:")) << equal;
    EXPECT_TRUE(has(equal, "endTime 0.5 is not after startTime 0.5")) << equal;
    const std::string before = inputError("endTime -1; deltaT 0.1; writeInterval 1;");
    EXPECT_TRUE(has(before, "controlDict:1:")) << before;
    EXPECT_TRUE(has(before, "not after startTime 0")) << before;
}

// Issue 14: non-finite run controls were taken as they came (an endTime of 1e999 ran forever,
// a NaN writeInterval never wrote); each is now refused at its own line. (Time checks them even
// though the dictionary reader may refuse inf and nan already: a value may come from elsewhere.)
TEST(Time, NonFiniteOrNonPositiveControlsAreErrorsAtTheirLine) {
    const std::vector<std::pair<std::string, std::string>> cases{
        {"endTime 1e999;\ndeltaT 0.1; writeInterval 1;", "endTime must be a finite number"},
        {"endTime -1e999;\ndeltaT 0.1; writeInterval 1;", "endTime must be a finite number"},
        {"startTime -1e999;\nendTime 1; deltaT 0.1; writeInterval 1;", "startTime must be a finite number"},
        {"endTime 1;\ndeltaT 1e999; writeInterval 1;", "deltaT must be positive and finite"},
        {"endTime 1;\ndeltaT 0; writeInterval 1;", "deltaT must be positive and finite"},
        {"endTime 1;\ndeltaT 0.1; writeControl runTime; writeInterval 1e999;",
         "writeInterval must be positive and finite"},
        {"endTime 1;\ndeltaT 0.1; writeControl runTime; writeInterval -0.1;",
         "writeInterval must be positive and finite"},
        {"endTime 1;\ndeltaT 0.1; writeInterval 1; maxDeltaT 1e999;",
         "maxDeltaT must be positive and finite"},
    };
    for (const auto& [text, expected] : cases) {
        const std::string what = inputError(text);
        // 1e999 may also be refused by the parser itself (out of range); either way at its line.
        EXPECT_TRUE(has(what, expected) || (has(expected, "finite") && has(what, "out of range")))
            << text << "\n -> " << what;
        EXPECT_TRUE(has(what, "controlDict:")) << what;
    }
    // On line 2 where the keyword is on line 2.
    EXPECT_TRUE(has(inputError("endTime 1;\ndeltaT 1e999; writeInterval 1;"), "controlDict:2:"));
}

// A restart whose latest time is the end time has nothing to do (SolverRun then ends at once,
// writing nothing); a start before the end has.
TEST(Time, FinishedWhenTheStartIsTheEndTime) {
    Time time = makeTime("startFrom latestTime; endTime 1; deltaT 0.1; writeInterval 1;");
    EXPECT_FALSE(time.finished());
    time.start(1.0, "1");
    EXPECT_TRUE(time.finished());
    EXPECT_FALSE(time.running());
}

// Issue 14: writePrecision 2 with writeInterval 0.05 up to 2 named 1.05 and 1.1 alike (and so
// on: 40 writes into fewer directories, each replacing the previous). Refused at start-up with
// the precision that is needed.
TEST(Time, WriteTimesNamedAlikeAreRefusedAtStartUpWithThePrecisionNeeded) {
    const std::string what = inputError(
        "endTime 2; deltaT 0.01; writeControl adjustableRunTime; writeInterval 0.05; writePrecision 2;");
    EXPECT_TRUE(has(what, "writePrecision 2 names the write times")) << what;
    EXPECT_TRUE(has(what, "Set writePrecision 3")) << what;
    // At writePrecision's line.
    const std::string line2 = inputError(
        "endTime 2; deltaT 0.01; writeControl adjustableRunTime; writeInterval 0.05;\nwritePrecision 2;");
    EXPECT_TRUE(has(line2, "controlDict:2:")) << line2;
    // runTime and a fixed-step timeStep control are foreseen as well.
    EXPECT_TRUE(
        has(inputError("endTime 2; deltaT 0.01; writeControl runTime; writeInterval 0.05; writePrecision 2;"),
            "Set writePrecision 3"));
    EXPECT_TRUE(
        has(inputError("endTime 2; deltaT 0.01; writeControl timeStep; writeInterval 5; writePrecision 2;"),
            "Set writePrecision 3"));
    // The first write against the start's name: from 1 with steps of 1e-3, "1.001" needs 4 digits.
    const std::string first = inputError(
        "startTime 1; endTime 1.005; deltaT 0.001; writeControl timeStep; writeInterval 1; writePrecision 3;",
        1.0, "1");
    EXPECT_TRUE(has(first, "Set writePrecision 4")) << first;
    // Enough digits: no error.
    EXPECT_EQ(
        inputError(
            "endTime 2; deltaT 0.01; writeControl adjustableRunTime; writeInterval 0.05; writePrecision 3;"),
        "");
}

// With adjustTimeStep and writeControl timeStep the write times are not known at start-up: the
// clash is caught at the write, before the earlier directory is replaced.
TEST(Time, WriteNamedLikeThePreviousOneIsARunErrorNamingWritePrecision) {
    Time time = makeTime(
        "endTime 1; deltaT 1e-4; adjustTimeStep yes; writeControl timeStep; writeInterval 1; writePrecision "
        "2;");
    time.advance(time.chooseDeltaT({0.011, "vote"}));  // t = 1.2e-4: "0.00012"
    ASSERT_TRUE(time.writeTime());
    time.wrote();
    time.advance(0.01);  // t = 0.01012: "0.01"
    time.wrote();
    try {
        time.advance(1e-5);  // t = 0.01013: "0.01" again
        FAIL() << "no error";
    } catch (const RunError& e) {
        EXPECT_TRUE(has(e.what(), "would be named '0.01'")) << e.what();
        EXPECT_TRUE(has(e.what(), "writePrecision 2 is too low")) << e.what();
    }
    // While a failed step is handled (SolverRun advances to write the failing state), the
    // failure's own message leads.
    time.wrote();
    try {
        try {
            throw RunError("negative density at particle 7");
        } catch (const RunError&) {
            time.advance(1e-6);  // "0.01" once more
        }
        FAIL() << "no error";
    } catch (const RunError& e) {
        EXPECT_EQ(std::string(e.what()).rfind(
                      "negative density at particle 7\n(the failing state is not written", 0),
                  0u)
            << e.what();
    }
}

namespace {

// A state written at t = 0.25 after 5 steps, with one entry replaced by `key value`.
std::string restoreError(const std::string& key, const std::string& value, const std::string& name = "0.25") {
    const std::string controls = "endTime 1; deltaT 0.05; writeControl timeStep; writeInterval 5;";
    Time source = makeTime(controls);
    for (int k = 0; k < 5; ++k) source.advance(source.chooseDeltaT(unlimited));
    std::string state = source.state();
    const auto at = state.find(key);
    state.replace(at, state.find(';', at) - at, key + " " + value);
    Time time = makeTime(controls);
    time.start(0.25, name);
    try {
        time.restore(Dictionary::parse(state, "0.25/state"));
    } catch (const InputError& e) {
        return e.what();
    }
    return "";
}

}  // namespace

// Issue 14: a state with timeExact "nan" ran at t = nan and wrote a directory `nan`. Every
// value of the state is checked, the error naming the state file and line.
TEST(Time, RestoreRefusesDamagedStatesNamingTheFileAndLine) {
    EXPECT_EQ(restoreError("timeIndex", "5"), "");  // the unchanged state is fine
    const std::vector<std::tuple<std::string, std::string, std::string>> cases{
        {"timeExact", "\"nan\"", "expected an exact finite"},
        {"timeExact", "\"inf\"", "expected an exact finite"},
        {"timeExact", "\"\"", "expected an exact finite"},
        {"timeExact", "\"-0x1p-2\"", "is negative"},
        {"timeExact", "\"0x1p-1\"", "does not match the directory name '0.25'"},
        {"deltaTExact", "\"0x0p+0\"", "is not positive"},
        {"deltaTExact", "\"nan\"", "expected an exact finite"},
        {"desiredDeltaTExact", "\"-0x1p-3\"", "is negative"},
        {"timeIndex", "-1", "step index -1 is negative"},
        {"writeIndex", "-3", "write index -3 is negative"},
    };
    for (const auto& [key, value, expected] : cases) {
        const std::string what = restoreError(key, value);
        EXPECT_TRUE(has(what, expected)) << key << " " << value << " -> " << what;
        EXPECT_TRUE(has(what, "0.25/state:")) << what;
        EXPECT_TRUE(has(what, key)) << what;
    }
    // The name's digits set the tolerance: 0.25 in a directory written with 1 digit, "0.3".
    EXPECT_EQ(restoreError("timeIndex", "5", "0.3"), "");
    EXPECT_TRUE(has(restoreError("timeIndex", "5", "0.4"), "does not match"));
    EXPECT_TRUE(has(restoreError("timeIndex", "5", "0.26"), "does not match"));
}

// A controlDict re-read that fails half way keeps all the old controls: the entries before the
// bad one used to be applied already (here startTime), against "keeping the old controls".
TEST(Time, FailedReReadKeepsEveryOldControl) {
    namespace fs = std::filesystem;
    const fs::path dir = fs::temp_directory_path() / ("mfdynTimeReRead" + std::to_string(::getpid()));
    fs::create_directories(dir);
    const fs::path file = dir / "controlDict";
    std::ofstream(file) << "endTime 1; deltaT 0.1; writeInterval 1;\n";
    Time time(file, Dictionary::read(file));
    time.start(0.0, "0");
    std::ofstream(file) << "startTime 0.5; endTime 1; deltaT 0.2; writeInterval 1; writePrecision 99;\n";
    fs::last_write_time(file, fs::last_write_time(file) + std::chrono::seconds(5));
    EXPECT_EQ(time.checkModified(), "");
    EXPECT_EQ(time.startTime(), 0.0);
    EXPECT_EQ(time.deltaT(), 0.1);
    EXPECT_EQ(time.writePrecision(), 6);
    fs::remove_all(dir);
}

// Issue 14 (fuzz fixtures hugeGravityStepCollapse, tinyLengthScale): an adjusted step that
// shrinks without bound ran forever. Below minDeltaT (by default 1e-10 of the run's length) it is
// a RunError naming the limiting vote and the steps it would take.
TEST(Time, CollapsedStepIsARunErrorBelowMinDeltaT) {
    Time time =
        makeTime("endTime 1; deltaT 1e-3; adjustTimeStep yes; writeControl timeStep; writeInterval 100;");
    EXPECT_NEAR(time.chooseDeltaT({2e-10, "acceleration"}), 2e-10, 1e-25);  // small, but it can end
    try {
        time.chooseDeltaT({5e-11, "acceleration"});
        FAIL() << "no error";
    } catch (const RunError& e) {
        EXPECT_TRUE(has(e.what(), "the time step collapsed: dt = 5e-11 (acceleration)")) << e.what();
        EXPECT_TRUE(has(e.what(), "below minDeltaT 1e-10")) << e.what();
        EXPECT_TRUE(has(e.what(), "2e+10 more steps")) << e.what();
    }
    // Set explicitly, or switched off with 0.
    Time strict = makeTime(
        "endTime 1; deltaT 1e-3; adjustTimeStep yes; minDeltaT 1e-6; writeControl timeStep; writeInterval "
        "100;");
    EXPECT_THROW(strict.chooseDeltaT({1e-7, "vote"}), RunError);
    Time off = makeTime(
        "endTime 1; deltaT 1e-3; adjustTimeStep yes; minDeltaT 0; writeControl timeStep; writeInterval 100;");
    EXPECT_EQ(off.chooseDeltaT({1e-20, "vote"}), 1e-20);
    // A fixed deltaT below it is refused at start-up, at deltaT's line.
    const std::string fixed = inputError("endTime 1;\ndeltaT 1e-12; writeInterval 1;");
    EXPECT_TRUE(has(fixed, "controlDict:2:")) << fixed;
    EXPECT_TRUE(has(fixed, "the run would take 1000000000000 steps")) << fixed;
    EXPECT_TRUE(
        has(inputError("endTime 1; deltaT 0.1; writeInterval 1; minDeltaT -1;"), "minDeltaT must be >= 0"));
}
