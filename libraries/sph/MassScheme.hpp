#pragma once
#include "sph/DensityScheme.hpp"

namespace mfdyn {

class MassScheme final : public DensityScheme {
public:
    static KeywordSchema keywords();
    explicit MassScheme(const Dictionary& dict);
    void coefficients(std::size_t n, const double* m, const double* rho, double* a, double* b,
                      double* c) const override;
};

}  // namespace mfdyn
