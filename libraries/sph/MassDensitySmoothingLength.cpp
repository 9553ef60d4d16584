// Smoothing length from the mass density (Zisis 2017 eq. 4.2; Monaghan 1992):
//
//     h_i = η (m_i/ρ_i)^{1/d},
//
// explicit in the evolved density, so that every particle keeps about the same number of
// neighbours under compression and expansion.
#include "sph/MassDensitySmoothingLength.hpp"

namespace mfdyn {

KeywordSchema MassDensitySmoothingLength::keywords() {
    return etaKeyword("massDensity");
}

MassDensitySmoothingLength::MassDensitySmoothingLength(const Dictionary& dict)
    : SmoothingLengthLaw(keywords().read(dict).scalar("eta")) {}

void MassDensitySmoothingLength::update(int dim, std::size_t n, const double* m, const double* rho,
                                        const double*, double* h) const {
    for (std::size_t i = 0; i < n; ++i) h[i] = eta() * dimensionRoot(m[i] / rho[i], dim);
}

double MassDensitySmoothingLength::initial(int dim, double mass, double rho) const {
    return eta() * dimensionRoot(mass / rho, dim);
}

MFDYN_REGISTER(SmoothingLengthLaw, MassDensitySmoothingLength, "massDensity", "h = eta (m/rho)^(1/d)");

}  // namespace mfdyn
