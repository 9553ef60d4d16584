// The dissipation family's shared helper (the models are in their own files).
#include "sph/Dissipation.hpp"

#include <vector>

namespace mfdyn {

void Dissipation::coefficientPair(const KeywordValues& v, const char* name, double& a, double& b) {
    const std::vector<double>& pair = v.vector(name);
    if (pair.size() != 2)
        throw v.error(name, "expected (a b): a coefficient and a signal-velocity factor, found " +
                                std::to_string(pair.size()) + " values");
    a = pair[0];
    b = pair[1];
}

}  // namespace mfdyn
