#pragma once
// Shared by the kernel tests: building a kernel as a user does, and a quadrature written apart from
// the library's Gauss-Legendre so that normalisation is checked by independent code.
#include "core/Dictionary.hpp"
#include "kernels/Kernel.hpp"

#include <cmath>
#include <functional>
#include <memory>
#include <numbers>
#include <string>

namespace mfdyn::test {

inline std::unique_ptr<Kernel> makeKernel(const std::string& text) {
    return Kernel::New(Dictionary::parse(text, "test"));
}

// Composite Simpson on [a, b] with n panels (n a multiple of 6 keeps spline knots at 1/2, 1/3, 2/3 of
// the support on panel edges), refined once by Richardson (Boole): error O(n^-6) on smooth pieces.
inline double simpson(const std::function<double(double)>& f, double a, double b, int n) {
    auto rule = [&](int panels) {
        const double dx = (b - a) / panels;
        double sum = f(a) + f(b);
        for (int i = 1; i < panels; ++i) sum += (i % 2 ? 4.0 : 2.0) * f(a + i * dx);
        return sum * dx / 3.0;
    };
    const double coarse = rule(n), fine = rule(2 * n);
    return fine + (fine - coarse) / 15.0;
}

inline double sphereSurface(int dim) {
    return dim == 1 ? 2.0 : dim == 2 ? 2.0 * std::numbers::pi : 4.0 * std::numbers::pi;
}

}  // namespace mfdyn::test
