// The quadratic B-spline centred on the nodes (Steffen, Kirby & Berzins 2008, "Analysis and
// reduction of quadrature errors in the material point method", Int. J. Numer. Meth. Eng.
// 76:922; de Vaucorbeil et al. 2020, "Material point method after 25 years", Adv. Appl. Mech.
// 53:185), knots at the half-integers, in cell units r = (x - x_I)/h:
//
//     |r| < 1/2:          N = 3/4 - r^2              dN/dr = -2 r
//     1/2 <= |r| < 3/2:   N = (3/2 - |r|)^2 / 2      dN/dr = -sign(r) (3/2 - |r|)
//     beyond:             N = 0
//
// With the nearest node c = floor(xi + 1/2) and t = xi - c in [-1/2, 1/2], the window c - 1, c,
// c + 1 has N = ((1/2 - t)^2/2, 3/4 - t^2, (1/2 + t)^2/2), dN/dxi = (t - 1/2, -2t, t + 1/2).
// C1, 3 nodes per axis, support half-width 1.5 cells.
//
// At the grid's edges, the boundary modification: the outside node's function is folded onto the
// edge nodes (TensorProductShapeFunction.hpp), giving the natural quadratic spline: for
// xi < 1/2, N_-1 = (1/2 - xi)^2/2 and
//     node 0: 3/4 - xi^2 + (1/2 - xi)^2   = 1 - xi
//     node 1: (1/2 + xi)^2/2 - (1/2 - xi)^2/2 = xi
// (linear in the half cell at the edge, C1 at xi = 1/2, non-negative, N_0(0) = 1: the edge node
// carries the wall's value), as in Karamelo's boundary node types.
#include "grid/shapeFunctions/QuadraticBSplineShapeFunction.hpp"

namespace mfdyn {

template <class T>
std::int64_t QuadraticBSplineBasis::weights(T xi, double, std::int64_t, T* w, T* dw) {
    const std::int64_t centre = shapeFunctionDetail::floorIndex(xi + 0.5);
    const T t = xi - double(centre);
    const T left = 0.5 - t, right = 0.5 + t;
    w[0] = 0.5 * left * left;
    w[1] = 0.75 - t * t;
    w[2] = 0.5 * right * right;
    dw[0] = -left;
    dw[1] = -2.0 * t;
    dw[2] = right;
    return centre - 1;
}

template <int Dim>
KeywordSchema QuadraticBSplineShapeFunction<Dim>::keywords() {
    return KeywordSchema(ShapeFunction<Dim>::familyName, "quadraticBSpline");
}

template class QuadraticBSplineShapeFunction<1>;
template class QuadraticBSplineShapeFunction<2>;
template class QuadraticBSplineShapeFunction<3>;

MFDYN_REGISTER_DIM(ShapeFunction, QuadraticBSplineShapeFunction, "quadraticBSpline",
                   "quadratic B-spline on the nodes (C1, 3 nodes per axis), natural at the grid's edges "
                   "(Steffen, Kirby & Berzins 2008)");

}  // namespace mfdyn
