// orderEstimate's numbers against closed forms (equations in
// applications/utilities/orderEstimate/OrderEstimate.cpp). Tolerances: alpha is a quotient of two
// expm1 values, each within an ulp or two, so it is exact to a few units of 1e-16 relative; 1e-14
// leaves a factor of 20. The inversion bisects to a few ulp of p; what limits it is the round-off
// of alpha near the root divided by |d ln alpha / dp| (about ln 2 here), ~1e-15, so 1e-10 is
// loose by five orders and still catches any wrong formula (a wrong d or a swapped ratio moves p
// by O(1)).
#include "OrderEstimate.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>

using mfdyn::OrderEstimate;

namespace {

// The lemma's alpha written as printed, with pow: the independent reference for the expm1 form.
double alphaAsPrinted(double n1, double n2, double n3, int d, double p) {
    return (std::pow(n2 / n3, p / d) - 1.0) / (1.0 - std::pow(n2 / n1, p / d));
}

}  // namespace

TEST(OrderEstimate, geometricRefinementIn3DGivesTwoToTheMinusP) {
    // N ratio 8 in 3D halves dx: alpha(p) = 2^-p exactly.
    const OrderEstimate estimate({1000, 8000, 64000}, 3);
    for (double p : {-10.0, -2.0, -0.5, 0.25, 0.5, 1.0, 2.0, 3.0, 5.0, 20.0}) {
        const double expected = std::pow(2.0, -p);
        EXPECT_NEAR(estimate.alpha(p), expected, 1e-14 * expected) << "p = " << p;
    }
}

TEST(OrderEstimate, geometricRefinementIn2D) {
    const OrderEstimate estimate({100, 400, 1600}, 2);
    for (double p : {0.5, 1.0, 2.0})
        EXPECT_NEAR(estimate.alpha(p), std::pow(2.0, -p), 1e-14 * std::pow(2.0, -p));
}

TEST(OrderEstimate, inversionRecoversTheOrderFromTheClosedFormRatio) {
    const OrderEstimate estimate({1000, 8000, 64000}, 3);
    for (double p : {0.5, 1.0, 2.0, 3.0, -0.5}) {
        const auto order = estimate.order(std::pow(2.0, -p));
        ASSERT_EQ(order.status, OrderEstimate::Status::ok) << "p = " << p;
        EXPECT_NEAR(order.value, p, 1e-10);
    }
}

TEST(OrderEstimate, inversionFromTheTwoDifferences) {
    // phi_k = phi* + C N_k^(-p/d): the differences of the three values give the order back.
    const double p = 1.5, c = 0.37;
    const auto phi = [&](double n) { return 2.0 + c * std::pow(n, -p / 3.0); };
    const OrderEstimate estimate({1000, 8000, 64000}, 3);
    const auto order = estimate.order(std::abs(phi(64000) - phi(8000)), std::abs(phi(8000) - phi(1000)));
    ASSERT_EQ(order.status, OrderEstimate::Status::ok);
    // The differences lose about 2 digits to cancellation (|phi2 - phi1| ~ 1e-2 of phi): 1e-10 holds.
    EXPECT_NEAR(order.value, p, 1e-10);
}

TEST(OrderEstimate, limitAtZeroOrder) {
    const OrderEstimate estimate({1244, 2400, 4200}, 3);
    const double limit = std::log(4200.0 / 2400.0) / std::log(2400.0 / 1244.0);
    EXPECT_NEAR(estimate.alphaAtZeroOrder(), limit, 1e-14 * limit);  // two logs, each within an ulp
    EXPECT_EQ(estimate.alpha(0.0), estimate.alphaAtZeroOrder());
    // Continuous through p = 0: alpha'(0) is O(1), so alpha(+-1e-8) is within ~1e-8 of the limit;
    // the pow form loses half its digits there, the expm1 form does not (2e-8 is the slope bound).
    for (double p : {-1e-8, 1e-8, 1e-300}) EXPECT_NEAR(estimate.alpha(p), limit, 2e-8) << "p = " << p;
    const auto order = estimate.order(limit);
    ASSERT_EQ(order.status, OrderEstimate::Status::ok);
    EXPECT_NEAR(order.value, 0.0, 1e-10);
    // Geometric: the limit is 1 (equal log steps), and ratio 1 means order 0.
    EXPECT_NEAR(OrderEstimate({1000, 8000, 64000}, 3).order(1.0).value, 0.0, 1e-10);
}

TEST(OrderEstimate, nonGeometricCountsMatchThePrintedFormula) {
    const OrderEstimate estimate({1244, 2400, 4200}, 3);
    for (double p : {-3.0, -0.5, 0.3, 1.0, 1.7, 2.0, 4.0}) {
        const double expected = alphaAsPrinted(1244, 2400, 4200, 3, p);
        EXPECT_NEAR(estimate.alpha(p), expected, 1e-12 * expected) << "p = " << p;
    }
    for (double p : {0.5, 1.0, 2.0, 3.0, -0.5}) {
        const auto order = estimate.order(alphaAsPrinted(1244, 2400, 4200, 3, p));
        ASSERT_EQ(order.status, OrderEstimate::Status::ok) << "p = " << p;
        EXPECT_NEAR(order.value, p, 1e-10) << "p = " << p;
    }
}

