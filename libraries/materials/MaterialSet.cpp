// The materials of a run (MaterialSet.hpp): each material's models as its dictionary names them,
// checked against what the method takes.
#include "materials/MaterialSet.hpp"

#include "core/Dictionary.hpp"
#include "core/Error.hpp"
#include "core/Log.hpp"

namespace mfdyn {

std::vector<std::string> materialNames(const Dictionary& materialProperties) {
    const Dictionary& all = materialProperties.subDict("materials");
    std::vector<std::string> names;
    for (const auto& entry : all.entries()) {
        if (!entry->isDict()) throw all.error(entry->key, "expected a material dictionary");
        names.push_back(entry->key);
    }
    if (names.empty()) throw all.error("", "no materials defined");
    return names;
}

namespace {

constexpr int modelCount = 4;
const char* modelKeys[modelCount] = {"equationOfState", "strength", "constitutiveLaw", "viscosity"};

ModelUse modelUse(const MaterialModels& models, int k) {
    const ModelUse uses[modelCount] = {models.equationOfState, models.strength, models.constitutiveLaw,
                                       models.viscosity};
    return uses[k];
}

// "an equationOfState and optionally a strength": what the method takes, for messages.
std::string takes(const MaterialModels& models) {
    std::string required, optional;
    for (int k = 0; k < modelCount; ++k) {
        const ModelUse use = modelUse(models, k);
        std::string& list = use == ModelUse::required ? required : optional;
        if (use == ModelUse::refused) continue;
        list += (list.empty() ? "" : ", ") + std::string(modelKeys[k]);
    }
    std::string s;
    if (!required.empty()) s = required;
    if (!optional.empty()) s += (s.empty() ? "optionally " : " and optionally ") + optional;
    if (models.equationOfStateOrConstitutiveLaw)
        s += " (an equationOfState or a constitutiveLaw per material)";
    return s;
}

}  // namespace

template <int Dim>
MaterialSet<Dim>::MaterialSet(const Dictionary& materialProperties, const MaterialModels& models)
    : names_(materialNames(materialProperties)) {
    const Dictionary& all = materialProperties.subDict("materials");
    for (const auto& name : names_) {
        const Dictionary& dict = all.subDict(name);
        for (int k = 0; k < modelCount; ++k) {
            const ModelUse use = modelUse(models, k);
            if (use == ModelUse::refused && dict.found(modelKeys[k]))
                throw dict.error(modelKeys[k],
                                 models.method + " takes no " + modelKeys[k] + "; it takes " + takes(models) +
                                     (k == 3 ? " (a viscous fluid, viscosity { type newtonian; mu ...; }, "
                                               "runs in mpmFsi)"
                                             : ""));
            if (use == ModelUse::required && !dict.findDict(modelKeys[k]))
                throw InputError(dict.where(), dict.scope(),
                                 "material '" + name + "' names no " + modelKeys[k] +
                                     " { type ...; }: " + models.method + " takes " + takes(models));
        }
        if (models.equationOfStateOrConstitutiveLaw && !dict.findDict("equationOfState") &&
            !dict.findDict("constitutiveLaw"))
            throw InputError(dict.where(), dict.scope(),
                             "material '" + name +
                                 "' names neither an equationOfState nor a constitutiveLaw: " +
                                 models.method + " takes " + takes(models));

        Material m;
        m.name = name;
        m.dict = &dict;
        std::string line;
        auto add = [&](const std::string& part) { line += (line.empty() ? "" : ", ") + part; };
        if (const Dictionary* eos = dict.findDict("equationOfState")) {
            m.eos = EquationOfState::New(*eos);
            needsEnergy_ = needsEnergy_ || m.eos->needsEnergy();
            add("equationOfState " + m.eos->type());
        }
        if (const Dictionary* strength = dict.findDict("strength")) {
            auto law = Strength<Dim>::New(*strength);
            add("strength " + law->type());
            // A law that carries no deviatoric stress (`none`) is a fluid: no stress field for it.
            if (law->allocatesStress()) {
                anyStrength_ = true;
                usesPlasticStrain_ = usesPlasticStrain_ || law->usesPlasticStrain();
                usesTemperature_ = usesTemperature_ || law->usesTemperature();
                m.strength = std::move(law);
            }
        }
        if (const Dictionary* law = dict.findDict("constitutiveLaw")) {
            m.constitutiveLaw = ConstitutiveLaw::New(*law);
            usesPlasticState_ = usesPlasticState_ || m.constitutiveLaw->usesPlasticState();
            add(m.constitutiveLaw->describe());
        }
        if (const Dictionary* viscosity = dict.findDict("viscosity")) {
            // A viscosity is a fluid's deviator: beside a strength law that carries stress, or a
            // constitutive law, the body would have two deviatoric stresses.
            if (m.strength)
                throw dict.error("viscosity", "material '" + name +
                                                  "' is a fluid given a strength law (strength " +
                                                  m.strength->type() +
                                                  ") as well as a viscosity: a viscosity is a fluid's "
                                                  "deviatoric stress; give an equationOfState with either "
                                                  "a viscosity (a fluid) or a strength (a solid)");
            if (m.constitutiveLaw)
                throw dict.error("viscosity", "material '" + name +
                                                  "' names a viscosity on a constitutiveLaw material: a "
                                                  "viscosity goes with an equationOfState (a fluid), "
                                                  "never with a constitutiveLaw");
            m.viscosity = Viscosity::New(*viscosity);
            anyViscosity_ = true;
            add("viscosity " + m.viscosity->type());
        }
        Log::info("Material " + name + ": " + line);
        materials_.push_back(std::move(m));
    }
}

template <int Dim>
MaterialSet<Dim>::~MaterialSet() = default;
template <int Dim>
MaterialSet<Dim>::MaterialSet(MaterialSet&&) noexcept = default;
template <int Dim>
MaterialSet<Dim>& MaterialSet<Dim>::operator=(MaterialSet&&) noexcept = default;

template class MaterialSet<1>;
template class MaterialSet<2>;
template class MaterialSet<3>;

}  // namespace mfdyn
