#include "sph/DensityScheme.hpp"

namespace mfdyn {

DensityScheme::DensityScheme(const Dictionary& dict) {
    const std::string form = dict.getOrDefault<std::string>("form", "continuity");
    if (form != "continuity" && form != "summation")
        throw dict.error("form", "'" + form + "' is not a valid form; valid choices: continuity | summation");
    summation_ = form == "summation";
    gradH_ = dict.getOrDefault<bool>("gradH", true);
}

DensityScheme::~DensityScheme() = default;

}  // namespace mfdyn
