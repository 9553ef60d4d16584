#pragma once
// Uniform GIMP, shape function `uGIMP` (equations and source in UGimpShapeFunction.cpp).
#include "core/KeywordSchema.hpp"
#include "grid/shapeFunctions/TensorProductShapeFunction.hpp"

namespace mfdyn {

struct UGimpBasis {
    static constexpr int width = 3;
    static constexpr double supportHalfWidth = 1.5;
    static constexpr bool needsSize = true;
    // Forced inline into evaluate()'s particle loop: GCC kept uGIMP's and the cubic's as calls
    // (a few per cent of evaluate()'s time).
    template <class T>
    [[gnu::always_inline]] static inline std::int64_t weights(T xi, double lp, std::int64_t n, T* w, T* dw);
};

template <int Dim>
class UGimpShapeFunction : public TensorProductShapeFunction<Dim, UGimpBasis> {
public:
    explicit UGimpShapeFunction(const Dictionary&) {}
    static KeywordSchema keywords();
};

extern template class UGimpShapeFunction<1>;
extern template class UGimpShapeFunction<2>;
extern template class UGimpShapeFunction<3>;

}  // namespace mfdyn
