#pragma once
// The cable of Lee et al. 2016 section 8.1 (doc/methods/tl-jst-sph.md 8.1): a 1D elastic bar 0 <= X <= L,
// fixed at X = 0, free at X = L, at rest and unstrained at t = 0 except for an axial velocity v0
// on X <= a. The d'Alembert solution; equations in CableWave.cpp.
namespace mfdyn {

class CableWave {
public:
    // Length L [m], wave speed c [m/s], initial velocity v0 [m/s] on 0 <= X <= a [m]. Throws Error
    // unless L > 0, c > 0, 0 <= a <= L.
    CableWave(double length, double waveSpeed, double velocity, double loadedLength);

    double length() const { return L_; }
    double waveSpeed() const { return c_; }
    // The time the wave takes to go and come back, 4L/c, after which the motion repeats.
    double period() const { return 4 * L_ / c_; }

    // Axial velocity, displacement u = x - X and strain du/dX at (X, t).
    double velocity(double X, double t) const;
    double displacement(double X, double t) const;
    double strain(double X, double t) const;

    // The initial velocity extended oddly about 0 and evenly about L (period 4L), and its
    // integral from 0 (even, of period 4L: the extension has zero mean).
    double extendedVelocity(double s) const;
    double extendedIntegral(double s) const;

private:
    // s folded into [0, 2L] and the sign of the odd extension there.
    double fold(double s, double& sign) const;

    double L_, c_, v0_, a_;
};

}  // namespace mfdyn
