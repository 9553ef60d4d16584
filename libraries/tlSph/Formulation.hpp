#pragma once
// The conservation laws a total-Lagrangian solver evolves (Lee et al. 2016, doc/methods/tl-jst-sph.md 1 and
// 2.3), chosen by name in constant/tlSphProperties:
//
//     formulation { type pFJ; }
//
//     type          evolves               computed from F each evaluation
//     pF            p, F                  H = cof F, J = det F
//     pFJ           p, F, J               H = cof F
//     pFHJ          p, F, H, J            -
//     displacement  p (and x)             F = I + grad~ u, u = x - X (Remark 5, eq. 34: the
//                                         classical displacement-based TL-SPH, for comparison)
//
// The solver asks only which fields a formulation evolves; the update rules are the solver's
// (dF/dt = G, dH/dt = F x G, dJ/dt = H : G with G = grad~ v).
#include "core/KeywordSchema.hpp"
#include "core/Registry.hpp"

#include <memory>
#include <string>

namespace mfdyn {

class Formulation {
public:
    static constexpr const char* familyName = "formulation";
    using Selector = Registry<Formulation, const Dictionary&>;
    static std::unique_ptr<Formulation> New(const Dictionary& dict);

    virtual ~Formulation();
    virtual std::string name() const = 0;
    virtual bool evolvesF() const = 0;
    virtual bool evolvesH() const = 0;
    virtual bool evolvesJ() const = 0;
    bool displacementBased() const { return !evolvesF(); }
};

}  // namespace mfdyn
