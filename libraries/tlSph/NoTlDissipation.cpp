#include "tlSph/NoTlDissipation.hpp"

namespace mfdyn {

MFDYN_REGISTER(TlDissipation, NoTlDissipation, "none", "no dissipation (unstabilised mixed SPH)");

}  // namespace mfdyn
