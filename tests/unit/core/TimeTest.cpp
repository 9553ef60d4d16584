// Run control: which steps write, how steps land on write and end times, the stability check,
// and the exact restart state. Times are compared exactly where the design promises exactness.
#include "core/Dictionary.hpp"
#include "core/Time.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

using namespace mfdyn;

namespace {

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
