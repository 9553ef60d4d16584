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
//             density 2700;                   // kg/m^3: mass = density × lattice volume per particle
//             fields  { velocity (0 -100); }  // uniform initial values of any scalar or vector field
//             override yes;                   // take over earlier regions' particles in this shape (default)
//         }
//     }
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
    double volume = 0;         // count × lattice volume per particle
    double exactVolume = -1;   // the shape's closed-form volume, or -1
    double mass = 0;
    double spacing = 0;
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
