#pragma once
// What every ParticleSet<Dim> has, without the dimension in the type: the fields (FieldStore),
// and the names of regions and materials that the integer fields `region` (and a model's
// `material`, if it keeps one) index. Generic code (writers, function objects, utilities)
// works on this; solvers dispatch once to ParticleSet<Dim> with withDimension().
#include "particles/FieldStore.hpp"

#include <memory>
#include <string>
#include <vector>

namespace mfdyn {

class ParticleSetBase : public FieldStore {
public:
    ~ParticleSetBase() override;

    // region id -> name, and material id -> name; written to and read from the particle file.
    std::vector<std::string> regionNames;
    std::vector<std::string> materialNames;

    // A field of `kind` created by name, for code that does not know Dim (the reader); the
    // element type is the one ParticleSet<Dim> uses for that kind.
    virtual FieldBase& addField(const std::string& name, FieldKind kind) = 0;
    using FieldStore::addField;
    virtual std::unique_ptr<ParticleSetBase> clone() const = 0;

    // Particles per region id (ids beyond regionNames are counted too).
    std::vector<std::size_t> regionCounts() const;

protected:
    ParticleSetBase(int dimension, std::size_t size) : FieldStore(dimension, size) {}
    ParticleSetBase(const ParticleSetBase&) = default;
};

}  // namespace mfdyn
