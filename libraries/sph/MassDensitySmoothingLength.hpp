#pragma once
// `massDensity`: see MassDensitySmoothingLength.cpp for its equations and keywords.
#include "sph/SmoothingLengthLaw.hpp"

namespace mfdyn {

class MassDensitySmoothingLength final : public SmoothingLengthLaw {
public:
    static KeywordSchema keywords();
    explicit MassDensitySmoothingLength(const Dictionary& dict);
    void update(int dim, std::size_t n, const double* m, const double* rho, const double*,
                double* h) const override;
    double initial(int dim, double mass, double rho) const override;
};

}  // namespace mfdyn
