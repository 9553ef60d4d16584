#pragma once
// Artificial dissipation of an SPH shock solver, chosen by name (the family `dissipation`):
//
//   dissipation { type riemann; velocity (1 2); density (0.5 2); energy (0.1 2); signal riemann;
//                 pairs approaching; }
//   dissipation { type monaghanGingold; alpha 1; beta 2; balsara no; density (0.5 0); }  // + mass flux
//   dissipation { type none; }
//
// Each model's equations and keywords are in its own .cpp (RiemannDissipation,
// MonaghanGingoldViscosity, NoDissipation) and in doc/models/dissipation/. The pair terms are
// evaluated inside SphSolver's force loop, not by a virtual call per pair: a model states its
// parameters (DissipationParameters) and the solver's loop applies them.
#include "core/KeywordSchema.hpp"
#include "core/Registry.hpp"

#include <memory>

namespace mfdyn {

struct DissipationParameters {
    enum class Kind { none, riemann, monaghanGingold } kind = Kind::none;
    double av = 0, bv = 0, arho = 0, brho = 0, ae = 0, be = 0;
    bool alternativeSignal = false;
    bool allPairs = false;
    double alpha = 0, beta = 0;
    bool balsara = false;
};

class Dissipation {
public:
    static constexpr const char* familyName = "dissipation";
    using Selector = Registry<Dissipation, const Dictionary&>;
    static std::unique_ptr<Dissipation> New(const Dictionary& dict) { return Selector::New(dict); }

    explicit Dissipation(const Dictionary&) {}
    virtual ~Dissipation() = default;
    // The pair terms are evaluated inside the solver's force loop (a virtual call per pair would
    // cost more than the terms); a model states its parameters.
    virtual DissipationParameters parameters() const = 0;
};

}  // namespace mfdyn
