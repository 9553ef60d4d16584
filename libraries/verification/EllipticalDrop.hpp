#pragma once
// Reference solution of the elliptical drop (Monaghan 1994; Zisis 2017 4.5.1; doc/methods/sph-impact.md 8.1):
// a unit disk of incompressible fluid with the initial velocity (-A0 x, A0 y) stretches into an
// ellipse of semi-axes a(t) (along x) and b(t) (along y), ab = 1. Equations: EllipticalDrop.cpp.
#include <array>

namespace mfdyn {

class EllipticalDrop {
public:
    struct State {
        double a;  // semi-axis along x
        double b;  // semi-axis along y
        double A;  // strain rate: v = (-A x, A y)
    };

    // stepsPerUnit: RK4 steps per unit of A0 t (default 1e4, so |A dt| <= 1e-4: the local error
    // (A dt)^5 ~ 1e-20 keeps b to ~1e-14 over the test's range).
    explicit EllipticalDrop(double A0 = 100.0, double stepsPerUnit = 1e4);

    double initialStrainRate() const { return A0_; }
    // The state at t >= 0 (RK4 from 0 with equal steps no larger than 1/(A0 stepsPerUnit)).
    State state(double t) const;
    // Exact velocity at (x, y) and time t: v_x = (a'/a) x = -A x, v_y = (b'/b) y = A y.
    std::array<double, 2> velocity(double x, double y, double t) const;
    // Whether (x, y) lies inside the drop at time t: (x/a)^2 + (y/b)^2 <= 1.
    bool inside(double x, double y, double t) const;

private:
    double A0_;
    double stepsPerUnit_;
};

}  // namespace mfdyn
