// Elliptical drop (Monaghan 1994, J. Comput. Phys. 110:399, Sec. 6; Monaghan & Rafiee 2013;
// Zisis 2017 4.5.1, Fig. 4.2; doc/methods/sph-impact.md 8.1). An incompressible, inviscid drop with the
// linear velocity field v = (a'/a x, b'/b y) keeps an elliptical boundary x^2/a^2 + y^2/b^2 = 1;
// incompressibility gives a'/a + b'/b = 0, i.e. ab = 1 (area conserved), and the free surface
// (P = 0) fixes the strain rate A = -a'/a = b'/b through
//
//     A' = A^2 (a^2 - b^2)/(a^2 + b^2),   a' = -A a,   b' = A b,   A(0) = A0, a(0) = b(0) = 1.
//
// The system is integrated by classical RK4 with fixed equal steps (Hairer, Norsett & Wanner 1993,
// II.1); ab = 1 is an invariant of the ODE (d(ab)/dt = -Aab + Aab = 0) that RK4 keeps to its
// truncation error, which tests use as a check. Reference [C]: b(0.0076) = 1.9445 (A = 70.31),
// b(0.01) = 2.2755 for A0 = 100.
#include "verification/EllipticalDrop.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "core/Error.hpp"
#include "core/KeywordSchema.hpp"  // formatKeywordNumber: 1e-320 shows as 9.99989e-321, not 0.000000

namespace mfdyn {

EllipticalDrop::EllipticalDrop(double A0, double stepsPerUnit) : A0_(A0), stepsPerUnit_(stepsPerUnit) {
    if (!std::isfinite(A0)) throw Error("EllipticalDrop: A0 must be finite");
    if (!(stepsPerUnit >= 10.0)) throw Error("EllipticalDrop: stepsPerUnit must be >= 10");
}

EllipticalDrop::State EllipticalDrop::state(double t) const {
    if (!(t >= 0.0)) throw Error("EllipticalDrop: time must be >= 0, found " + formatKeywordNumber(t));
    // y = (a, b, A).
    auto rate = [](const State& y) {
        const double a2 = y.a * y.a, b2 = y.b * y.b;
        return State{-y.A * y.a, y.A * y.b, y.A * y.A * (a2 - b2) / (a2 + b2)};
    };
    auto axpy = [](const State& y, double h, const State& k) {
        return State{y.a + h * k.a, y.b + h * k.b, y.A + h * k.A};
    };
    const long steps = std::max(1L, long(std::ceil(std::abs(A0_) * t * stepsPerUnit_)));
    const double h = t / double(steps);
    State y{1.0, 1.0, A0_};
    for (long n = 0; n < steps; ++n) {
        const State k1 = rate(y);
        const State k2 = rate(axpy(y, 0.5 * h, k1));
        const State k3 = rate(axpy(y, 0.5 * h, k2));
        const State k4 = rate(axpy(y, h, k3));
        y.a += h / 6.0 * (k1.a + 2.0 * k2.a + 2.0 * k3.a + k4.a);
        y.b += h / 6.0 * (k1.b + 2.0 * k2.b + 2.0 * k3.b + k4.b);
        y.A += h / 6.0 * (k1.A + 2.0 * k2.A + 2.0 * k3.A + k4.A);
    }
    return y;
}

std::array<double, 2> EllipticalDrop::velocity(double x, double y, double t) const {
    const double A = state(t).A;
    return {-A * x, A * y};
}

bool EllipticalDrop::inside(double x, double y, double t) const {
    const State s = state(t);
    return (x / s.a) * (x / s.a) + (y / s.b) * (y / s.b) <= 1.0;
}

}  // namespace mfdyn
