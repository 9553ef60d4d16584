#pragma once
// The quadratic B-spline on the nodes, shape function `quadraticBSpline` (equations and source in QuadraticBSplineShapeFunction.cpp).
#include "core/KeywordSchema.hpp"
#include "grid/shapeFunctions/TensorProductShapeFunction.hpp"

namespace mfdyn {

struct QuadraticBSplineBasis {
    static constexpr int width = 3;
    static constexpr double supportHalfWidth = 1.5;
    static constexpr bool needsSize = false;
    // Forced inline into evaluate()'s particle loop: GCC kept uGIMP's and the cubic's as calls
    // (a few per cent of evaluate()'s time).
    template <class T>
    [[gnu::always_inline]] static inline std::int64_t weights(T xi, double lp, std::int64_t n, T* w, T* dw);
};

template <int Dim>
class QuadraticBSplineShapeFunction : public TensorProductShapeFunction<Dim, QuadraticBSplineBasis> {
public:
    explicit QuadraticBSplineShapeFunction(const Dictionary&) {}
    static KeywordSchema keywords();
};

extern template class QuadraticBSplineShapeFunction<1>;
extern template class QuadraticBSplineShapeFunction<2>;
extern template class QuadraticBSplineShapeFunction<3>;

}  // namespace mfdyn
