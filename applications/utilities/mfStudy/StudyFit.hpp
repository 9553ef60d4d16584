#pragma once
// The numbers a convergence study prints: the observed order of a line of runs (least squares of
// log error on log h, or on log CPU time), Richardson's three-level extrapolation, the Pareto
// front of error against cost, and the cost at which a line first reaches a target error.
// Kept apart from mfStudy.cpp so that the unit tests check them against closed forms.
#include <optional>
#include <vector>

namespace mfdyn::study {

// Slope of log y on log x by least squares over the points with x > 0 and y > 0; empty when
// fewer than two such points remain or all x are equal. For y = C x^p it returns p exactly.
std::optional<double> logLogSlope(const std::vector<double>& x, const std::vector<double>& y);

struct Richardson {
    double order = 0;         // observed order p from the three levels
    double extrapolated = 0;  // Q at h -> 0
};

// Three levels h1 > h2 > h3 with values q1, q2, q3 assumed Q(h) = Q0 + C h^p. For a constant
// ratio r = h1/h2 = h2/h3, p = ln((q1 - q2)/(q2 - q3))/ln r; otherwise p solves
// (q1 - q2)/(q2 - q3) = (h1^p - h2^p)/(h2^p - h3^p) by bisection on (0, 20].
// Empty when the differences change sign (oscillating, not in the asymptotic range), when one is
// zero, when the levels are not distinct and decreasing, or when a value is not finite.
std::optional<Richardson> richardson(double h1, double q1, double h2, double q2, double h3, double q3);

// Indices of the points on the lower-left Pareto front of (cost, error): none other is at most as
// costly and at most as wrong while better in one. Points with a non-positive or non-finite
// value are never on it. Sorted by cost.
std::vector<std::size_t> paretoFront(const std::vector<double>& cost, const std::vector<double>& error);

// Along a line of runs sorted by cost, the cost at which the error first falls to `target`,
// interpolated linearly in log-log between the two runs that bracket it; empty when no run
// reaches it. A first run already below the target gives that run's cost.
std::optional<double> costToReach(const std::vector<double>& cost, const std::vector<double>& error,
                                  double target);

}  // namespace mfdyn::study
