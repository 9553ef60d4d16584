// Exact Riemann solver for two materials (Toro 2009, "Riemann Solvers and Numerical Methods for
// Fluid Dynamics", 3rd ed., Ch. 4; two materials as in Ivings, Causon & Toro 1998).
//
//     f(P) = f_L(P) + f_R(P) + (v_R - v_L) = 0,                          (Toro 4.5)
//     v*   = (v_L + v_R)/2 + (f_R(P*) - f_L(P*))/2,                        (Toro 4.9)
//
// with f_K the wave curve of side K's closure (RiemannEquationOfState.cpp). Each f_K is C1 and
// increasing in P, so f has one root above the pressure floor P_min = max(floor_L, floor_R)
// (0 for an ideal gas, -pRef for a stiffened gas, -c0^2 rho0 for a barotropic material) when
// f(P_min) < 0; otherwise the rarefactions open a vacuum (Toro 4.40 generalised) and we throw.
// The root is bracketed and found by Newton steps that fall back to bisection whenever a step
// leaves the bracket, to |dP| <= 1e-12 (|P| + rho c^2) (the pressure scale keeps the test
// meaningful for P* near zero or negative in a barotropic material). Sampling follows Toro 4.5.
#include "verification/RiemannSolver.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "core/Error.hpp"

namespace mfdyn {

RiemannSolver::RiemannSolver(const PrimitiveState& left, const RiemannEquationOfState& leftEos,
                             const PrimitiveState& right, const RiemannEquationOfState& rightEos)
    : left_(left), right_(right), leftEos_(leftEos), rightEos_(rightEos) {
    leftEos_.check(left_, "left");
    rightEos_.check(right_, "right");
    solveStarPressure();

    const auto fL = leftEos_.waveFunction(left_, pStar_), fR = rightEos_.waveFunction(right_, pStar_);
    vStar_ = 0.5 * (left_.velocity + right_.velocity) + 0.5 * (fR.value - fL.value);
    rhoStarL_ = leftEos_.densityBehind(left_, pStar_);
    rhoStarR_ = rightEos_.densityBehind(right_, pStar_);

    if (pStar_ > left_.pressure) {
        const double s = leftEos_.shockSpeed(left_, pStar_, -1);
        leftWave_ = {WaveKind::shock, s, s};
    } else {
        leftWave_ = {WaveKind::rarefaction,
                     left_.velocity - leftEos_.soundSpeed(left_.density, left_.pressure),
                     vStar_ - leftEos_.soundSpeed(rhoStarL_, pStar_)};
    }
    if (pStar_ > right_.pressure) {
        const double s = rightEos_.shockSpeed(right_, pStar_, +1);
        rightWave_ = {WaveKind::shock, s, s};
    } else {
        rightWave_ = {WaveKind::rarefaction,
                      right_.velocity + rightEos_.soundSpeed(right_.density, right_.pressure),
                      vStar_ + rightEos_.soundSpeed(rhoStarR_, pStar_)};
    }
}

void RiemannSolver::solveStarPressure() {
    const double dv = right_.velocity - left_.velocity;
    auto f = [&](double p) {
        const auto l = leftEos_.waveFunction(left_, p), r = rightEos_.waveFunction(right_, p);
        return RiemannEquationOfState::WaveFunction{l.value + r.value + dv, l.derivative + r.derivative};
    };
    const double cL = leftEos_.soundSpeed(left_.density, left_.pressure);
    const double cR = rightEos_.soundSpeed(right_.density, right_.pressure);
    const double scale = std::max(left_.density * cL * cL, right_.density * cR * cR);

    double lo = std::max(leftEos_.pressureFloor(), rightEos_.pressureFloor());
    const double fLo = f(lo).value;
    if (!(fLo < 0.0)) {
        std::ostringstream s;
        s.precision(10);
        s << "RiemannSolver: the data generate vacuum: the rarefactions reach the pressure floor " << lo
          << " before the velocities meet (f(P_floor) = " << fLo << " >= 0; left " << leftEos_.describe()
          << " rho = " << left_.density << " v = " << left_.velocity << " P = " << left_.pressure
          << ", right " << rightEos_.describe() << " rho = " << right_.density << " v = " << right_.velocity
          << " P = " << right_.pressure << ")";
        throw Error(s.str());
    }
    // Upper end of the bracket: grow until f > 0 (f increases without bound through the shocks).
    double hi = std::max({left_.pressure, right_.pressure, lo + scale});
    for (int n = 0; f(hi).value <= 0.0; ++n) {
        if (n > 200) throw Error("RiemannSolver: could not bracket the star pressure");
        hi = lo + 2.0 * (hi - lo);
    }
    // Start from the mean pressure, a fair guess for weak and moderate waves (Toro 4.47).
    double p = std::clamp(0.5 * (left_.pressure + right_.pressure), lo, hi);
    if (p <= lo) p = 0.5 * (lo + hi);
    for (iterations_ = 1; iterations_ <= 500; ++iterations_) {
        const auto [value, derivative] = f(p);
        if (value == 0.0) {
            pStar_ = p;
            return;
        }
        (value < 0.0 ? lo : hi) = p;
        double next = p - value / derivative;
        // Newton may overshoot in the strongly curved rarefaction branch; bisect then.
        if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
        const double change = std::abs(next - p);
        p = next;
        if (change <= 1e-12 * (std::abs(p) + scale) || hi - lo <= 1e-15 * (std::abs(p) + scale)) {
            pStar_ = p;
            return;
        }
    }
    throw Error("RiemannSolver: the star-pressure iteration did not converge in 500 steps");
}

FlowState RiemannSolver::leftState() const {
    return {left_.density, left_.velocity, left_.pressure,
            leftEos_.internalEnergy(left_.density, left_.pressure)};
}

FlowState RiemannSolver::rightState() const {
    return {right_.density, right_.velocity, right_.pressure,
            rightEos_.internalEnergy(right_.density, right_.pressure)};
}

FlowState RiemannSolver::starLeft() const {
    return {rhoStarL_, vStar_, pStar_, leftEos_.internalEnergy(rhoStarL_, pStar_)};
}

FlowState RiemannSolver::starRight() const {
    return {rhoStarR_, vStar_, pStar_, rightEos_.internalEnergy(rhoStarR_, pStar_)};
}

FlowState RiemannSolver::sample(double xi) const {
    return sampleSide(xi, isLeftMaterial(xi) ? -1 : +1);
}

// side = -1: left of the contact, +1: right. Multiplying by side turns "beyond the wave, away from
// the contact" into s*(xi - speed) > 0 for both sides.
FlowState RiemannSolver::sampleSide(double xi, int side) const {
    const Wave& wave = side < 0 ? leftWave_ : rightWave_;
    const FlowState outer = side < 0 ? leftState() : rightState();
    const FlowState star = side < 0 ? starLeft() : starRight();
    if (wave.kind == WaveKind::shock) return side * (xi - wave.headSpeed) > 0.0 ? outer : star;
    if (side * (xi - wave.headSpeed) >= 0.0) return outer;
    if (side * (xi - wave.tailSpeed) <= 0.0) return star;
    return side < 0 ? leftEos_.fan(left_, xi, -1) : rightEos_.fan(right_, xi, +1);
}

}  // namespace mfdyn
