// No dissipation: the mixed {p, F, ...} equations without the JST terms (Lee et al. 2016 §3.3):
// the central scheme keeps its zero-energy (hourglass) modes and rings at shocks, so this is for
// tests of the unstabilised scheme and of what the JST terms buy, not for production runs.
#include "tlSph/NoTlDissipation.hpp"

namespace mfdyn {

MFDYN_REGISTER(TlDissipation, NoTlDissipation, "none", "no dissipation (unstabilised mixed SPH)");

}  // namespace mfdyn
