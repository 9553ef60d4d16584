// No artificial dissipation: the pair loop adds no viscosity, mass flux or conduction. For smooth
// flows and tests of the inviscid scheme; a shock without dissipation rings (Zisis 2017 §4.2).
#include "sph/NoDissipation.hpp"

namespace mfdyn {

KeywordSchema NoDissipation::keywords() {
    return KeywordSchema(familyName, "none");
}

NoDissipation::NoDissipation(const Dictionary& dict) : Dissipation(dict) {
    keywords().read(dict);
}

void NoDissipation::computeRates(SphPairLoop<1>& loop) {
    loop.run(*this);
}
void NoDissipation::computeRates(SphPairLoop<2>& loop) {
    loop.run(*this);
}
void NoDissipation::computeRates(SphPairLoop<3>& loop) {
    loop.run(*this);
}

MFDYN_REGISTER(Dissipation, NoDissipation, "none", "no artificial dissipation");

}  // namespace mfdyn
