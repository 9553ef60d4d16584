// The densityScheme family's shared keywords (the schemes are in their own files).
#include "sph/DensityScheme.hpp"

namespace mfdyn {

KeywordSchema DensityScheme::commonKeywords(const char* type) {
    return KeywordSchema(familyName, type)
        .word("form", {"continuity", "summation"}, "density by the continuity equation or by the summation")
        .orDefault("continuity")
        .flag("gradH", "the grad-h factor omega in the continuity, momentum and energy equations")
        .orDefault(true)
        .scalar("omegaMin", "-", "floor of omega (at free surfaces the sum behind it loses its far half)")
        .greaterThan(0)
        .atMost(1)
        .orDefault(0.5);
}

DensityScheme::DensityScheme(const KeywordValues& v)
    : summation_(v.word("form") == "summation"), gradH_(v.flag("gradH")), omegaMin_(v.scalar("omegaMin")) {}

DensityScheme::~DensityScheme() = default;

}  // namespace mfdyn
