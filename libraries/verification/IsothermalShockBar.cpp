// Isothermal shock-bar by successive Riemann problems (Zisis 2017 Fig. 5.1; doc/methods/sph-impact.md 8.2;
// the wave-interaction construction of Toro 2009, Ch. 4.9, and Courant & Friedrichs 1948, Ch. III).
//
//   1. t = 0, x = a: Riemann problem bar1 | bar2 (RiemannSolver). Its right shock S1 reaches the
//      quiescent interface b at t1 = (b - a)/S1.
//   2. t = t1, x = b: Riemann problem (star state behind S1, material 2) | bar3. Its left wave is
//      reflected into the shocked bar 2, its right wave transmitted into bar 3.
//
//   W(x, t) = W_1((x - a)/t)            left of the reflected wave's head (or t <= t1, x < b)
//           = W_2((x - b)/(t - t1))     between that head and c
//           = bar3 / bar4               undisturbed
//
// The construction is exact until the next interaction: the transmitted wave reaching c, at
// t1 + (c - b)/S_2R, or the reflected wave's head catching the impact's left wave. For the note's
// data, P = c0^2 (rho - rho0): impact P* = 0.64039, v* = 0.5; t1 = 0.15616; reflected rarefaction
// (head -0.5, tail -0.19562), P* = 0.20992, v* = 0.80438, transmitted shock 1.04387; valid to
// t = 0.5393 (transmitted shock at x = 1.2). The material contact between bars 1 and 2 carries no
// jump (same material, same star density), so the reflected fan crosses it unchanged; a nontrivial
// contact there would start a third interaction, which the constructor rejects.
#include "verification/IsothermalShockBar.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "core/Error.hpp"

namespace mfdyn {
namespace {

// The Riemann problem at b, built once the impact's star state is known.
RiemannSolver transmissionProblem(const RiemannSolver& impact, const RiemannEquationOfState& eos2,
                                  const PrimitiveState& bar3, const RiemannEquationOfState& eos3) {
    const PrimitiveState behind{impact.starDensityRight(), impact.starVelocity(), impact.starPressure()};
    return RiemannSolver(behind, eos2, bar3, eos3);
}

bool same(double u, double v, double scale) {
    return std::abs(u - v) <= 1e-12 * scale;
}

}  // namespace

IsothermalShockBar::IsothermalShockBar(double a, double b, double c, const Bar& bar1, const Bar& bar2,
                                       const Bar& bar3, const Bar& bar4)
    : a_(a),
      b_(b),
      c_(c),
      bar3_(bar3),
      bar4_(bar4),
      impact_(bar1.state, bar1.eos, bar2.state, bar2.eos),
      transmission_(transmissionProblem(impact_, bar2.eos, bar3.state, bar3.eos)) {
    if (!(a < b && b < c)) throw Error("IsothermalShockBar: the interfaces need a < b < c");
    // Pressure and velocity scales for "equal" below.
    const double pScale =
        std::abs(impact_.starPressure()) + std::abs(bar2.state.pressure) +
        bar2.state.density * std::pow(bar2.eos.soundSpeed(bar2.state.density, bar2.state.pressure), 2);
    const double vScale = std::abs(bar1.state.velocity - bar2.state.velocity) + 1.0;
    auto quiescent = [&](const Bar& l, const Bar& r) {
        return same(l.state.pressure, r.state.pressure, pScale) &&
               same(l.state.velocity, r.state.velocity, vScale);
    };
    if (!quiescent(bar2, bar3) || !quiescent(bar3, bar4))
        throw Error(
            "IsothermalShockBar: bars 2|3 and 3|4 must have equal pressure and velocity at t = 0 "
            "(only the impact at a may start waves)");
    if (!(bar1.eos == bar2.eos) ||
        !same(impact_.starDensityLeft(), impact_.starDensityRight(), impact_.starDensityLeft()))
        throw Error(
            "IsothermalShockBar: bars 1 and 2 must share their material and have equal star densities; "
            "otherwise the reflected wave interacts with the contact between them");
    if (impact_.rightWave().kind != RiemannSolver::WaveKind::shock || !(impact_.rightWave().headSpeed > 0.0))
        throw Error("IsothermalShockBar: the impact must send a shock towards b");
    t1_ = (b_ - a_) / impact_.rightWave().headSpeed;

    const double transmitted = transmission_.rightWave().headSpeed;
    if (transmitted > 0.0) tEnd_ = std::min(tEnd_, t1_ + (c_ - b_) / transmitted);
    // The reflected wave's head, b + h (t - t1), meets the impact's left wave's tail, a + s t.
    const double h = transmission_.leftWave().headSpeed, s = impact_.leftWave().tailSpeed;
    if (h < s) tEnd_ = std::min(tEnd_, (b_ - a_ - h * t1_) / (s - h));
}

IsothermalShockBar IsothermalShockBar::zisis2017() {
    const auto material1 = RiemannEquationOfState::linearBarotropic(1.0, 1.0);
    const auto material2 = RiemannEquationOfState::linearBarotropic(0.25, 0.5);
    return IsothermalShockBar(0.6, 0.8, 1.2, {{1.0, 1.0, 0.0}, material1}, {{1.0, 0.0, 0.0}, material1},
                              {{0.25, 0.0, 0.0}, material2}, {{1.0, 0.0, 0.0}, material1});
}

FlowState IsothermalShockBar::state(double x, double t) const {
    if (!(t >= 0.0) || t > tEnd_) {
        std::ostringstream s;
        s.precision(10);
        s << "IsothermalShockBar: t = " << t << " is outside [0, " << tEnd_
          << "], where the two-Riemann-problem construction is exact (a later wave interaction follows)";
        throw Error(s.str());
    }
    auto undisturbed = [&](const Bar& bar) {
        return FlowState{bar.state.density, bar.state.velocity, bar.state.pressure,
                         bar.eos.internalEnergy(bar.state.density, bar.state.pressure)};
    };
    if (x >= c_) return undisturbed(bar4_);
    if (t <= t1_) {
        if (x >= b_) return undisturbed(bar3_);
        if (t == 0.0) return x < a_ ? impact_.leftState() : impact_.rightState();
        return impact_.sample((x - a_) / t);
    }
    if (x < b_ + transmission_.leftWave().headSpeed * (t - t1_)) return impact_.sample((x - a_) / t);
    return transmission_.sample((x - b_) / (t - t1_));
}

std::vector<FlowState> IsothermalShockBar::profile(std::span<const double> x, double t) const {
    std::vector<FlowState> out;
    out.reserve(x.size());
    for (double xi : x) out.push_back(state(xi, t));
    return out;
}

}  // namespace mfdyn
