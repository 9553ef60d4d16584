#pragma once
// The hot-loop form of a kernel: a small value type that a solver copies into its particle loop.
//
// Why a table and not a virtual call or a visitor: a virtual call per pair blocks inlining and
// vectorisation in the loops that dominate an SPH step, and a compile-time visitor over the known
// kernels would shut out kernels loaded from user libraries. Every kernel is therefore tabulated
// once per dimension as a piecewise cubic Hermite interpolant of its unit-support shape w(u),
// u = r/H on [0, 1] (Kernel.hpp), and the evaluator below reads it: one multiply to find the cell,
// four coefficients, a Horner step, a mask for compact support. No branch depends on the kernel
// type, and the code is identical for built-in and user kernels.
//
// Accuracy: the table has Kernel::tableCells cells; the spline knots (u = 1/2, 1/3, 2/3) fall on
// cell boundaries, so the cubic pieces of M4 are reproduced exactly and the other kernels carry an
// interpolation error of order (1/cells)^4 max|w''''| / 384 in W and one order less in dW/dr
// (tests/unit/kernels checks W to 1e-10 W(0) and dW/dr, dW/dh to 1e-8 of their maxima for every
// registered kernel). Cost: about 10 ns per W + dW/dr pair at random r (Wendland C2, 3D, -O3),
// against 75 ns through the exact virtual members.
//
// The evaluator points into tables owned by its Kernel: keep the Kernel alive while it is used.
#include "core/Tensor.hpp"

#include <algorithm>

namespace mfdyn {

template <int Dim>
struct KernelEvaluator {
    static_assert(Dim >= 1 && Dim <= 3, "kernels are normalised in 1, 2 and 3 dimensions");

    const double* coefficients = nullptr;  // 4 per cell: w on the cell as a cubic in its local coordinate
    int cells = 0;
    double invKappa = 1.0;  // h / H
    double norm = 0.0;      // c_d, so that W = c_d H^-d w(r/H)

    struct Value {
        double W;
        double dWdr;
    };

    double W(double r, double h) const {
        const double invH = invKappa / h;
        double w, dw;
        shape(r * invH, w, dw);
        return norm * power(invH) * w;
    }

    double dWdr(double r, double h) const {
        const double invH = invKappa / h;
        double w, dw;
        shape(r * invH, w, dw);
        return norm * power(invH) * invH * dw;
    }

    // W and dW/dr together: the usual need of a pair interaction.
    Value evaluate(double r, double h) const {
        const double invH = invKappa / h;
        double w, dw;
        shape(r * invH, w, dw);
        const double c = norm * power(invH);
        return {c * w, c * invH * dw};
    }

    // dW/dh = -(1/h) c_d H^-d [d w(u) + u w'(u)], needed for the grad-h (omega) terms.
    double dWdh(double r, double h) const {
        const double invH = invKappa / h;
        const double u = r * invH;
        double w, dw;
        shape(u, w, dw);
        return -norm * power(invH) / h * (Dim * w + u * dw);
    }

    // grad_i W(x_i - x_j, h) = dW/dr * rij/|rij|, with |rij| given because the caller has it.
    Vector<Dim> gradW(const Vector<Dim>& rij, double r, double h) const {
        const double f = r > 0.0 ? dWdr(r, h) / r : 0.0;
        return f * rij;
    }

    // w(u) and dw/du from the table; zero for u >= 1.
    void shape(double u, double& w, double& dw) const {
        const double inside = u < 1.0 ? 1.0 : 0.0;
        const double t = std::min(u, 1.0) * cells;
        const int i = std::min(int(t), cells - 1);
        const double s = t - i;
        const double* a = coefficients + 4 * i;
        w = inside * (a[0] + s * (a[1] + s * (a[2] + s * a[3])));
        dw = inside * cells * (a[1] + s * (2.0 * a[2] + 3.0 * s * a[3]));
    }

private:
    static double power(double x) {
        if constexpr (Dim == 1) return x;
        if constexpr (Dim == 2) return x * x;
        return x * x * x;
    }
};

}  // namespace mfdyn
