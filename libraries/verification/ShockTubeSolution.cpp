// Exact shock-tube profile: the self-similar Riemann solution (Toro 2009, Ch. 4.5) placed at x0,
//
//     W(x, t) = W_RP((x - x0)/t),   t > 0,
//
// where W_RP is RiemannSolver::sample. Conserved totals over [a, b] obey, while no wave has reached
// a or b, d/dt int_a^b U dx = F(U(a)) - F(U(b)) with U = (rho, rho v, rho E), E = e + v^2/2 and
// F = (rho v, rho v^2 + P, v (rho E + P)) (Toro 2009, Eq. 3.69 in 1D); tests check this balance.
#include "verification/ShockTubeSolution.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include "core/Error.hpp"
#include "core/KeywordSchema.hpp"  // formatKeywordNumber: 1e-320 shows as 9.99989e-321, not 0.000000

namespace mfdyn {

ShockTubeSolution::ShockTubeSolution(double x0, const PrimitiveState& left,
                                     const RiemannEquationOfState& leftEos, const PrimitiveState& right,
                                     const RiemannEquationOfState& rightEos)
    : x0_(x0), solver_(left, leftEos, right, rightEos) {}

FlowState ShockTubeSolution::state(double x, double t) const {
    if (t < 0.0) throw Error("ShockTubeSolution: time must be >= 0, found " + formatKeywordNumber(t));
    if (t == 0.0) return x <= x0_ ? solver_.leftState() : solver_.rightState();
    return solver_.sample((x - x0_) / t);
}

std::vector<FlowState> ShockTubeSolution::profile(std::span<const double> x, double t) const {
    std::vector<FlowState> out;
    out.reserve(x.size());
    for (double xi : x) out.push_back(state(xi, t));
    return out;
}

ShockTubeSolution::WavePositions ShockTubeSolution::wavePositions(double t) const {
    const auto& l = solver_.leftWave();
    const auto& r = solver_.rightWave();
    return {x0_ + l.headSpeed * t, x0_ + l.tailSpeed * t, x0_ + solver_.contactSpeed() * t,
            x0_ + r.tailSpeed * t, x0_ + r.headSpeed * t};
}

ConservedTotals ShockTubeSolution::flux(const FlowState& s) const {
    const double rhoE = s.density * (s.internalEnergy + 0.5 * s.velocity * s.velocity);
    return {s.density * s.velocity, s.density * s.velocity * s.velocity + s.pressure,
            s.velocity * (rhoE + s.pressure)};
}

ConservedTotals ShockTubeSolution::integrate(double a, double b, double t) const {
    if (!(b >= a)) throw Error("ShockTubeSolution::integrate: needs a <= b");
    // Break points: the wave edges, so that each piece is uniform or lies inside one fan.
    std::vector<double> cuts{a, b};
    if (t > 0.0) {
        const auto w = wavePositions(t);
        for (double x : {w.leftHead, w.leftTail, w.contact, w.rightTail, w.rightHead})
            if (x > a && x < b) cuts.push_back(x);
    } else if (x0_ > a && x0_ < b) {
        cuts.push_back(x0_);
    }
    std::sort(cuts.begin(), cuts.end());

    // 5-point Gauss-Legendre nodes and weights on [-1, 1] (exact for degree 9).
    static constexpr std::array<double, 5> node{0.0, 0.5384693101056831, -0.5384693101056831,
                                                0.9061798459386640, -0.9061798459386640};
    static constexpr std::array<double, 5> weight{0.5688888888888889, 0.4786286704993665, 0.4786286704993665,
                                                  0.2369268850561891, 0.2369268850561891};
    constexpr int subintervals = 64;
    ConservedTotals sum;
    for (std::size_t i = 0; i + 1 < cuts.size(); ++i) {
        const double h = (cuts[i + 1] - cuts[i]) / subintervals;
        for (int k = 0; k < subintervals; ++k) {
            const double mid = cuts[i] + (k + 0.5) * h;
            for (std::size_t q = 0; q < node.size(); ++q) {
                const FlowState s = state(mid + 0.5 * h * node[q], t);
                const double w = 0.5 * h * weight[q];
                sum.mass += w * s.density;
                sum.momentum += w * s.density * s.velocity;
                sum.energy += w * s.density * (s.internalEnergy + 0.5 * s.velocity * s.velocity);
            }
        }
    }
    return sum;
}

}  // namespace mfdyn
