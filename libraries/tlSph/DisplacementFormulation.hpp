#pragma once
// The classical displacement-based total-Lagrangian SPH (Lee et al. 2016 Remark 5, eq. 34;
// Vidal, Bonet, Huerta 2007): F = I + grad~(x - X) from the positions at every evaluation, only
// p and x evolve. The baseline the mixed formulations are compared with.
#include "tlSph/Formulation.hpp"

namespace mfdyn {

class DisplacementFormulation final : public Formulation {
public:
    // No keywords: the formulation is its name.
    static KeywordSchema keywords() { return KeywordSchema(familyName, "displacement"); }
    explicit DisplacementFormulation(const Dictionary& dict) { keywords().read(dict); }
    std::string name() const override { return "displacement"; }
    bool evolvesF() const override { return false; }
    bool evolvesH() const override { return false; }
    bool evolvesJ() const override { return false; }
};

}  // namespace mfdyn
