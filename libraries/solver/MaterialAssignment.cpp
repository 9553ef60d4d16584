#include "solver/MaterialAssignment.hpp"

#include "core/Error.hpp"

namespace mfdyn {

template <int Dim>
void assignMaterials(ParticleSet<Dim>& particles, const std::vector<std::string>& names,
                     const Dictionary& materialProperties) {
    auto indexOf = [&](const std::string& name) -> std::int64_t {
        for (std::size_t k = 0; k < names.size(); ++k)
            if (names[k] == name) return std::int64_t(k);
        return -1;
    };
    auto valid = [&] {
        std::string s;
        for (const auto& n : names) s += " " + n;
        return s;
    };
    auto& material = particles.integerField("material");
    const auto& fileNames = particles.materialNames;
    const auto& regionNames = particles.regionNames;
    const auto& region = particles.region();
    const bool fromFile = !fileNames.empty();
    const auto& source = fromFile ? fileNames : regionNames;
    std::vector<std::int64_t> map;
    for (const auto& name : source) map.push_back(indexOf(name));
    for (std::size_t i = 0; i < particles.size(); ++i) {
        const std::int64_t id = fromFile ? material[i] : region[i];
        std::int64_t k = (id >= 0 && std::size_t(id) < map.size()) ? map[id] : -1;
        if (k < 0 && names.size() == 1) k = 0;
        if (k < 0) {
            const std::string name =
                (id >= 0 && std::size_t(id) < source.size()) ? source[id] : std::to_string(id);
            throw materialProperties.error("materials",
                                           "particle " + std::to_string(particles.globalId()[i]) +
                                               " has material/region '" + name +
                                               "', which constant/materialProperties does not define; "
                                               "materials:" +
                                               valid());
        }
        material[i] = k;
    }
    particles.materialNames = names;
}

template void assignMaterials<1>(ParticleSet<1>&, const std::vector<std::string>&, const Dictionary&);
template void assignMaterials<2>(ParticleSet<2>&, const std::vector<std::string>&, const Dictionary&);
template void assignMaterials<3>(ParticleSet<3>&, const std::vector<std::string>&, const Dictionary&);

}  // namespace mfdyn
