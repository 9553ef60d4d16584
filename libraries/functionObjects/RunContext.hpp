#pragma once
// What a running solver shows to function objects: the case, the time, the particle fields,
// and the energies it alone knows how to compute.
#include "core/Case.hpp"
#include "core/Time.hpp"
#include "particles/FieldStore.hpp"

#include <optional>
#include <string>

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
};

}  // namespace mfdyn
