#pragma once
// The model families of the material point method (mpmFsi), each selected by a word in
// constant/mpmProperties (doc/methods/mpm.md sections 2 and 7):
//
//     scheme          USL;     // mpmScheme: when the stress is updated (USL | USF | MUSL)
//     velocityUpdate  FLIP;    // velocityUpdate: how particles take the grid's velocity
//                              // (FLIP | PIC | flipPic with `flipFraction 0.99;` | APIC)
//     gridDamping     none;    // gridDamping: none | massProportional with `dampingCoefficient 15;`
//
// A model's own parameters are entries of mpmProperties beside its word, declared in the model's
// keywords(). The models are descriptions the solver's loops read once per step (flags and
// numbers, never a virtual call per particle or node): the transfers themselves are in
// MpmSolver.cpp, where the equations are.
#include "core/Dictionary.hpp"
#include "core/KeywordSchema.hpp"
#include "core/Registry.hpp"

#include <memory>
#include <string>

namespace mfdyn {

// Selects `type` of the family from the word entry `key` of `properties` (default `fallback`);
// an unknown word is an InputError at that entry listing the valid types.
template <class Family>
std::unique_ptr<Family> selectByWord(const Dictionary& properties, const char* key, const char* fallback) {
    const std::string type = properties.found(key) ? properties.get<std::string>(key) : std::string(fallback);
    const RegistryFamily& family = RegistryIndex::global().family(Family::familyName, methodNameOf<Family>());
    if (!family.find(type)) throw properties.error(key, family.unknownTypeMessage(type));
    auto model = Family::Selector::NewOfType(type, properties, properties);
    model->setType(type);
    return model;
}

// mpmScheme: the order of the stress update within a step (Bardenhagen 2002; Nairn 2003;
// Buzzi et al. 2008). USL updates the stress after the grid-to-particle transfer from the grid's
// updated velocity (the thesis), USF before the grid solve from the velocity the particles
// brought, MUSL after re-mapping the updated particle velocities to the grid.
class MpmScheme {
public:
    static constexpr const char* familyName = "mpmScheme";
    using Selector = Registry<MpmScheme, const Dictionary&>;
    virtual ~MpmScheme() = default;
    enum class StressUpdate { last, first, modifiedLast };
    virtual StressUpdate stressUpdate() const = 0;
    const std::string& type() const { return type_; }
    void setType(std::string type) { type_ = std::move(type); }

private:
    std::string type_;
};

// velocityUpdate: v_p^{n+1} = r (v_p^n + dt sum_I N_Ip a_I) + (1 - r) sum_I N_Ip v_I^{n+1}, r the
// FLIP fraction (FLIP 1, PIC 0, flipPic given); APIC (Jiang et al. 2015) is PIC with the affine
// matrix C_p carried by each particle and mapped with its momentum.
class VelocityUpdate {
public:
    static constexpr const char* familyName = "velocityUpdate";
    using Selector = Registry<VelocityUpdate, const Dictionary&>;
    virtual ~VelocityUpdate() = default;
    virtual double flipFraction() const = 0;
    virtual bool affine() const { return false; }
    virtual std::string describe() const { return type_; }
    const std::string& type() const { return type_; }
    void setType(std::string type) { type_ = std::move(type); }

private:
    std::string type_;
};

// gridDamping: the grid force f_d = -alpha_d (mv)_I of note 2.4 (massProportional, alpha_d in
// 1/s, a damping ratio alpha_d / (2 omega) on a mode of angular frequency omega), or none.
class GridDamping {
public:
    static constexpr const char* familyName = "gridDamping";
    using Selector = Registry<GridDamping, const Dictionary&>;
    virtual ~GridDamping() = default;
    virtual double coefficient() const = 0;
    virtual std::string describe() const { return type_; }
    const std::string& type() const { return type_; }
    void setType(std::string type) { type_ = std::move(type); }

private:
    std::string type_;
};

}  // namespace mfdyn
