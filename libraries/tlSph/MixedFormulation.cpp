// Lee, Gil, Greto, Kulasegaram, Bonet (2016), "A new Jameson-Schmidt-Turkel smooth particle
// hydrodynamics algorithm for large strain explicit fast dynamics", CMAME 311: the first-order
// conservation laws (1) in the reduced form (6), evolving
//   dF/dt = grad0(p/rho0),   dH/dt = F x grad0(p/rho0),   dJ/dt = H : grad0(p/rho0).
// {p,F} computes H = cof F and J = det F; {p,F,J} evolves J as well, which is what keeps the
// pressure free of checkerboarding near incompressibility (the paper's 8.6, 8.8, 8.9); {p,F,H,J}
// evolves all four (the polyconvex Mooney-Rivlin law's natural arguments).
#include "tlSph/MixedFormulation.hpp"

namespace mfdyn {

using PFFormulation = MixedFormulation<false, false>;
using PFJFormulation = MixedFormulation<false, true>;
using PFHJFormulation = MixedFormulation<true, true>;

MFDYN_REGISTER(Formulation, PFFormulation, "pF", "mixed {p, F}; H = cof F, J = det F (Lee et al. 2016)");
MFDYN_REGISTER(Formulation, PFJFormulation, "pFJ", "mixed {p, F, J}; H = cof F (near incompressibility)");
MFDYN_REGISTER(Formulation, PFHJFormulation, "pFHJ", "mixed {p, F, H, J} (Lee et al. 2016)");

}  // namespace mfdyn
