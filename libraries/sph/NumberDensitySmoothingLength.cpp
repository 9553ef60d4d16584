// Smoothing length from the number density (Zisis 2017 eq. 4.1; Hu & Adams 2006):
//
//     h_i = η ñ_i^{-1/d},   ñ_i = Σ_j W_ij(h_i)  (the number density of the last neighbour sum),
//
// which follows the particle spacing whatever the masses: at a contact of materials of very
// different densities (the thesis's multi-material impacts) it keeps h continuous where the
// massDensity law jumps. The initial h is η (m/ρ)^{1/d}.
#include "sph/NumberDensitySmoothingLength.hpp"

namespace mfdyn {

KeywordSchema NumberDensitySmoothingLength::keywords() {
    return etaKeyword("numberDensity");
}

NumberDensitySmoothingLength::NumberDensitySmoothingLength(const Dictionary& dict)
    : SmoothingLengthLaw(keywords().read(dict).scalar("eta")) {}

void NumberDensitySmoothingLength::update(int dim, std::size_t n, const double*, const double*,
                                          const double* number, double* h) const {
    for (std::size_t i = 0; i < n; ++i) h[i] = eta() / dimensionRoot(number[i], dim);
}

double NumberDensitySmoothingLength::initial(int dim, double mass, double rho) const {
    return eta() * dimensionRoot(mass / rho, dim);
}

MFDYN_REGISTER(SmoothingLengthLaw, NumberDensitySmoothingLength, "numberDensity",
               "h = eta n^(-1/d), n = sum W");

}  // namespace mfdyn
