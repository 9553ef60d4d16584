// Newtonian fluid with Stokes' hypothesis (zero bulk viscosity; Batchelor 1967, An Introduction
// to Fluid Dynamics, Eqs. 3.3.12 and 3.4.4; the MPM fluid of doc/methods/mpm.md section 1 item 3):
//
//     sigma = 2 mu (D - tr(D)/3 I) - p I,    D = (L + L^T)/2,
//
// p from the material's equation of state (Tait for water, p = B ((rho/rho0)^gamma - 1): the
// thesis's kappa is Tait's B). Plane strain below 3D (D_zz = 0): sigma_zz = -(2 mu/3) tr D - p.
// Simple shear v_x = gamma_dot y gives sigma_xy = mu gamma_dot. The viscous dissipation per unit
// volume is 2 mu dev D : dev D. mu = 0 is inviscid.
#include "materials/viscosity/Newtonian.hpp"

namespace mfdyn {

KeywordSchema Newtonian::keywords() {
    return KeywordSchema(familyName, "newtonian")
        .scalar("mu", "Pa s", "dynamic viscosity (1.0e-3 for water at 20 C; 0: inviscid)")
        .atLeast(0)
        .example("1e-3");
}

Newtonian::Newtonian(const Dictionary& dict) : Viscosity(dict) {
    const KeywordValues v = keywords().read(dict);
    mu_ = v.scalar("mu");
}

MFDYN_REGISTER(Viscosity, Newtonian, "newtonian", "Newtonian fluid: tau = 2 mu dev D (Stokes' hypothesis)");

}  // namespace mfdyn
