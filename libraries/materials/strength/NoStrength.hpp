#pragma once
// `none`: no deviatoric stress (fluids, gases, the thesis's shock tests). allocatesStress() is
// false, so a solver allocates no tau for the material and skips the strength phase for it.
//
//     strength { type none; }
#include "materials/strength/Strength.hpp"

namespace mfdyn {

template <int Dim>
class NoStrength : public Strength<Dim> {
public:
    using typename Strength<Dim>::Fields;

    explicit NoStrength(const Dictionary& dict);
    // No keywords beyond `type`.
    static KeywordSchema keywords() { return KeywordSchema(Strength<Dim>::familyName, "none"); }

    bool allocatesStress() const override { return false; }
    void update(const Fields& fields, double dt) const override;
    void stressRate(const Fields& fields) const override;
    double yieldStress(double plasticStrain, double strainRate, double temperature) const override;
};

}  // namespace mfdyn