TEST(OrderEstimate, alphaDecreasesStrictly) {
    const OrderEstimate estimate({1244, 2400, 4200}, 2);
    double previous = estimate.alpha(OrderEstimate::lowestOrder);
    for (double p = OrderEstimate::lowestOrder + 0.125; p <= OrderEstimate::highestOrder; p += 0.125) {
        const double a = estimate.alpha(p);
        EXPECT_LT(a, previous) << "p = " << p;
        EXPECT_GT(a, 0.0);
        previous = a;
    }
}

TEST(OrderEstimate, ratiosOutsideTheBracketAreReportedNotClamped) {
    const OrderEstimate estimate({1000, 8000, 64000}, 3);
    // 2^11 > alpha(-10) = 2^10: below the bracket; 2^-21 < alpha(20): above; 0: the finer pair agrees.
    EXPECT_EQ(estimate.order(std::pow(2.0, 11)).status, OrderEstimate::Status::belowRange);
    EXPECT_TRUE(std::isnan(estimate.order(std::pow(2.0, 11)).value));
    EXPECT_EQ(estimate.order(std::pow(2.0, -21)).status, OrderEstimate::Status::aboveRange);
    EXPECT_EQ(estimate.order(0.0).status, OrderEstimate::Status::aboveRange);
    EXPECT_EQ(estimate.order(0.0, 1.0).status, OrderEstimate::Status::aboveRange);
    // No ratio at all.
    EXPECT_EQ(estimate.order(1.0, 0.0).status, OrderEstimate::Status::undefined);
    EXPECT_EQ(estimate.order(0.0, 0.0).status, OrderEstimate::Status::undefined);
    EXPECT_EQ(estimate.order(std::nan(""), 1.0).status, OrderEstimate::Status::undefined);
    EXPECT_EQ(estimate.order(-1.0).status, OrderEstimate::Status::undefined);
    // Differences at round-off level of the values are none: a field the runs share.
    EXPECT_EQ(estimate.order(2e-16, 3e-16, 1.0).status, OrderEstimate::Status::undefined);
    EXPECT_EQ(estimate.order(0.5e-10, 1e-10, 1.0).status, OrderEstimate::Status::undefined);
    EXPECT_EQ(estimate.order(0.5e-9, 2e-9, 1.0).status, OrderEstimate::Status::ok);
    EXPECT_NEAR(estimate.order(0.5e-9, 2e-9, 1.0).value, 2.0, 1e-10);
    EXPECT_EQ(estimate.order(std::numeric_limits<double>::infinity()).status,
              OrderEstimate::Status::undefined);
    // The ends themselves are inside.
    EXPECT_NEAR(estimate.order(std::pow(2.0, 10)).value, -10.0, 1e-10);
    EXPECT_NEAR(estimate.order(std::pow(2.0, -20)).value, 20.0, 1e-10);
    EXPECT_EQ(OrderEstimate::statusText(OrderEstimate::Status::belowRange), "below -10");
    EXPECT_EQ(OrderEstimate::statusText(OrderEstimate::Status::aboveRange), "above 20");
}

TEST(OrderEstimate, countsMustIncreaseStrictly) {
    EXPECT_THROW(OrderEstimate({1000, 1000, 8000}, 3), std::invalid_argument);
    EXPECT_THROW(OrderEstimate({8000, 1000, 64000}, 3), std::invalid_argument);
    EXPECT_THROW(OrderEstimate({0, 1000, 8000}, 3), std::invalid_argument);
    EXPECT_THROW(OrderEstimate({10, 100, 1000}, 4), std::invalid_argument);
}

TEST(OrderEstimate, differenceNorms) {
    const std::vector<double> a{1.0, 2.0, 3.0, 4.0}, b{1.0, 4.0, 2.0, 4.0};  // differences 0 -2 1 0
    EXPECT_EQ(OrderEstimate::differenceNorm(a, b, OrderEstimate::Norm::infinity), 2.0);
    EXPECT_NEAR(OrderEstimate::differenceNorm(a, b, OrderEstimate::Norm::l2), std::sqrt(5.0 / 4.0), 1e-15);
    // A NaN anywhere is not hidden by the maximum.
    EXPECT_TRUE(std::isnan(
        OrderEstimate::differenceNorm({1.0, std::nan("")}, {0.0, 0.0}, OrderEstimate::Norm::infinity)));
    EXPECT_TRUE(std::isnan(OrderEstimate::differenceNorm({}, {}, OrderEstimate::Norm::l2)));
    EXPECT_TRUE(std::isnan(OrderEstimate::differenceNorm({1.0}, {1.0, 2.0}, OrderEstimate::Norm::l2)));
}

TEST(OrderEstimate, meanSpacing) {
    EXPECT_NEAR(OrderEstimate::meanSpacing(8.0, 1000.0, 3), 0.2, 1e-15);
    EXPECT_NEAR(OrderEstimate::meanSpacing(2.0, 800.0, 2), 0.05, 1e-16);
    EXPECT_NEAR(OrderEstimate::meanSpacing(3.0, 30.0, 1), 0.1, 1e-16);
}
