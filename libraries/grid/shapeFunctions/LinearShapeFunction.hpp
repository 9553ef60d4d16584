#pragma once
// The linear hat of the MPM thesis, shape function `linear` (equations and source in LinearShapeFunction.cpp).
#include "core/KeywordSchema.hpp"
#include "grid/shapeFunctions/TensorProductShapeFunction.hpp"

namespace mfdyn {

struct LinearBasis {
    static constexpr int width = 2;
    static constexpr double supportHalfWidth = 1.0;
    static constexpr bool needsSize = false;
    // Forced inline into evaluate()'s particle loop: GCC kept uGIMP's and the cubic's as calls
    // (a few per cent of evaluate()'s time).
    template <class T>
    [[gnu::always_inline]] static inline std::int64_t weights(T xi, double lp, std::int64_t n, T* w, T* dw);
};

template <int Dim>
class LinearShapeFunction : public TensorProductShapeFunction<Dim, LinearBasis> {
public:
    explicit LinearShapeFunction(const Dictionary&) {}
    static KeywordSchema keywords();
};

extern template class LinearShapeFunction<1>;
extern template class LinearShapeFunction<2>;
extern template class LinearShapeFunction<3>;

}  // namespace mfdyn
