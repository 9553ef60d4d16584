// Artificial viscosity for total-Lagrangian SPH (Lee et al. 2016 Remark 6): a viscous stress
// P_vis = (mu_vis/rho0) grad0 p, whose divergence is D(p) = (mu_vis/rho0) L[p] - the JST D2 term
// with eps2_p c_p h = mu_vis/rho0. mu_vis [Pa s] is `viscosity`.
#include "tlSph/ArtificialViscosity.hpp"

namespace mfdyn {

KeywordSchema ArtificialViscosity::keywords() {
    return KeywordSchema(familyName, "artificialViscosity")
        .scalar("viscosity", "Pa s", "mu_vis of the viscous stress (mu_vis/rho0) grad0 p")
        .atLeast(0);
}

ArtificialViscosity::ArtificialViscosity(const Dictionary& dict) {
    c_.viscosity = keywords().read(dict).scalar("viscosity");
}

std::string ArtificialViscosity::describe() const {
    return "artificialViscosity: mu_vis " + std::to_string(c_.viscosity) + " Pa s";
}

MFDYN_REGISTER(TlDissipation, ArtificialViscosity, "artificialViscosity",
               "viscous stress (mu_vis/rho0) grad0 p (Lee et al. 2016 Remark 6)");

}  // namespace mfdyn
