#pragma once
// `numberDensity`: see NumberDensitySmoothingLength.cpp for its equations and keywords.
#include "sph/SmoothingLengthLaw.hpp"

namespace mfdyn {

class NumberDensitySmoothingLength final : public SmoothingLengthLaw {
public:
    static KeywordSchema keywords();
    explicit NumberDensitySmoothingLength(const Dictionary& dict);
    void update(int dim, std::size_t n, const double*, const double*, const double* number,
                double* h) const override;
    bool needsNumberDensity() const override { return true; }
    double initial(int dim, double mass, double rho) const override;
};

}  // namespace mfdyn
