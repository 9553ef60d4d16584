// volume: ρ̃_i = ρ_i q̃_i with q̃_i = Σ_j (m_j/ρ_j) W_ij, the Lebesgue (colour-function) measure
// (Zisis 2017 eqs. 3.47–3.56, denominator ρ_iρ_j per the errata). a_i = m_i/ρ_i, b_j = m_j/ρ_j, c_i = ρ_i.
// Its summation is implicit in ρ (b depends on ρ), so only the continuity form is offered.
#include "sph/VolumeScheme.hpp"

namespace mfdyn {

KeywordSchema VolumeScheme::keywords() {
    return commonKeywords("volume");
}

VolumeScheme::VolumeScheme(const Dictionary& dict) : VolumeScheme(keywords().read(dict)) {}

VolumeScheme::VolumeScheme(const KeywordValues& v) : DensityScheme(v) {
    if (summation())
        throw v.error("form",
                      "the volume scheme's summation is implicit in the density; use form continuity");
}

void VolumeScheme::coefficients(std::size_t n, const double* m, const double* rho, double* a, double* b,
                                double* c) const {
    for (std::size_t i = 0; i < n; ++i) a[i] = m[i] / rho[i], b[i] = m[i] / rho[i], c[i] = rho[i];
}

MFDYN_REGISTER(DensityScheme, VolumeScheme, "volume",
               "rho = rho sum (m/rho) W (volume measure), continuity form, momentum/energy matched");

}  // namespace mfdyn
