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
//             fields  { velocity (0 -100); }  // uniform initial values of any scalar or vector field
//             override yes;                   // take over earlier regions' particles in this shape (default)
//             mass    uniformSpacing;         // or equalMass (below); default uniformSpacing
//             material aluminium;             // optional; stored in the integer field `material`
//             angularVelocity { omega (0 0 10); centre (0 0 0); }  // optional; rad/s, adds ω × (x − c)
//         }
//     }
//
// Two ways to fill regions of different density (sph-impact.md §4, "Initial lattices"):
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
    std::unique_ptr<ParticleSetBase> generate();
    const std::vector<RegionReport>& report() const { return report_; }
    std::string reportTable() const;

private:
    const Dictionary& dict_;
    int dimension_;
    std::vector<RegionReport> report_;
};

}  // namespace mfdyn
