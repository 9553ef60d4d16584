#pragma once
// The cubic B-spline on the nodes, shape function `cubicBSpline` (equations and source in CubicBSplineShapeFunction.cpp).
#include "core/KeywordSchema.hpp"
#include "grid/shapeFunctions/TensorProductShapeFunction.hpp"

namespace mfdyn {

struct CubicBSplineBasis {
    static constexpr int width = 4;
    static constexpr double supportHalfWidth = 2.0;
    static constexpr bool needsSize = false;
    // Forced inline into evaluate()'s particle loop: GCC kept uGIMP's and the cubic's as calls
    // (a few per cent of evaluate()'s time).
    template <class T>
    [[gnu::always_inline]] static inline std::int64_t weights(T xi, double lp, std::int64_t n, T* w, T* dw);
};

template <int Dim>
class CubicBSplineShapeFunction : public TensorProductShapeFunction<Dim, CubicBSplineBasis> {
public:
    explicit CubicBSplineShapeFunction(const Dictionary&) {}
    static KeywordSchema keywords();
};

extern template class CubicBSplineShapeFunction<1>;
extern template class CubicBSplineShapeFunction<2>;
extern template class CubicBSplineShapeFunction<3>;

}  // namespace mfdyn
