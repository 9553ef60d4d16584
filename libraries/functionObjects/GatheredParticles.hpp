#pragma once
// What a function object sees on several ranks (ParticleScope, FunctionObject.hpp).
//
// GatheredParticles: every rank's owned particles on every rank, for the objects written for one
// process (scope all). refresh() is collective: each rank packs its owned particles' selected
// fields (globalId and region always), every rank receives every rank's bytes
// (Communicator::allGatherVariable) and puts them in global-id order. That is the serial run's
// order when the particle file is in id order (as particleGen writes it), so an object that breaks
// ties by index, takes a median or sorts by position gives the serial answer, and every rank the
// same one. Its cost per refresh: the selected fields of all N particles in every rank's memory
// and received by every rank, and a sort when the ranks' pieces interleave in id. FunctionObjectList
// refreshes it once per call, and only at the calls where an object of scope all writes.
//
// FunctionObjectContext: the context FunctionObjectList constructs each object with on several
// ranks. It forwards everything to the run's context except the particles: fields() and
// ownedParticles() show the gathered copy or the run's own (this rank's), by the scope the
// object's base constructor stated.
#include "functionObjects/FunctionObject.hpp"
#include "particles/ParticleSetBase.hpp"

#include <cstdint>
#include <memory>
#include <optional>
#include <set>
#include <string>

namespace mfdyn {

class GatheredParticles {
public:
    explicit GatheredParticles(const RunContext& run);
    ~GatheredParticles();
    GatheredParticles(const GatheredParticles&) = delete;
    GatheredParticles& operator=(const GatheredParticles&) = delete;

    // The copy as of the latest refresh. The first call gathers: objects read the particles in
    // their constructors, which every rank runs at the same point, so that gather is collective
    // too; later ones are FunctionObjectList's explicit refresh().
    const ParticleSetBase& particles();
    // Collective: every rank's owned particles again, with the selected fields.
    void refresh();
    // From now on only `fields` (and globalId, region) are gathered; the copy drops the others.
    // nullopt: every field of the run. Called once the objects are built and have said what they
    // read (FunctionObject::fieldsRead): a reference an object took to a field it did not name
    // would be left pointing at a removed field.
    void select(const std::optional<std::set<std::string>>& fields);
    // How often the particles were gathered (for tests: once per call with a write of scope all).
    std::uint64_t refreshes() const { return refreshes_; }
    // The copy as it is, without gathering: null before the first gather.
    const ParticleSetBase* copy() const { return copy_.get(); }

private:
    bool gathers(const std::string& field) const;

    const RunContext& run_;
    std::unique_ptr<ParticleSetBase> copy_;
    std::optional<std::set<std::string>> selected_;
    std::uint64_t refreshes_ = 0;
};

class FunctionObjectContext final : public RunContext {
public:
    FunctionObjectContext(const RunContext& run, GatheredParticles& gathered)
        : run_(run), gathered_(gathered) {}

    // Called by FunctionObject's constructor, before the derived constructor reads a particle:
    // the object's constructor receives this context as `const RunContext&`, so the scope is set
    // through a const call (a mutable member) once, at that point, and never changed.
    void show(ParticleScope scope) const { scope_ = scope; }
    ParticleScope scope() const { return scope_; }

    const Case& runCase() const override { return run_.runCase(); }
    const Time& time() const override { return run_.time(); }
    const FieldStore& fields() const override;
    const std::string& startTimeName() const override { return run_.startTimeName(); }
    std::optional<double> internalEnergy() const override { return run_.internalEnergy(); }
    std::optional<double> potentialEnergy() const override { return run_.potentialEnergy(); }
    std::optional<double> schemeDissipation() const override { return run_.schemeDissipation(); }
    std::optional<double> externalWork() const override { return run_.externalWork(); }
    bool energyBudgetCloses() const override { return run_.energyBudgetCloses(); }
    std::vector<HealthIndicator> healthIndicators() const override { return run_.healthIndicators(); }
    std::optional<DomainBox> domain() const override { return run_.domain(); }
    std::size_t ownedParticles() const override;
    const RunContext& solverContext() const override { return run_.solverContext(); }

private:
    const RunContext& run_;
    GatheredParticles& gathered_;
    mutable ParticleScope scope_ = ParticleScope::all;
};

}  // namespace mfdyn
