#pragma once
// What every ParticleSet<Dim> has, without the dimension in the type: the fields (FieldStore),
// and the names of regions and materials that the integer fields `region` (and a model's
// `material`, if it keeps one) index. Generic code (writers, function objects, utilities)
// works on this; solvers dispatch once to ParticleSet<Dim> with withDimension().
#include "particles/FieldStore.hpp"

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace mfdyn {

// Refreshes the halo of a field: the values of other ranks' particles that this rank's owned
// particles read (particles/Decomposition.hpp implements it over MPI). `data` is the field's
// first element, elementBytes its size; the halo occupies [first, first + count) of the field.
class HaloExchange {
public:
    virtual ~HaloExchange() = default;
    virtual void refresh(void* data, std::size_t elementBytes, std::size_t first) const = 0;
};

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

    // --- Particles that come and go -------------------------------------------------------
    // append(n) issues the new particles the ids nextGlobalId() .. + n - 1 (region 0, every
    // other field zero); keep() retires the ids of the particles it removes. An id is never
    // issued twice in a run, nor after a restart: nextGlobalId() is above every id this set has
    // held, and the particle file carries it (FieldData nextGlobalId, written when it is more
    // than the largest id + 1, i.e. after the particle of the highest id was removed).
    // Both refuse while ghosts are there (clear them first: ghosts are remade each step).
    //
    // MPI (not built yet): each rank holds its own set; the ranks agree on the next id by a
    // global max of nextGlobalId() after each topology change, and a rank appending k
    // particles takes the block [next + offset, next + offset + k) with offset the exclusive
    // prefix sum of the ranks' k, so blocks are disjoint and no id is reused.
    std::size_t append(std::size_t n) override;
    void keep(const std::vector<std::size_t>& indices) override;
    void resize(std::size_t n) override;
    void reorder(const std::vector<std::size_t>& order) override;
    // Above every id issued, held or read so far.
    std::int64_t nextGlobalId() const;
    // Raise the next id to at least `next` (the reader, from the file's nextGlobalId).
    void reserveGlobalIdsBelow(std::int64_t next);

    // --- Owned particles and ghosts -------------------------------------------------------
    // The set holds its owned particles [0, ownedCount()) followed by ghosts
    // [ownedCount(), size()): read-only images of owned particles (mirror planes today, other
    // ranks' particles under MPI), remade each step, never integrated or written. Ghost g
    // (index ownedCount() + g) is the image of owned particle ghostSource()[g]; the orthogonal
    // map from source to ghost is ParticleSet<Dim>::ghostMap()[g]. Without ghosts
    // ownedCount() == size().
    std::size_t ownedCount() const { return size() - ghostSource_.size(); }
    std::size_t ghostCount() const { return ghostSource_.size(); }
    const std::vector<std::size_t>& ghostSource() const { return ghostSource_; }
    // Drop every ghost (the fields shrink back to the owned particles).
    virtual void clearGhosts();

    // --- The halo (MPI) -------------------------------------------------------------------
    // Under domain decomposition the first ghosts are the halo: other ranks' particles that
    // this rank's owned ones reach, appended by the decomposition (appendHalo: every field
    // extended, each halo ghost its own source under the identity map, so the ghost loops
    // below leave it alone) and filled from their owners. copyToGhosts and reflect*ToGhosts
    // refresh the halo of the field they are given first, so "this phase's neighbours read
    // field f" is said once, by the call, serially and distributed alike.
    virtual std::size_t appendHalo(std::size_t n, const HaloExchange& exchange);
    std::size_t haloCount() const { return haloCount_; }
    std::size_t haloBegin() const { return haloBegin_; }
    // Fills the halo part of a field from its owners (nothing without a halo).
    void refreshHalo(void* data, std::size_t elementBytes) const {
        if (haloCount_ != 0) halo_->refresh(data, elementBytes, haloBegin_);
    }
    // Changes only when the owned particles change (appended, removed, reordered, migrated), not
    // when ghosts come and go: what a list over owned and halo particles must be rebuilt for.
    std::uint64_t ownedTopologyVersion() const { return ownedVersion_; }
    // Particles arrived from another rank: n more, every field zero, no id issued (the sender's
    // ids come with the fields).
    std::size_t appendMigrated(std::size_t n);

protected:
    // Append ghosts of `source` (owned indices), every field copied from its source (globalId
    // too: a ghost is its source seen elsewhere); returns the first ghost's index.
    std::size_t appendGhostCopies(const std::vector<std::size_t>& source);

    ParticleSetBase(int dimension, std::size_t size) : FieldStore(dimension, size) {}
    ParticleSetBase(const ParticleSetBase&) = default;

private:
    void refuseWithGhosts(const char* operation) const;

    std::int64_t nextIdFloor_ = 0;
    std::uint64_t ownedVersion_ = 0;
    const HaloExchange* halo_ = nullptr;
    std::size_t haloBegin_ = 0, haloCount_ = 0;          // the next id is at least this (see nextGlobalId())
    std::vector<std::size_t> ghostSource_;  // per ghost, its owned source
};

}  // namespace mfdyn
