#pragma once
// Discrete error norms of a 1D particle field against an exact profile, weighted by particle
// volumes (or any non-negative quadrature weights), over a window [x0, x1].
#include <cstddef>
#include <functional>
#include <span>

namespace mfdyn {

class ErrorNorms {
public:
    // Weighted means over the particles i with x0 <= x_i <= x1, e_i = f_i - exact(x_i):
    //     l1   = sum w_i |e_i| / sum w_i
    //     l2   = sqrt(sum w_i e_i^2 / sum w_i)
    //     linf = max |e_i|                         (unweighted)
    // With w_i = particle volumes these are the mean absolute and RMS errors over the window
    // (the L1 and L2 norms of the error divided by the window's length in 1D).
    double l1 = 0.0;
    double l2 = 0.0;
    double linf = 0.0;
    double totalWeight = 0.0;  // sum w_i over the window
    std::size_t count = 0;     // particles in the window

    // Throws Error when the spans differ in length, a weight is negative or not finite, the window
    // is empty of particles or carries no weight, or a value or the exact profile is not finite.
    static ErrorNorms compute(std::span<const double> x, std::span<const double> values,
                              std::span<const double> weights, const std::function<double(double)>& exact,
                              double x0, double x1);
};

}  // namespace mfdyn
