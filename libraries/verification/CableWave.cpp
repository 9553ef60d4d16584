// Cable (Lee, Gil, Greto, Karim & Bonet 2016, section 8.1, Figs 3-4; doc/methods/tl-jst-sph.md 8.1): the
// wave equation u_tt = c^2 u_XX on 0 <= X <= L, c = sqrt(E/rho0) (nu = 0), with u(0, t) = 0
// (fixed), u_X(L, t) = 0 (free), u(X, 0) = 0 and u_t(X, 0) = v0 for X <= a, 0 beyond.
// d'Alembert with the initial velocity w extended oddly about X = 0 (u = 0 there) and evenly
// about X = L (zero strain there), which makes it periodic with period 4L:
//
//     v(X, t) = 1/2 [w(X - ct) + w(X + ct)],
//     u(X, t) = int_0^t v dt = 1/(2c) [G(X + ct) - G(X - ct)],     G(s) = int_0^s w,
//     du/dX   = 1/(2c) [w(X + ct) - w(X - ct)],   axial stress E du/dX.
//
// w is odd and 4L-periodic, so its mean is zero and G is even and 4L-periodic:
//     G(s) = v0 min(s, a)          on [0, L],
//     G(s) = 2 G(L) - G(2L - s)    on [L, 2L]   (w(s) = w(2L - s) there).
// At the tip v(L, t) = w(L - ct): +v0 for ct in (L - a, L), -v0 for ct in (L, L + a), ...; the tip
// displacement is a triangle peaking at v0 a/c at ct = L (2.5 mm at 2 ms for L = 10 m, c = 5000
// m/s, v0 = 5 m/s, a = 2.5 m) and -v0 a/c at ct = 3L. The bulk stress behind the fronts is
// rho0 c v0/2. Exact for linear elasticity; the discontinuous fronts are where particle methods
// over- and undershoot.
#include "verification/CableWave.hpp"

#include "core/Error.hpp"

#include <algorithm>
#include <cmath>

namespace mfdyn {

CableWave::CableWave(double length, double waveSpeed, double velocity, double loadedLength)
    : L_(length), c_(waveSpeed), v0_(velocity), a_(loadedLength) {
    if (!(L_ > 0) || !(c_ > 0) || !(a_ >= 0 && a_ <= L_) || !std::isfinite(v0_))
        throw Error(
            "cable wave: expected length > 0, wave speed > 0, 0 <= loaded length <= length and a finite "
            "velocity");
}

double CableWave::fold(double s, double& sign) const {
    const double period = 4 * L_;
    s = std::fmod(s, period);
    if (s < -2 * L_) s += period;
    if (s >= 2 * L_) s -= period;  // now in [-2L, 2L)
    sign = 1;
    if (s < 0) s = -s, sign = -1;
    return s;
}

double CableWave::extendedVelocity(double s) const {
    double sign;
    s = fold(s, sign);
    if (s > L_) s = 2 * L_ - s;
    // 0 at the nodes of the odd extension (X = 0, 2L), so that the fixed end has v = 0 at t = 0 too.
    return s > 0 && s <= a_ ? sign * v0_ : 0.0;
}

double CableWave::extendedIntegral(double s) const {
    double sign;
    s = fold(s, sign);  // G is even: the sign does not matter
    auto G = [&](double r) { return v0_ * std::min(r, a_); };
    return s <= L_ ? G(s) : 2 * G(L_) - G(2 * L_ - s);
}

double CableWave::velocity(double X, double t) const {
    return 0.5 * (extendedVelocity(X - c_ * t) + extendedVelocity(X + c_ * t));
}

double CableWave::displacement(double X, double t) const {
    return (extendedIntegral(X + c_ * t) - extendedIntegral(X - c_ * t)) / (2 * c_);
}

double CableWave::strain(double X, double t) const {
    return (extendedVelocity(X + c_ * t) - extendedVelocity(X - c_ * t)) / (2 * c_);
}

}  // namespace mfdyn
