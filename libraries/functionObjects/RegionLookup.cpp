#include "functionObjects/RegionLookup.hpp"

#include "particles/ParticleSetBase.hpp"

#include <algorithm>

namespace mfdyn {

std::vector<std::string> runRegionNames(const RunContext& context) {
    const auto* set = dynamic_cast<const ParticleSetBase*>(&context.fields());
    return set ? set->regionNames : std::vector<std::string>{};
}

std::int64_t regionIndex(const Dictionary& dict, const std::string& keyword, const std::string& name,
                         const RunContext& context) {
    const std::vector<std::string> names = runRegionNames(context);
    const auto it = std::find(names.begin(), names.end(), name);
    if (it == names.end()) {
        std::string valid;
        for (const auto& n : names) valid += " " + n;
        throw dict.error(keyword, "no region '" + name + "' in this run; regions:" +
                                      (valid.empty() ? std::string(" none") : valid));
    }
    return it - names.begin();
}

}  // namespace mfdyn
