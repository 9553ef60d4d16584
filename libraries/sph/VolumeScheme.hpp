#pragma once
#include "sph/DensityScheme.hpp"

namespace mfdyn {

class VolumeScheme final : public DensityScheme {
public:
    static KeywordSchema keywords();
    explicit VolumeScheme(const Dictionary& dict);
    void coefficients(std::size_t n, const double* m, const double* rho, double* a, double* b,
                      double* c) const override;
    bool explicitSummation() const override { return false; }

private:
    explicit VolumeScheme(const KeywordValues& v);
};

}  // namespace mfdyn
