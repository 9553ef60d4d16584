// Lie's splitting (von Nida 2005 §4.1, §4.3; doc/methods/fpm.md §3.1): with the parts' flows
// phi_S, phi_H, phi_R,
//
//     Phi(t + dt) = phi_R(dt) phi_H(dt) phi_S(dt) Phi(t),
//
// an O(dt^2) local error from the parts' commutators, first order globally. The thesis uses it
// "deliberately", as the simplest (§4.3).
#include "fpm/splitting/LieSplitting.hpp"

namespace mfdyn::fpm {

KeywordSchema LieSplitting::keywords() {
    return KeywordSchema(familyName, "lie");
}

LieSplitting::LieSplitting(const Dictionary& dict) : Splitting(dict) {
    keywords().read(dict);
}

std::vector<SplitStage> LieSplitting::stages(const std::vector<Subsystem>& parts) const {
    std::vector<SplitStage> s;
    for (Subsystem p : parts) s.push_back({p, 1.0});
    return s;
}

MFDYN_REGISTER(Splitting, LieSplitting, "lie",
               "Lie splitting: shear, Euler, rotation parts once over dt each (the thesis's; first order)");

}  // namespace mfdyn::fpm
