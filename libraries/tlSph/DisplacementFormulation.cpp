// F_a = I + sum_b V_b (u_b - u_a) (x) grad~W_b(X_a),  u = x - X   (Lee et al. 2016 eq. 34).
// With the corrected gradient this equals sum_b V_b (x_b - x_a) (x) grad~W_b(X_a); the u form also
// gives F = I at rest with the uncorrected gradient.
#include "tlSph/DisplacementFormulation.hpp"

namespace mfdyn {

MFDYN_REGISTER(Formulation, DisplacementFormulation, "displacement",
               "displacement-based TL-SPH: F from the positions (Lee et al. 2016 eq. 34), for comparison");

}  // namespace mfdyn
