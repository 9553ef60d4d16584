#pragma once
// Which material each particle is made of, shared by the solvers that read
// constant/materialProperties { materials { name { ... } ... } }.
//
// A particle's material is, in order of precedence:
//   - its integer field `material`, an index into the particle file's material names (particleGen
//     writes both), matched by name to the materials the case defines;
//   - else its `region`, matched by the region's name;
//   - else, when the case defines exactly one material, that one.
// Anything else is an input error naming the particle, its material or region, and the valid
// materials. On return `material` holds indices into `names` and particles.materialNames = names.
#include "core/Dictionary.hpp"
#include "materials/MaterialSet.hpp"  // materialNames
#include "particles/ParticleSet.hpp"

#include <string>
#include <vector>

namespace mfdyn {

template <int Dim>
void assignMaterials(ParticleSet<Dim>& particles, const std::vector<std::string>& names,
                     const Dictionary& materialProperties);

}  // namespace mfdyn
