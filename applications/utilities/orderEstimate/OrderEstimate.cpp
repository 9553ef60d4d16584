// The three-resolution order estimate: von Nida 2005, "Numerical simulation of elastic solids
// with the finite pointset method", §7.2.3, Lemma 7.1, after Deuflhard & Hohmann, "Numerical
// Analysis in Modern Scientific Computing" (the estimate of an order from three discretisations
// of a sequence). Summarised in doc/methods/fpm.md §4.11.
//
// Error model. Run k has N_k particles in d dimensions, so its mean mesh size is
// dx_k ∝ N_k^(-1/d), and its field at a fixed point is
//
//     phi_k = phi* + C N_k^(-p/d)     (= phi* + C' dx_k^p),   N1 < N2 < N3.
//
// Then, taking out N2^(-p/d) from both differences,
//
//     phi3 - phi2 = C N2^(-p/d) ((N2/N3)^(p/d) - 1),
//     phi2 - phi1 = C N2^(-p/d) (1 - (N2/N1)^(p/d)),
//
//     (phi3 - phi2) / (phi2 - phi1) = alpha(p) = ((N2/N3)^(p/d) - 1) / (1 - (N2/N1)^(p/d)).
//
// With C = C(x) over a grid of points the differences are C(x) times the same numbers, so the
// ratio of their norms (any norm) is alpha(p) too; that is what the utility measures:
//
//     r = ||phi3 - phi2|| / ||phi2 - phi1||,   p solves alpha(p) = r.
//
// alpha is strictly decreasing in p, from +inf (p -> -inf) to 0 (p -> +inf): with
// s = ln(N3/N2)/d > 0 and t = ln(N2/N1)/d > 0,
//
//     alpha(p) = (1 - e^(-s p)) / (e^(t p) - 1) = s ∫_0^1 e^(-s p u) du / (t ∫_0^1 e^(t p u) du),
//
// a positive decreasing numerator over a positive increasing denominator. So every r > 0 has
// exactly one p, found here by bisection on [lowestOrder, highestOrder] = [-10, 20].
// (doc/methods/fpm.md §4.11 calls alpha increasing; in p it decreases, as shown.) At p = 0
// alpha is 0/0 with the limit s/t = ln(N3/N2)/ln(N2/N1) (both integrals are 1), used there.
// For geometric refinement, N3/N2 = N2/N1 = q^d, alpha(p) = q^(-p) and p = -ln r / ln q.
//
// Numerics: (N2/N3)^(p/d) - 1 is evaluated as expm1(p ln(N2/N3)/d), which keeps its digits
// as p -> 0 where the power form cancels; so alpha is smooth through the removable singularity.
//
// The lemma assumes the error behaves like C N^(-p/d) at all three resolutions (the asymptotic
// range) and that the interpolation onto the grid is more accurate than the runs themselves.
// With a norm of the differences, an error that changes sign between resolutions is not seen
// as such: r is then just a number, and the order it gives is not meaningful.
//
// Mean mesh size: dx = (V / N)^(1/d), V the bodies' total volume (the thesis uses the radius of
// the sphere of volume V/N, (3V/(4 pi N))^(1/3), which differs by a constant factor; the order
// depends on the particle counts only).
#include "OrderEstimate.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>

namespace mfdyn {

namespace {
constexpr double notANumber = std::numeric_limits<double>::quiet_NaN();

std::string formatOrder(double p) {
    char text[32];
    std::snprintf(text, sizeof text, "%g", p);
    return text;
}
}  // namespace

OrderEstimate::OrderEstimate(const std::array<double, 3>& particleCounts, int dimension) {
    const auto [n1, n2, n3] = particleCounts;
    if (dimension < 1 || dimension > 3)
        throw std::invalid_argument("order estimate: dimension " + std::to_string(dimension) +
                                    " is not 1, 2 or 3");
    if (!(n1 > 0.0 && n1 < n2 && n2 < n3 && std::isfinite(n3)))
        throw std::invalid_argument("order estimate: the particle counts must be 0 < N1 < N2 < N3");
    logFineRatio_ = std::log(n2 / n3) / dimension;
    logCoarseRatio_ = std::log(n2 / n1) / dimension;
}

double OrderEstimate::alphaAtZeroOrder() const {
    return -logFineRatio_ / logCoarseRatio_;
}

double OrderEstimate::alpha(double order) const {
    if (order == 0.0) return alphaAtZeroOrder();
    return std::expm1(order * logFineRatio_) / -std::expm1(order * logCoarseRatio_);
}

OrderEstimate::Order OrderEstimate::order(double ratio) const {
    if (!(ratio >= 0.0) || !std::isfinite(ratio)) return {notANumber, Status::undefined};
    if (ratio > alpha(lowestOrder)) return {notANumber, Status::belowRange};
    if (ratio < alpha(highestOrder)) return {notANumber, Status::aboveRange};
    // alpha(lo) >= ratio >= alpha(hi) throughout. The bracket halves until it is a few units in
    // the last place of p wide (55 steps from a width of 30), below any accuracy that r has.
    double lo = lowestOrder, hi = highestOrder;
    for (int step = 0; step < 200; ++step) {
        const double mid = 0.5 * (lo + hi);
        if (hi - lo <= 4 * std::numeric_limits<double>::epsilon() * std::max(1.0, std::abs(mid))) break;
        if (alpha(mid) >= ratio)
            lo = mid;
        else
            hi = mid;
    }
    return {0.5 * (lo + hi), Status::ok};
}

OrderEstimate::Order OrderEstimate::order(double fineDifference, double coarseDifference,
                                          double valueMagnitude) const {
    if (!std::isfinite(fineDifference) || !std::isfinite(coarseDifference) || !(coarseDifference > 0.0) ||
        coarseDifference <= roundOffLevel * std::abs(valueMagnitude))
        return {notANumber, Status::undefined};
    return order(fineDifference / coarseDifference);
}

double OrderEstimate::differenceNorm(const std::vector<double>& a, const std::vector<double>& b, Norm norm) {
    if (a.empty() || a.size() != b.size()) return notANumber;
    double result = 0.0;
    for (std::size_t i = 0; i < a.size(); ++i) {
        const double difference = std::abs(a[i] - b[i]);
        // A NaN must not vanish in std::max: it makes the whole norm NaN.
        if (std::isnan(difference)) return notANumber;
        result = norm == Norm::infinity ? std::max(result, difference) : result + difference * difference;
    }
    return norm == Norm::infinity ? result : std::sqrt(result / double(a.size()));
}

double OrderEstimate::meanSpacing(double totalVolume, double particleCount, int dimension) {
    return std::pow(totalVolume / particleCount, 1.0 / dimension);
}

std::string OrderEstimate::normName(Norm norm) {
    return norm == Norm::infinity ? "infinity" : "l2";
}

std::string OrderEstimate::statusText(Status status) {
    switch (status) {
        case Status::ok:
            return "ok";
        case Status::belowRange:
            return "below " + formatOrder(lowestOrder);
        case Status::aboveRange:
            return "above " + formatOrder(highestOrder);
        case Status::undefined:
            break;
    }
    return "undefined";
}

}  // namespace mfdyn
