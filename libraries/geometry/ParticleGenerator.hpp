#pragma once
// Particles from system/particleGenDict:
//
//     dimension 2;
//     regions
//     {
//         projectile                          // region name (region id = order of appearance)
//         {
//             shape   { type box; min (0 0); max (0.01 0.01); }
//             lattice { type cubic; spacing 1e-3; }
//             density 2700;                   // kg/m^3: mass = density × the point's lattice volume
//                                             // (materialPoints: × the shape's exact volume / N)
//             fields  { velocity (0 -100); }  // uniform initial values (known fields below)
//             override yes;                   // take over earlier regions' particles in this shape (default)
//             mass    uniformSpacing;         // or equalMass (below); default uniformSpacing
//             material aluminium;             // optional; stored in the integer field `material`
//             angularVelocity { omega (0 0 10); centre (0 0 0); }  // optional; rad/s, adds ω × (x − c)
//         }
//     }
//     userFields (myField);                   // optional: fields read by a model of your own
//
// `fields` takes the initial fields that the toolkit's models read (knownFieldsHelp(), printed by
// `particleGen -help`): velocity (vector), pressure, specificInternalEnergy, temperature,
// smoothingLength, plasticStrain (scalars). Any other name is an error with a did-you-mean, since
// a misspelt `velocty` would be written as a field no model reads; a user library's own field is
// declared in the top-level `userFields` list. position, globalId, region, mass, material and
// density are set by particleGen itself. Every value must be finite.
//
// Checks before anything is allocated: each region's lattice points over its shape's bounding
// box are counted (Lattice::pointCount) and, at 200 bytes per particle, compared with the free
// memory (MemAvailable in /proc/meminfo, lowered by a cgroup limit or `ulimit -v`); a region
// that would not fit is an error naming it, the estimated count and the spacing (particleGen
// itself measured 128 bytes per particle in 3D with velocity and pressure; 200 leaves room for more
// fields). A region left with no particle (none inside its shape, or all taken over by later
// regions) is an error, and so is a particle volume or mass that underflows to zero, overflows,
// or is subnormal. Shapes take coordinates and lengths within ±1e150 m, so that squared
// distances stay finite. A lattice much coarser than its shape (particle volume off by more
// than 25% from the shape's exact volume) is a warning.
//
// Two ways to fill regions of different density (doc/methods/sph-impact.md §4, "Initial lattices"):
//  - `mass uniformSpacing` (default), scheme (b): every region uses its lattice as given and
//    m_i = ρ₀ × (volume per lattice point). Works for any geometry; with equal spacings a density
//    jump becomes a mass jump, which gives a small pressure hump at the contact.
//  - `mass equalMass`, scheme (a): all equalMass regions get the same particle mass, that of the
//    lowest-density one with its own spacing; each other region's spacing is scaled by
//    (ρ_low/ρ)^(1/dim) (D_H = D_L ρ_L/ρ_H in 1D). Flat pressure at contacts, but the lightest material
//    sets the resolution, so it is costly for large density ratios; the method note recommends it
//    when the density ratio is small (below about 4).
// `material name;` must be one of `materials { name { ... } }` in <case>/constant/materialProperties
// when that file exists; the `material` field holds indices into ParticleSetBase::materialNames
// (in order of first use). Either every region names a material or none does.
// `angularVelocity` adds the rigid rotation ω × (x − c) to `velocity` (creating it if no region
// sets it); in 2D ω is about z, a scalar or (0 0 ω).
//
// Particles are generated region by region in lattice order and numbered 0..N-1 (globalId), so
// the output is identical run to run.
#include "core/Dictionary.hpp"
#include "particles/ParticleSetBase.hpp"

#include <memory>
#include <string>
#include <vector>

namespace mfdyn {

struct RegionReport {
    std::string name;
    std::size_t count = 0;
    double volume = 0;        // Σ the particles' lattice volumes (Lattice::pointVolumes)
    double exactVolume = -1;  // the shape's closed-form volume, or -1
    double mass = 0;
    double spacing = 0;  // Lattice::spacing(): 0 for a nodal lattice given by `points`
};

class ParticleGenerator {
public:
    explicit ParticleGenerator(const Dictionary& particleGenDict);
    // Throws InputError for bad input, Error when memory runs out.
    std::unique_ptr<ParticleSetBase> generate();
    const std::vector<RegionReport>& report() const { return report_; }
    std::string reportTable() const;
    // The fields `fields` accepts, one per line with their kind and meaning (for -help).
    static std::string knownFieldsHelp();

private:
    std::unique_ptr<ParticleSetBase> build();
    const Dictionary& dict_;
    int dimension_;
    std::vector<RegionReport> report_;
    std::string current_;  // the region being generated, for out-of-memory messages
};

}  // namespace mfdyn
