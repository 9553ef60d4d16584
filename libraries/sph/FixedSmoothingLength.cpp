// Fixed smoothing length: h_i never changes. Its value is `h` when given, else the initial
// massDensity value η (m_i/ρ_i)^{1/d} (Zisis 2017 eq. 4.2). For flows whose density changes
// little (smooth-flow tests); under compression a fixed h gathers ever more neighbours.
#include "sph/FixedSmoothingLength.hpp"

namespace mfdyn {

KeywordSchema FixedSmoothingLength::keywords() {
    return etaKeyword("fixed").append(
        KeywordSchema(familyName, "fixed")
            .scalar("h", "m", "the smoothing length of every particle (else from eta)")
            .greaterThan(0)
            .optional());
}

FixedSmoothingLength::FixedSmoothingLength(const Dictionary& dict)
    : FixedSmoothingLength(keywords().read(dict)) {}

FixedSmoothingLength::FixedSmoothingLength(const KeywordValues& v)
    : SmoothingLengthLaw(v.scalar("eta")), h_(v.optionalScalar("h").value_or(0.0)) {}

double FixedSmoothingLength::initial(int dim, double mass, double rho) const {
    return h_ > 0 ? h_ : eta() * dimensionRoot(mass / rho, dim);
}

MFDYN_REGISTER(SmoothingLengthLaw, FixedSmoothingLength, "fixed", "h constant in time");

}  // namespace mfdyn
