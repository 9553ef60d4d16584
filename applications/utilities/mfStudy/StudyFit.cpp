#include "StudyFit.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace mfdyn::study {

std::optional<double> logLogSlope(const std::vector<double>& x, const std::vector<double>& y) {
    std::vector<double> lx, ly;
    for (std::size_t i = 0; i < x.size() && i < y.size(); ++i)
        if (x[i] > 0 && y[i] > 0 && std::isfinite(x[i]) && std::isfinite(y[i])) {
            lx.push_back(std::log(x[i]));
            ly.push_back(std::log(y[i]));
        }
    if (lx.size() < 2) return std::nullopt;
    const double n = double(lx.size());
    const double mx = std::accumulate(lx.begin(), lx.end(), 0.0) / n;
    const double my = std::accumulate(ly.begin(), ly.end(), 0.0) / n;
    double sxx = 0, sxy = 0;
    for (std::size_t i = 0; i < lx.size(); ++i) {
        sxx += (lx[i] - mx) * (lx[i] - mx);
        sxy += (lx[i] - mx) * (ly[i] - my);
    }
    // Equal abscissae (every run at one resolution) carry no slope.
    if (sxx <= 1e-24 * n) return std::nullopt;
    return sxy / sxx;
}

std::optional<Richardson> richardson(double h1, double q1, double h2, double q2, double h3, double q3) {
    if (!(h1 > h2 && h2 > h3 && h3 > 0)) return std::nullopt;
    // A missing value (NaN: a run that reported no such measure) carries no order: the sign
    // tests below are all false for NaN, and the bisection then "found" p = 1e-6.
    if (!std::isfinite(q1) || !std::isfinite(q2) || !std::isfinite(q3) || !std::isfinite(h1))
        return std::nullopt;
    const double d12 = q1 - q2, d23 = q2 - q3;
    if (d12 == 0 || d23 == 0 || (d12 > 0) != (d23 > 0)) return std::nullopt;
    const double ratio = d12 / d23;
    const double r12 = h1 / h2, r23 = h2 / h3;
    double p = 0;
    if (std::abs(r12 - r23) <= 1e-9 * r23) {
        p = std::log(ratio) / std::log(r23);
    } else {
        // g(p) = (h1^p - h2^p)/(h2^p - h3^p) rises from ln(h1/h2)/ln(h2/h3) at p -> 0 without bound.
        const auto g = [&](double q) {
            return (std::pow(h1, q) - std::pow(h2, q)) / (std::pow(h2, q) - std::pow(h3, q));
        };
        double lo = 1e-6, hi = 20;
        if (ratio < g(lo) || ratio > g(hi)) return std::nullopt;
        for (int i = 0; i < 200; ++i) {
            const double mid = 0.5 * (lo + hi);
            (g(mid) < ratio ? lo : hi) = mid;
        }
        p = 0.5 * (lo + hi);
    }
    if (!(p > 0) || !std::isfinite(p)) return std::nullopt;
    const double extrapolated = q3 - d23 / (std::pow(r23, p) - 1);
    return Richardson{p, extrapolated};
}

std::vector<std::size_t> paretoFront(const std::vector<double>& cost, const std::vector<double>& error) {
    const auto valid = [&](std::size_t i) {
        return i < cost.size() && i < error.size() && std::isfinite(cost[i]) && std::isfinite(error[i]) &&
               cost[i] > 0 && error[i] > 0;
    };
    std::vector<std::size_t> front;
    for (std::size_t i = 0; i < cost.size(); ++i) {
        if (!valid(i)) continue;
        bool dominated = false;
        for (std::size_t j = 0; j < cost.size() && !dominated; ++j)
            dominated = j != i && valid(j) && cost[j] <= cost[i] && error[j] <= error[i] &&
                        (cost[j] < cost[i] || error[j] < error[i]);
        if (!dominated) front.push_back(i);
    }
    std::sort(front.begin(), front.end(), [&](std::size_t a, std::size_t b) { return cost[a] < cost[b]; });
    return front;
}

std::optional<double> costToReach(const std::vector<double>& cost, const std::vector<double>& error,
                                  double target) {
    for (std::size_t i = 0; i < cost.size() && i < error.size(); ++i) {
        if (!(error[i] <= target)) continue;
        if (i == 0 || !(error[i - 1] > 0) || !(cost[i - 1] > 0) || !(error[i] > 0)) return cost[i];
        // log c linear in log e between the run above the target and the first below it.
        const double s =
            (std::log(target) - std::log(error[i - 1])) / (std::log(error[i]) - std::log(error[i - 1]));
        return std::exp(std::log(cost[i - 1]) + s * (std::log(cost[i]) - std::log(cost[i - 1])));
    }
    return std::nullopt;
}

}  // namespace mfdyn::study
