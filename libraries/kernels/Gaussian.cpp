// Truncated Gaussian (Gingold & Monaghan 1977, MNRAS 181:375; Monaghan 1992, Annu. Rev. Astron.
// Astrophys. 30:543; Zisis 2017 Eq. 2.6 and section 6.1, doc/methods/sph-impact.md 1.1 and 1.3):
//
//     W(r, h) proportional to exp(-(r/h)^2) for r < a h, zero beyond; a = `cutoff` (default 3).
//
// In the unit-support form of Kernel.hpp, H = a h and w(u) = exp(-(a u)^2), w'(u) = -2 a^2 u w(u).
// c_d is computed by quadrature over the truncated support, so the truncated kernel integrates to
// one exactly (the note's 3^d/pi^(d/2) ignores truncation). Closed forms of the kept mass, for
// reference: sqrt(pi) erf(a), pi (1 - e^-a^2), pi^(3/2) erf(a) - 2 pi a e^-a^2 (d = 1, 2, 3).
//
// Limits: W jumps by c_d H^-d e^(-a^2) at the cutoff (1.2e-4 of W(0) for a = 3), so the force is
// not continuous there; the truncated transform may dip below zero by at most the removed mass
// fraction m/(1 - m) (truncatedMass), although the untruncated Gaussian's transform is positive.
#include "kernels/Gaussian.hpp"

#include <cmath>
#include <numbers>

namespace mfdyn {

KeywordSchema Gaussian::keywords() {
    return commonKeywords("gaussian")
        .scalar("cutoff", "-", "support radius in units of h: exp(-(r/h)^2) cut at r = cutoff h")
        .greaterThan(0)
        .orDefault(3.0);
}

Gaussian::Gaussian(const Dictionary& dict) : Gaussian(dict, keywords().read(dict)) {}

Gaussian::Gaussian(const Dictionary& dict, const KeywordValues& values)
    : Kernel(dict, values, values.scalar("cutoff")), cutoff_(values.scalar("cutoff")) {
    initialise();
}

double Gaussian::shape(double u, int) const {
    const double x = cutoff_ * u;
    return std::exp(-x * x);
}

double Gaussian::shapeDerivative(double u, int) const {
    const double x = cutoff_ * u;
    return -2.0 * cutoff_ * x * std::exp(-x * x);
}

double Gaussian::truncatedMass(int dim) const {
    const double a = cutoff_, e = std::exp(-a * a);
    if (dim == 1) return std::erfc(a);
    if (dim == 2) return e;
    return std::erfc(a) + 2.0 * a * e / std::sqrt(std::numbers::pi);
}

MFDYN_REGISTER(Kernel, Gaussian, "gaussian",
               "Gaussian exp(-(r/h)^2) truncated at cutoff*h (default 3) and renormalised");

}  // namespace mfdyn
