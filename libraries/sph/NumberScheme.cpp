// number: ρ_i = m_i ñ_i with ñ_i = Σ_j W_ij, the counting measure (Zisis 2017 eqs. 3.57–3.65,
// 4.17–4.19; Hu & Adams 2006). It ties h to the particle spacing whatever the masses, which is why
// the thesis uses it for unequal masses and multi-material contact. a_i = m_i²/ρ_i², b_j = 1, c_i = m_i.
#include "sph/NumberScheme.hpp"

namespace mfdyn {

KeywordSchema NumberScheme::keywords() {
    return commonKeywords("number");
}

NumberScheme::NumberScheme(const Dictionary& dict) : DensityScheme(keywords().read(dict)) {}

void NumberScheme::coefficients(std::size_t n, const double* m, const double* rho, double* a, double* b,
                                double* c) const {
    for (std::size_t i = 0; i < n; ++i) {
        const double ratio = m[i] / rho[i];
        a[i] = ratio * ratio, b[i] = 1.0, c[i] = m[i];
    }
}

MFDYN_REGISTER(DensityScheme, NumberScheme, "number",
               "rho = m sum W (number measure, Hu & Adams), momentum/energy matched");

}  // namespace mfdyn
