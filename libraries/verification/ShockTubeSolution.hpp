#pragma once
// Exact profile of a classical Riemann problem on the line: two uniform states meeting at x0 at
// t = 0, each with its own closure. Used by error function objects as the reference field, and to
// integrate the conserved quantities of the exact solution (a check of the solver and of the
// boundary fluxes a finite domain sees).
#include <span>
#include <vector>

#include "verification/RiemannSolver.hpp"

namespace mfdyn {

// Integrals over an interval of rho, rho v and rho (e + v^2/2). energy is NaN when a barotropic
// material lies in the interval (no energy equation).
struct ConservedTotals {
    double mass = 0.0;
    double momentum = 0.0;
    double energy = 0.0;
};

class ShockTubeSolution {
public:
    // Positions at time t of the wave edges, left to right. For a shock head == tail.
    struct WavePositions {
        double leftHead, leftTail, contact, rightTail, rightHead;
    };

    ShockTubeSolution(double x0, const PrimitiveState& left, const RiemannEquationOfState& leftEos,
                      const PrimitiveState& right, const RiemannEquationOfState& rightEos);

    const RiemannSolver& solver() const { return solver_; }
    double interface() const { return x0_; }

    // Exact state at (x, t); t = 0 gives the initial data (left state at x == x0). Throws for t < 0.
    FlowState state(double x, double t) const;
    std::vector<FlowState> profile(std::span<const double> x, double t) const;
    WavePositions wavePositions(double t) const;

    // Integrals of rho, rho v, rho E over [a, b] at time t: exact on the uniform pieces, composite
    // 5-point Gauss-Legendre in the fans (exact for the polynomial gas fans with gamma = 1.4, 5/3;
    // ~1e-14 relative for the exponential barotropic fan).
    ConservedTotals integrate(double a, double b, double t) const;
    // Fluxes (rho v, rho v^2 + P, v (rho E + P)) of a state, for balances with integrate().
    ConservedTotals flux(const FlowState& s) const;

private:
    double x0_;
    RiemannSolver solver_;
};

}  // namespace mfdyn
