// The cubic B-spline centred on the nodes (Steffen, Kirby & Berzins 2008, Int. J. Numer. Meth.
// Eng. 76:922; de Vaucorbeil et al. 2020, "Material point method after 25 years"),
// knots at the nodes, in cell units r = (x - x_I)/h:
//
//     |r| < 1:       N = |r|^3/2 - r^2 + 2/3        dN/dr = (3/2 |r| - 2) r
//     1 <= |r| < 2:  N = (2 - |r|)^3 / 6            dN/dr = -sign(r) (2 - |r|)^2 / 2
//     beyond:        N = 0
//
// In cell i (t = xi - i in [0, 1], u = 1 - t) the window i - 1 .. i + 2 has
//     N     = (u^3/6, (3t^3 - 6t^2 + 4)/6, (-3t^3 + 3t^2 + 3t + 1)/6, t^3/6)
//     dN/dt = (-u^2/2, (3t^2 - 4t)/2, (-3t^2 + 2t + 1)/2, t^2/2)
// C2, 4 nodes per axis, support half-width 2 cells.
//
// At the grid's edges, the boundary modification: the outside node's function is folded onto the
// edge nodes (TensorProductShapeFunction.hpp), giving the natural cubic spline (N'' = 0 at the
// edge): in the edge cell (t = xi),
//     node 0: (3t^3 - 6t^2 + 4)/6 + 2 (1 - t)^3/6      = 1 - t + t^3/6
//     node 1: (-3t^3 + 3t^2 + 3t + 1)/6 - (1 - t)^3/6 = t - t^3/3
//     node 2: t^3/6
// all non-negative on [0, 1], N_0(0) = 1; the same functions as Karamelo's boundary node types
// (de Vaucorbeil et al.'s code).
#include "grid/shapeFunctions/CubicBSplineShapeFunction.hpp"

namespace mfdyn {

template <class T>
std::int64_t CubicBSplineBasis::weights(T xi, double, std::int64_t n, T* w, T* dw) {
    const std::int64_t i = std::clamp<std::int64_t>(shapeFunctionDetail::floorIndex(xi), 0, n - 1);
    const T t = xi - double(i);
    const T u = 1.0 - t;
    const T t2 = t * t, t3 = t2 * t;
    constexpr double sixth = 1.0 / 6.0;
    w[0] = sixth * u * u * u;
    w[1] = sixth * (3.0 * t3 - 6.0 * t2 + 4.0);
    w[2] = sixth * (-3.0 * t3 + 3.0 * t2 + 3.0 * t + 1.0);
    w[3] = sixth * t3;
    dw[0] = -0.5 * u * u;
    dw[1] = 0.5 * (3.0 * t2 - 4.0 * t);
    dw[2] = 0.5 * (-3.0 * t2 + 2.0 * t + 1.0);
    dw[3] = 0.5 * t2;
    return i - 1;
}

template <int Dim>
KeywordSchema CubicBSplineShapeFunction<Dim>::keywords() {
    return KeywordSchema(ShapeFunction<Dim>::familyName, "cubicBSpline");
}

template class CubicBSplineShapeFunction<1>;
template class CubicBSplineShapeFunction<2>;
template class CubicBSplineShapeFunction<3>;

MFDYN_REGISTER_DIM(ShapeFunction, CubicBSplineShapeFunction, "cubicBSpline",
                   "cubic B-spline on the nodes (C2, 4 nodes per axis), natural at the grid's edges "
                   "(Steffen, Kirby & Berzins 2008)");

}  // namespace mfdyn
