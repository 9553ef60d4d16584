#pragma once
#include "tlSph/TlDissipation.hpp"

namespace mfdyn {

// No dissipation: the unstabilised mixed SPH (hourglass modes and shock oscillations left alone).
class NoTlDissipation final : public TlDissipation {
public:
    static KeywordSchema keywords() { return KeywordSchema(familyName, "none"); }
    explicit NoTlDissipation(const Dictionary& dict) { keywords().read(dict); }
    void evaluate(const Block&) const override {}
    std::string describe() const override { return "none"; }
};

}  // namespace mfdyn
