// Strang's splitting (Strang 1968, SIAM J. Numer. Anal. 5:506; von Nida 2005 eq. 4.5 and its
// outlook, doc/methods/fpm.md §3.1, §5 item 7): for parts A, B, ..., Z in order,
//
//     Phi(t + dt) = A(dt/2) B(dt/2) ... Z(dt) ... B(dt/2) A(dt/2) Phi(t),
//
// symmetric, so the O(dt^2) commutator terms of Lie's splitting cancel: an O(dt^3) local error,
// second order globally when each part is integrated to second order (fpmSolid's parts are
// forward Euler except the exact rotation, so the splitting error alone is what it removes). One
// part alone is that part over dt.
#include "fpm/splitting/StrangSplitting.hpp"

namespace mfdyn::fpm {

KeywordSchema StrangSplitting::keywords() {
    return KeywordSchema(familyName, "strang");
}

StrangSplitting::StrangSplitting(const Dictionary& dict) : Splitting(dict) {
    keywords().read(dict);
}

std::vector<SplitStage> StrangSplitting::stages(const std::vector<Subsystem>& parts) const {
    std::vector<SplitStage> s;
    if (parts.empty()) return s;
    for (std::size_t k = 0; k + 1 < parts.size(); ++k) s.push_back({parts[k], 0.5});
    s.push_back({parts.back(), 1.0});
    for (std::size_t k = parts.size() - 1; k-- > 0;) s.push_back({parts[k], 0.5});
    return s;
}

MFDYN_REGISTER(
    Splitting, StrangSplitting, "strang",
    "Strang splitting: A(dt/2) B(dt/2) C(dt) B(dt/2) A(dt/2), second order (the thesis's outlook)");

}  // namespace mfdyn::fpm
