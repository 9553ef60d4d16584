// mass: ρ = Σ_j m_j W_ij, the probability measure (Zisis 2017 eqs. 3.38, 3.44–3.45).
// a_i = m_i/ρ_i², b_j = m_j, c_i = 1.
#include "sph/MassScheme.hpp"

namespace mfdyn {

KeywordSchema MassScheme::keywords() {
    return commonKeywords("mass");
}

MassScheme::MassScheme(const Dictionary& dict) : DensityScheme(keywords().read(dict)) {}

void MassScheme::coefficients(std::size_t n, const double* m, const double* rho, double* a, double* b,
                              double* c) const {
    for (std::size_t i = 0; i < n; ++i) a[i] = m[i] / (rho[i] * rho[i]), b[i] = m[i], c[i] = 1.0;
}

MFDYN_REGISTER(DensityScheme, MassScheme, "mass", "rho = sum m W (mass measure), momentum/energy matched");

}  // namespace mfdyn
