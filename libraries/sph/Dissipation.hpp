#pragma once
// Artificial dissipation of an SPH shock solver, chosen by name (the family `dissipation`):
//
//   dissipation { type riemann; velocity (1 2); density (0.5 2); energy (0.1 2); signal riemann;
//                 pairs approaching; }
//   dissipation { type monaghanGingold; alpha 1; beta 2; balsara no; density (0.5 0); }  // + mass flux
//   dissipation { type none; }
//
// A model is behaviour, not flags: it carries its own pair terms (viscous force, mass flux,
// heating), and its equations and keywords are in its own .cpp (RiemannDissipation,
// MonaghanGingoldViscosity, NoDissipation) and in doc/models/impactSph/dissipation/. Evaluated
// inside the solver's fused pair loop by double dispatch (SphPairLoop.hpp): one virtual
// computeRates() a rate evaluation, which runs the loop compiled with the model's inline pair
// terms, so a model in a user library costs no virtual call per pair either. One overload per dimension: the solver is
// SphSolver<Dim> for Dim 1, 2, 3, the family one registry.
#include "core/KeywordSchema.hpp"
#include "core/Registry.hpp"

#include <memory>

namespace mfdyn {

template <int Dim>
struct SphPairLoop;

class Dissipation {
public:
    static constexpr const char* familyName = "dissipation";
    // impactSph's own family ("dissipation (impactSph)"; tlSph's dissipation is another).
    static constexpr const char* methodName = "impactSph";
    using Selector = Registry<Dissipation, const Dictionary&>;
    static std::unique_ptr<Dissipation> New(const Dictionary& dict) { return Selector::New(dict); }

    explicit Dissipation(const Dictionary&) {}
    virtual ~Dissipation() = default;

    // The rates of this step's pairs with the model's terms: defined by each model as
    // `{ loop.run(*this); }` (SphPairLoop.hpp).
    virtual void computeRates(SphPairLoop<1>& loop) = 0;
    virtual void computeRates(SphPairLoop<2>& loop) = 0;
    virtual void computeRates(SphPairLoop<3>& loop) = 0;
};

}  // namespace mfdyn
