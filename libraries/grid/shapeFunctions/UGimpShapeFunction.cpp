// Uniform GIMP (Bardenhagen & Kober 2004, "The generalized interpolation material point method",
// Comput. Model. Eng. Sci. 5:477, with the box characteristic function; the closed form as in
// Wallstedt & Guilkey 2008, J. Comput. Phys. 227:9628): the linear hat averaged over the
// particle's box of half-width l_p per axis, S_I = (1/2l_p) int_{x-l_p}^{x+l_p} N_I. In cell units
// (r = (x - x_I)/h, lp = l_p/h <= 1/2):
//
//     |r| < lp:              S = 1 - (r^2 + lp^2) / (2 lp)      dS/dr = -r / lp
//     lp <= |r| <= 1 - lp:   S = 1 - |r|                       dS/dr = -sign(r)
//     1 - lp < |r| < 1 + lp: S = (1 + lp - |r|)^2 / (4 lp)     dS/dr = -sign(r) (1 + lp - |r|) / (2 lp)
//     beyond:                S = 0
//
// C1 (the gradient is continuous across cell faces: no cell-crossing noise while the particle
// boxes tile space). "Uniform": l_p is the particle's initial half-size (the caller passes
// l_p = 0.5 V0^(1/Dim) per axis for a regular lattice) and is never updated with F, unlike
// cpGIMP; so the boxes stop tiling space under large strain. lp <= 1/2 (at least one particle per
// cell per axis; larger particles need a 4-node formula, refused). Support half-width 1 + lp <= 1.5
// cells: 3 nodes per axis, the window of the nearest node and its two neighbours.
//
// At the grid's edges the box of a particle within l_p of the edge pokes out; the outside node's
// share is folded onto the edge nodes (TensorProductShapeFunction.hpp). With xi < lp the outside
// node has S_-1 = (lp - xi)^2/(4 lp), and the fold gives
//     node 0: 1 - (xi^2 + lp^2)/(2 lp) + 2 (lp - xi)^2/(4 lp) = 1 - xi
//     node 1: (lp + xi)^2/(4 lp) - (lp - xi)^2/(4 lp)         = xi
// the linear hat: in the last l_p before the edge uGIMP becomes the hat of a point particle,
// non-negative, with the partition of unity and linear completeness up to the edge.
#include "grid/shapeFunctions/UGimpShapeFunction.hpp"

namespace mfdyn {

template <class T>
std::int64_t UGimpBasis::weights(T xi, double lp, std::int64_t, T* w, T* dw) {
    using shapeFunctionDetail::realPart;
    const std::int64_t start = shapeFunctionDetail::floorIndex(xi + 0.5) - 1;
    const double inverse = 1.0 / lp;
    for (int k = 0; k < width; ++k) {
        const T r = xi - double(start + k);
        const double sign = realPart(r) >= 0.0 ? 1.0 : -1.0;
        const T a = sign * r;  // |r|, keeping a complex step's direction
        if (realPart(a) < lp) {
            w[k] = 1.0 - 0.5 * (r * r + lp * lp) * inverse;
            dw[k] = -r * inverse;
        } else if (realPart(a) <= 1.0 - lp) {
            w[k] = 1.0 - a;
            dw[k] = -sign;
        } else if (realPart(a) < 1.0 + lp) {
            const T q = 1.0 + lp - a;
            w[k] = 0.25 * q * q * inverse;
            dw[k] = -sign * 0.5 * q * inverse;
        } else {
            w[k] = 0.0;
            dw[k] = 0.0;
        }
    }
    return start;
}

template <int Dim>
KeywordSchema UGimpShapeFunction<Dim>::keywords() {
    return KeywordSchema(ShapeFunction<Dim>::familyName, "uGIMP");
}

template class UGimpShapeFunction<1>;
template class UGimpShapeFunction<2>;
template class UGimpShapeFunction<3>;

MFDYN_REGISTER_DIM(
    ShapeFunction, UGimpShapeFunction, "uGIMP",
    "uniform GIMP (Bardenhagen & Kober 2004): the hat averaged over the particle's initial box "
    "(C1, 3 nodes per axis; half-size at most half a cell)");

}  // namespace mfdyn
