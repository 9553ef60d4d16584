#pragma once
// The materials of a run: constant/materialProperties read once, and for each material the models
// its dictionary names, built by their families' selectors:
//
//     materials
//     {
//         water { equationOfState { type tait; ... } }                             // a fluid
//         steel { equationOfState { type mieGruneisen; } strength { type vonMises; } }
//         rubber { constitutiveLaw { type neoHookean; rho0 1100; mu 5e6; kappa 5e7; } }
//         oil   { equationOfState { type tait; rho0 900; B 1e6; } viscosity { type newtonian; mu 0.1; } }
//     }
//
// A method states which models it takes (MaterialModels): impactSph an equation of state and an
// optional strength law, tlSph a constitutive law, MPM an equation of state or a constitutive law
// per material (a fluid next to a solid in one run) and a viscosity for a fluid. A model the method does not take is an input
// error at its entry, naming the method and what it takes; a missing required one is an error at
// the material. The set answers which fields the models need (energy, stress, plastic strain,
// temperature, plastic state), so that a solver allocates only those, and logs one line per
// material. Which particle is made of which material is solver/MaterialAssignment's business
// (assignMaterials(particles, set.names(), materialProperties)).
//
// A viscosity (materials/viscosity/Viscosity.hpp) is a fluid's deviatoric stress: on a material
// with a strength law that carries stress, or with a constitutive law, it is an error at the
// viscosity entry (two deviators for one body); `strength { type none; }` beside it is allowed.
#include "materials/constitutive/ConstitutiveLaw.hpp"
#include "materials/equationOfState/EquationOfState.hpp"
#include "materials/strength/Strength.hpp"
#include "materials/viscosity/Viscosity.hpp"

#include <memory>
#include <string>
#include <vector>

namespace mfdyn {

class Dictionary;

// The names of the entries of materialProperties' `materials` dictionary, in the order written
// (each must be a dictionary; an empty list is an error).
std::vector<std::string> materialNames(const Dictionary& materialProperties);

enum class ModelUse { refused, optional, required };

struct MaterialModels {
    std::string method;  // for messages: "impactSph"
    ModelUse equationOfState = ModelUse::refused;
    ModelUse strength = ModelUse::refused;
    ModelUse constitutiveLaw = ModelUse::refused;
    // Each material must name an equation of state or a constitutive law (or both), where each
    // alone is optional: a method that runs fluids beside solids.
    bool equationOfStateOrConstitutiveLaw = false;
    // Last, so that the aggregate initialisers written before it stay valid.
    ModelUse viscosity = ModelUse::refused;  // mpmFsi's fluids only (optional there)
};

template <int Dim>
class MaterialSet {
public:
    struct Material {
        std::string name;
        const Dictionary* dict = nullptr;
        std::unique_ptr<EquationOfState> eos;              // null when the material names none
        std::unique_ptr<Strength<Dim>> strength;           // null when none, or one that carries no stress
        std::unique_ptr<ConstitutiveLaw> constitutiveLaw;  // null when none
        std::unique_ptr<Viscosity> viscosity;              // null when none (inviscid)
    };

    // Reads materialProperties' `materials` (materialNames' rules: each entry a dictionary, at
    // least one) and builds every material's models; logs one line per material.
    MaterialSet(const Dictionary& materialProperties, const MaterialModels& models);
    ~MaterialSet();
    MaterialSet(MaterialSet&&) noexcept;
    MaterialSet& operator=(MaterialSet&&) noexcept;

    std::size_t size() const { return materials_.size(); }
    const Material& operator[](std::size_t k) const { return materials_[k]; }
    const std::vector<std::string>& names() const { return names_; }

    // Some material's equation of state depends on the specific internal energy.
    bool needsEnergy() const { return needsEnergy_; }
    // Some material carries a deviatoric stress (a strength law other than `none`).
    bool anyStrength() const { return anyStrength_; }
    // Some material has a viscosity.
    bool anyViscosity() const { return anyViscosity_; }
    bool usesPlasticStrain() const { return usesPlasticStrain_; }
    bool usesTemperature() const { return usesTemperature_; }
    // Some constitutive law carries a plastic state (Cp^-1 and the equivalent plastic strain).
    bool usesPlasticState() const { return usesPlasticState_; }

private:
    std::vector<Material> materials_;
    std::vector<std::string> names_;
    bool needsEnergy_ = false, anyStrength_ = false, usesPlasticStrain_ = false, usesTemperature_ = false,
         usesPlasticState_ = false, anyViscosity_ = false;
};

}  // namespace mfdyn
