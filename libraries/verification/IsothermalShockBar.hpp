#pragma once
// Exact solution of the isothermal shock-bar (Zisis 2017 5.1, Fig. 5.1; doc/methods/sph-impact.md 8.2): four
// uniform bars on the line, the first striking the second at t = 0. Built from two successive
// Riemann problems; valid until the next wave interaction, which it reports. See the .cpp.
#include <limits>
#include <span>
#include <vector>

#include "verification/RiemannSolver.hpp"

namespace mfdyn {

class IsothermalShockBar {
public:
    struct Bar {
        PrimitiveState state;
        RiemannEquationOfState eos;
    };

    // Bars occupy (-inf, a), [a, b), [b, c), [c, inf). Requirements (else Error): bars 2|3 and 3|4
    // are at rest relative to each other with equal pressures (no wave at b or c at t = 0); the
    // impact at a sends a shock to the right; bars 1 and 2 share their material and the contact
    // between them is trivial (equal star densities), so the reflected wave passes it unchanged.
    IsothermalShockBar(double a, double b, double c, const Bar& bar1, const Bar& bar2, const Bar& bar3,
                       const Bar& bar4);
    // The set-up of doc/methods/sph-impact.md 8.2: {rho, v, rho0, c0} = {1,1,1,1} on [0, 0.6), {1,0,1,1} on
    // [0.6, 0.8), {0.25,0,0.25,0.5} on [0.8, 1.2), {1,0,1,1} on [1.2, 1.4] (the domain ends are
    // not modelled: no wave reaches them before validUntil()).
    static IsothermalShockBar zisis2017();

    // The impact at x = a, t = 0.
    const RiemannSolver& impact() const { return impact_; }
    // The Riemann problem at x = b, t = transmissionTime(), when the impact's right shock arrives.
    const RiemannSolver& transmission() const { return transmission_; }
    double transmissionTime() const { return t1_; }
    // The first later interaction: the transmitted wave reaching c, or the reflected wave meeting
    // the impact's left wave. state() throws beyond it.
    double validUntil() const { return tEnd_; }

    FlowState state(double x, double t) const;
    std::vector<FlowState> profile(std::span<const double> x, double t) const;

private:
    double a_, b_, c_;
    Bar bar3_, bar4_;
    RiemannSolver impact_;
    double t1_ = 0.0;
    RiemannSolver transmission_;
    double tEnd_ = std::numeric_limits<double>::infinity();
};

}  // namespace mfdyn
