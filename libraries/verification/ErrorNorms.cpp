// Weighted discrete error norms (the particle quadrature of the continuous norms,
// ||e||_p = (int |e|^p dx / |Omega|)^(1/p) ~ (sum_i V_i |e_i|^p / sum_i V_i)^(1/p), with V_i the
// particle volume m_i/rho_i; with equal weights this is the plain particle mean). Normalising by sum w makes
// the norms independent of the window's length and of the particle count, so convergence rates read directly.
// Linf is the plain maximum: a weight would hide a single bad particle, which Linf is meant to show.
#include "verification/ErrorNorms.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "core/Error.hpp"
#include "core/KeywordSchema.hpp"  // formatKeywordNumber: 1e-320 shows as 9.99989e-321, not 0.000000

namespace mfdyn {

ErrorNorms ErrorNorms::compute(std::span<const double> x, std::span<const double> values,
                               std::span<const double> weights, const std::function<double(double)>& exact,
                               double x0, double x1) {
    if (x.size() != values.size() || x.size() != weights.size()) {
        std::ostringstream s;
        s << "ErrorNorms: " << x.size() << " positions, " << values.size() << " values and " << weights.size()
          << " weights; they must match";
        throw Error(s.str());
    }
    if (!(x1 >= x0)) throw Error("ErrorNorms: the window [x0, x1] needs x0 <= x1");
    ErrorNorms n;
    double sum1 = 0.0, sum2 = 0.0;
    for (std::size_t i = 0; i < x.size(); ++i) {
        if (!(weights[i] >= 0.0) || !std::isfinite(weights[i]))
            throw Error("ErrorNorms: weight " + std::to_string(i) + " is " + formatKeywordNumber(weights[i]) +
                        "; weights must be finite and >= 0");
        if (x[i] < x0 || x[i] > x1) continue;
        const double e = values[i] - exact(x[i]);
        if (!std::isfinite(e)) {
            std::ostringstream s;
            s.precision(12);
            s << "ErrorNorms: particle " << i << " at x = " << x[i] << " has value " << values[i]
              << " against exact " << exact(x[i]) << "; the error is not finite";
            throw Error(s.str());
        }
        sum1 += weights[i] * std::abs(e);
        sum2 += weights[i] * e * e;
        n.totalWeight += weights[i];
        n.linf = std::max(n.linf, std::abs(e));
        ++n.count;
    }
    if (n.count == 0 || !(n.totalWeight > 0.0)) {
        std::ostringstream s;
        s << "ErrorNorms: no weighted particle in the window [" << x0 << ", " << x1 << "]";
        throw Error(s.str());
    }
    n.l1 = sum1 / n.totalWeight;
    n.l2 = std::sqrt(sum2 / n.totalWeight);
    return n;
}

}  // namespace mfdyn
