#pragma once
// The particles a boundary condition acts on, read from the condition's own dictionary:
//
//     regions (wall lid);                          particles of these named regions
//     shape   { type box; min (0 0 0); max (1 0.1 1); }   particles inside the shape (Shape::New)
//     all     yes;                                 every particle
//
// `regions` and `shape` together select their intersection (the part of a region inside a box).
// A condition that may act on everything without a selection (a plane, which selects by its own
// side test) passes allByDefault; one that freezes particles (fixed) does not, so a forgotten
// `regions` is an error rather than a case in which nothing moves.
//
// The selection is resolved once, to an index list of owned particles (ghosts are never
// selected; haloIndices() gives the selected particles of an MPI halo). On several ranks the ids
// selected at the start are gathered from every rank, so that update() after a migration finds a
// particle that arrived from another rank. Indices go stale when the solver reorders particles (cell sorting) or changes
// their number (ParticleSetBase::append/keep); update() then
//   - keeps the same particles, found again by globalId (default): a removed particle drops
//     out, a particle appended since the last update (a global id not issued then) is judged by
//     the criteria (a new particle of region `inlet` joins `regions (inlet)`), or
//   - with `reselect yes;`, evaluates the criteria again on the current positions, for an
//     Updated-Lagrangian run whose boundary is a fixed region of space rather than fixed particles.
// refresh() is update() only when the particles changed since (FieldStore::topologyVersion()).
#include "core/Dictionary.hpp"
#include "core/KeywordSchema.hpp"
#include "geometry/Shape.hpp"
#include "particles/ParticleSet.hpp"

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace mfdyn {

// The selection keywords (regions, shape, all, reselect), appended to every boundary condition's
// schema (BoundaryCondition.hpp).
KeywordSchema selectionKeywords();

template <int Dim>
class Selection {
public:
    // From values read through a schema that includes selectionKeywords().
    Selection(const KeywordValues& values, const ParticleSet<Dim>& particles, bool allByDefault);
    // Reads `dict` through selectionKeywords() alone.
    Selection(const Dictionary& dict, const ParticleSet<Dim>& particles, bool allByDefault);
    Selection(Selection&&) noexcept = default;
    Selection& operator=(Selection&&) noexcept = default;
    ~Selection();

    // Indices into the particle set, ascending.
    const std::vector<std::size_t>& indices() const { return indices_; }
    // The selected particles of the set's halo (other ranks' particles this rank sees, MPI), for
    // a condition whose images or forces reach across a rank boundary (mirrorPlane's sources).
    std::vector<std::size_t> haloIndices(const ParticleSet<Dim>& particles) const;
    std::size_t size() const { return indices_.size(); }
    bool selectsAll() const { return all_; }

    // Refresh after a reorder or a change in particle count (see the header comment).
    void update(const ParticleSet<Dim>& particles);
    // update() if the particles' topologyVersion() differs from the one last resolved for;
    // returns whether it did.
    bool refresh(const ParticleSet<Dim>& particles);
    // Evaluate the criteria on the current state, whatever `reselect` says.
    void resolve(const ParticleSet<Dim>& particles);

    // "regions (wall)", "shape box", "all particles": for the log.
    std::string describe() const;

private:
    bool all_ = false;
    bool reselect_ = false;
    std::vector<std::string> regionNames_;
    std::vector<std::int64_t> regionIds_;
    std::unique_ptr<Shape> shape_;
    std::string shapeType_;
    std::vector<std::size_t> indices_;
    std::vector<std::int64_t> globalIds_;  // of indices_
    // The ids selected by identity on every rank (sorted): a particle that migrates from another
    // rank stays selected here. On one process, those of indices_ and the ones that joined since.
    std::vector<std::int64_t> wantedIds_;
    std::int64_t newIdsFrom_ = 0;          // ids from this one on were not issued at the last update
    std::uint64_t topologyVersion_ = 0;    // of the particles at the last update
    bool matches(const ParticleSet<Dim>& particles, std::size_t i) const;
    void record(const ParticleSet<Dim>& particles);
};

extern template class Selection<1>;
extern template class Selection<2>;
extern template class Selection<3>;

}  // namespace mfdyn
