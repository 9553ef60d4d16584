// mfStudy's numbers against closed forms: on data made from Q = Q0 + C h^p the fit and
// Richardson must return p and Q0 to round-off (1e-12 relative leaves room for log/pow).
#include "StudyFit.hpp"

#include <gtest/gtest.h>

#include <cmath>

using namespace mfdyn::study;

TEST(StudyFit, slopeOfAPowerLawIsItsExponent) {
    const std::vector<double> h{0.04, 0.02, 0.01, 0.005};
    std::vector<double> e;
    for (double x : h) e.push_back(3.0 * std::pow(x, 1.7));
    ASSERT_TRUE(logLogSlope(h, e));
    EXPECT_NEAR(*logLogSlope(h, e), 1.7, 1e-12);
}

TEST(StudyFit, slopeIsTheLeastSquaresLineOfTheLogs) {
    // Logs (0,0), (1,1), (2,3): the least squares slope is 1.5, by hand.
    const std::vector<double> x{1, std::exp(1.0), std::exp(2.0)};
    const std::vector<double> y{1, std::exp(1.0), std::exp(3.0)};
    EXPECT_NEAR(*logLogSlope(x, y), 1.5, 1e-12);
}

TEST(StudyFit, slopeNeedsTwoDistinctPositivePoints) {
    EXPECT_FALSE(logLogSlope({0.1}, {1.0}));
    EXPECT_FALSE(logLogSlope({0.1, 0.1}, {1.0, 2.0}));
    EXPECT_FALSE(logLogSlope({0.1, 0.05}, {1.0, 0.0}));  // a zero error has no logarithm
    EXPECT_FALSE(logLogSlope({0.1, 0.05}, {1.0, NAN}));
}

TEST(StudyFit, richardsonWithConstantRatio) {
    const auto q = [](double h) { return 7.0 + 2.5 * std::pow(h, 0.5); };
    const auto r = richardson(0.4, q(0.4), 0.2, q(0.2), 0.1, q(0.1));
    ASSERT_TRUE(r);
    EXPECT_NEAR(r->order, 0.5, 1e-10);
    EXPECT_NEAR(r->extrapolated, 7.0, 1e-10);
}

TEST(StudyFit, richardsonWithUnequalRatios) {
    // The Taylor bar's lattices 0.45, 0.35, 0.30 mm: the ratio is not constant.
    const auto q = [](double h) { return 7.5 - 1.2 * std::pow(h, 1.3); };
    const auto r = richardson(0.45, q(0.45), 0.35, q(0.35), 0.30, q(0.30));
    ASSERT_TRUE(r);
    EXPECT_NEAR(r->order, 1.3, 1e-9);
    EXPECT_NEAR(r->extrapolated, 7.5, 1e-9);
}

TEST(StudyFit, richardsonRefusesOscillationAndBadLevels) {
    EXPECT_FALSE(richardson(0.4, 1.0, 0.2, 2.0, 0.1, 1.5));  // differences change sign
    EXPECT_FALSE(richardson(0.4, 1.0, 0.2, 1.0, 0.1, 1.0));  // no change at all
    EXPECT_FALSE(richardson(0.1, 1.0, 0.2, 2.0, 0.4, 2.5));  // not refined
}

TEST(StudyFit, richardsonRefusesMissingValues) {
    // A scheme whose runs report no such measure (NaN) has no order: it printed "Richardson
    // order 1e-06" with an empty extrapolation (the twisting column's study, measured on no norm).
    EXPECT_FALSE(richardson(0.4, NAN, 0.2, NAN, 0.1, NAN));
    EXPECT_FALSE(richardson(0.4, 1.0, 0.2, NAN, 0.1, 0.25));
    EXPECT_FALSE(richardson(0.4, 1.0, 0.2, 0.5, 0.1, INFINITY));
    // Unequal ratios take the bisection: a NaN must not reach it either.
    EXPECT_FALSE(richardson(0.5, NAN, 0.3, NAN, 0.1, NAN));
    EXPECT_FALSE(richardson(1.0 / 6, NAN, 1.0 / 8, NAN, 1.0 / 12, NAN));  // the twisting column's levels
}

TEST(StudyFit, paretoFrontKeepsTheUndominated) {
    // (1, 0.5) (2, 0.1) (3, 0.2) (4, 0.05) (2, 0.3): the third is beaten by the second, the
    // fifth by the second too (as costly, more wrong).
    const std::vector<double> cost{1, 2, 3, 4, 2};
    const std::vector<double> error{0.5, 0.1, 0.2, 0.05, 0.3};
    EXPECT_EQ(paretoFront(cost, error), (std::vector<std::size_t>{0, 1, 3}));
    EXPECT_EQ(paretoFront({1, NAN}, {0.1, 0.01}), (std::vector<std::size_t>{0}));
}

TEST(StudyFit, costToReachInterpolatesInLogLog) {
    // Error 1e-1 at 1 s, 1e-3 at 100 s: the line e = 0.1 c^-1 reaches 1e-2 at 10 s.
    const std::vector<double> cost{1, 100};
    const std::vector<double> error{1e-1, 1e-3};
    EXPECT_NEAR(*costToReach(cost, error, 1e-2), 10.0, 1e-9);
    EXPECT_DOUBLE_EQ(*costToReach(cost, error, 0.5), 1.0);
    EXPECT_FALSE(costToReach(cost, error, 1e-4));
}
