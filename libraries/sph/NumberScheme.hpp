#pragma once
#include "sph/DensityScheme.hpp"

namespace mfdyn {

class NumberScheme final : public DensityScheme {
public:
    static KeywordSchema keywords();
    explicit NumberScheme(const Dictionary& dict);
    void coefficients(std::size_t n, const double* m, const double* rho, double* a, double* b,
                      double* c) const override;
};

}  // namespace mfdyn
