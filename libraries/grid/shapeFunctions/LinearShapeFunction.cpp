// The linear hat of the MPM thesis (its section 7.3, Eqs. 63-67, as in doc/methods/mpm.md §2.2),
// per axis in cell units r = (x - x_I)/h:
//
//     N(r) = 1 - |r|  for |r| < 1,  0 beyond;     dN/dr = -sign(r)
//
// and its tensor product: in 2D the thesis's N0 = a0 b0, N1 = a1 b0, N2 = a1 b1, N3 = a0 b1 with
// a0 = (x2 - x)/dx, a1 = (x - x0)/dx. A particle in cell i (t = xi - i in [0, 1]) touches nodes i
// and i + 1 with N = (1 - t, t), dN/dxi = (-1, 1). C0: the gradient jumps when a particle crosses
// a cell face (the thesis's cell-crossing noise). On a node or face the cell to the right (above)
// is taken, so the gradient is the right derivative (at the grid's upper face, the left one).
// Never leaves the grid: no fold is needed. 2 nodes per axis, support half-width 1 cell.
#include "grid/shapeFunctions/LinearShapeFunction.hpp"

namespace mfdyn {

template <class T>
std::int64_t LinearBasis::weights(T xi, double, std::int64_t n, T* w, T* dw) {
    const std::int64_t i = std::clamp<std::int64_t>(shapeFunctionDetail::floorIndex(xi), 0, n - 1);
    const T t = xi - double(i);
    w[0] = 1.0 - t;
    w[1] = t;
    dw[0] = -1.0;
    dw[1] = 1.0;
    return i;
}

template <int Dim>
KeywordSchema LinearShapeFunction<Dim>::keywords() {
    return KeywordSchema(ShapeFunction<Dim>::familyName, "linear");
}

template class LinearShapeFunction<1>;
template class LinearShapeFunction<2>;
template class LinearShapeFunction<3>;

MFDYN_REGISTER_DIM(
    ShapeFunction, LinearShapeFunction, "linear",
    "linear hat of the MPM thesis (C0, 2 nodes per axis): N = 1 - |r| per axis, tensor product");

}  // namespace mfdyn
