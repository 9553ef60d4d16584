// Monaghan-Gingold artificial viscosity (Monaghan & Gingold 1983, J. Comput. Phys. 52:374;
// Monaghan 1992, Annu. Rev. Astron. Astrophys. 30:543, Eq. 4.1), for approaching pairs:
//
//   μ_ij = h̄ v_ij·x_ij/(|x_ij|² + 0.01 h̄²),  Π_ij = (−α c̄ μ_ij + β μ_ij²)/ρ̄,
//   dv_i/dt −= Σ m_j Π_ij ∇̄W,  de_i/dt += ½ Σ m_j Π_ij v_ij·∇̄W,
//
// with Balsara's (1995, J. Comput. Phys. 121:357) switch f_i = |∇·v|/(|∇·v| + |∇×v| + 1e-4 c_i/h_i)
// multiplying Π by ½(f_i+f_j), which removes the viscosity from shear flow. The artificial mass
// flux of the riemann model (Eq. 4.26) combines with it: the elliptical drop of Zisis 2017 §4.5.1
// pairs Monaghan's viscosity with a_ρ = 0.5, b_ρ = 0; it is off unless given.
#include "sph/MonaghanGingoldViscosity.hpp"

namespace mfdyn {

KeywordSchema MonaghanGingoldViscosity::keywords() {
    return KeywordSchema(familyName, "monaghanGingold")
        .scalar("alpha", "-", "linear (bulk) viscosity coefficient")
        .atLeast(0)
        .orDefault(1.0)
        .scalar("beta", "-", "quadratic (von Neumann-Richtmyer) coefficient")
        .atLeast(0)
        .orDefault(2.0)
        .flag("balsara", "Balsara's switch against viscosity in shear flow")
        .orDefault(false)
        .vector("density", "-", "(a_rho b_rho): artificial mass flux on the pressure jump (riemann Eq. 4.26)")
        .atLeast(0)
        .ofLength(2)
        .orDefault(std::vector<double>{0.0, 0.0});
}

MonaghanGingoldViscosity::MonaghanGingoldViscosity(const Dictionary& dict) : Dissipation(dict) {
    const KeywordValues v = keywords().read(dict);
    p_.kind = DissipationParameters::Kind::monaghanGingold;
    p_.alpha = v.scalar("alpha");
    p_.beta = v.scalar("beta");
    p_.balsara = v.flag("balsara");
    p_.arho = v.vector("density")[0];
    p_.brho = v.vector("density")[1];
}

MFDYN_REGISTER(Dissipation, MonaghanGingoldViscosity, "monaghanGingold",
               "alpha/beta artificial viscosity with optional Balsara switch");

}  // namespace mfdyn
