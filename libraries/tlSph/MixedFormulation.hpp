#pragma once
// The mixed formulations {p,F}, {p,F,J}, {p,F,H,J} (Lee et al. 2016 eqs. 1, 6): F always, H and
// J as the template says. Registered as pF, pFJ, pFHJ.
#include "tlSph/Formulation.hpp"

namespace mfdyn {

template <bool EvolveH, bool EvolveJ>
class MixedFormulation final : public Formulation {
public:
    static constexpr const char* typeName = EvolveH ? "pFHJ" : EvolveJ ? "pFJ" : "pF";
    // No keywords: the formulation is its name.
    static KeywordSchema keywords() { return KeywordSchema(familyName, typeName); }
    explicit MixedFormulation(const Dictionary& dict) { keywords().read(dict); }
    std::string name() const override { return typeName; }
    bool evolvesF() const override { return true; }
    bool evolvesH() const override { return EvolveH; }
    bool evolvesJ() const override { return EvolveJ; }
};

}  // namespace mfdyn
