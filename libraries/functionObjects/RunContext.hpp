#pragma once
// What a running solver shows to function objects: the case, the time, the particle fields,
// and the energies it alone knows how to compute.
#include "core/Case.hpp"
#include "core/Time.hpp"
#include "functionObjects/HealthIndicator.hpp"
#include "particles/FieldStore.hpp"

#include <optional>
#include <string>
#include <vector>

namespace mfdyn {

class RunContext {
public:
    virtual ~RunContext() = default;
    virtual const Case& runCase() const = 0;
    virtual const Time& time() const = 0;
    virtual const FieldStore& fields() const = 0;
    int dimension() const { return fields().dimension(); }
    // The time directory the run started from: function objects write under
    // postProcessing/<name>/<startTimeName>/.
    virtual const std::string& startTimeName() const = 0;
    // Σ m e, or the stored elastic energy, when the solver has one.
    virtual std::optional<double> internalEnergy() const { return std::nullopt; }
    // Energy of conservative body forces, when the solver has one.
    virtual std::optional<double> potentialEnergy() const { return std::nullopt; }
    // The energy budget's other two terms, each summed since the solver was constructed (a run's
    // start), when the solver measures them (the health check's budget: K + U + Phi + D - W is
    // constant for a scheme that loses nothing it does not account for):
    //   schemeDissipation  energy the scheme's stabilisation removed from K + U (an artificial
    //                      viscosity whose heat goes to U removes nothing; JST's or upwinding's does)
    //   externalWork       work done on the particles by boundary conditions and non-conservative
    //                      body forces
    virtual std::optional<double> schemeDissipation() const { return std::nullopt; }
    virtual std::optional<double> externalWork() const { return std::nullopt; }
    // Whether that budget closes step by step (K + U + Phi + D - W constant to the time error in
    // every configuration the method runs): the health check's energy-growth stop is then on by
    // default (Health.cpp).
    virtual bool energyBudgetCloses() const { return false; }
    // The method's indicators of a degrading discretisation, computed now (the health check calls
    // it at its writes only: it may cost a pass over the neighbours).
    virtual std::vector<HealthIndicator> healthIndicators() const { return {}; }
    // The box the particles must stay in, when the method has one (a background grid's).
    virtual std::optional<DomainBox> domain() const { return std::nullopt; }
    // Particles [0, ownedParticles()) are this process's own; the rest are ghosts (images).
    virtual std::size_t ownedParticles() const { return fields().size(); }
    // The solver's own context: this one, or on several ranks the one a function object's
    // context wraps (FunctionObjectContext, which forwards every hook above: a new hook must be
    // forwarded there too). For a cast to a method's interface (trajectoryError's body force).
    virtual const RunContext& solverContext() const { return *this; }
};

}  // namespace mfdyn
