// harmonicTrap: a = -ω² (x - c), an isotropic harmonic trap centred at c.
//
//   phi(x) = ½ ω² |x - c|²
//   x(t) = c + (x0 - c) cos ωt + (v0/ω) sin ωt,   v(t) = -ω (x0 - c) sin ωt + v0 cos ωt
//
// Velocity Verlet shifts the phase by ω³ dt² t / 24 per unit amplitude (second order), so the
// position error after time t is about A ω³ dt² t / 24: the case checks it against that bound.
#include "HarmonicTrap.hpp"

#include <cmath>

namespace myModels {

HarmonicTrap::HarmonicTrap(const mfdyn::Dictionary& dict, int dimension)
    : mfdyn::BodyForce(dict, dimension), omega_(dict.get<double>("omega")) {
    if (!(omega_ > 0)) throw dict.error("omega", "omega must be positive (rad/s)");
    const auto c = dict.getOrDefault<std::vector<double>>("centre", {0, 0, 0});
    for (int d = 0; d < dimension && d < int(c.size()); ++d) centre_[d] = c[d];
}

void HarmonicTrap::acceleration(const double* x, double, double* a) const {
    for (int d = 0; d < dimension(); ++d) a[d] = -omega_ * omega_ * (x[d] - centre_[d]);
}

double HarmonicTrap::potential(const double* x) const {
    double r2 = 0;
    for (int d = 0; d < dimension(); ++d) r2 += (x[d] - centre_[d]) * (x[d] - centre_[d]);
    return 0.5 * omega_ * omega_ * r2;
}

bool HarmonicTrap::exactTrajectory(const double* x0, const double* v0, double tau, double* x,
                                   double* v) const {
    const double c = std::cos(omega_ * tau), s = std::sin(omega_ * tau);
    for (int d = 0; d < dimension(); ++d) {
        x[d] = centre_[d] + (x0[d] - centre_[d]) * c + v0[d] / omega_ * s;
        v[d] = -omega_ * (x0[d] - centre_[d]) * s + v0[d] * c;
    }
    return true;
}

// Verlet is stable for ω dt < 2; a twentieth of a period keeps the phase error small.
mfdyn::TimeStepVote HarmonicTrap::stableTimeStep() const {
    return {0.05 * 2 * M_PI / omega_, "harmonicTrap period/20"};
}

MFDYN_REGISTER(mfdyn::BodyForce, HarmonicTrap, "harmonicTrap",
               "isotropic harmonic trap a = -omega^2 (x - centre) [user library]");

}  // namespace myModels
