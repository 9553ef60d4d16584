// Artificial viscosity for total-Lagrangian SPH (Lee et al. 2016 Remark 6): a viscous stress
// P_vis = (mu_vis/rho0) grad0 p, whose divergence is D(p) = (mu_vis/rho0) L[p] - the JST D2 term
// with eps2_p c_p h = mu_vis/rho0. mu_vis [Pa s] is `viscosity`. Per particle a:
//     D(p)_a = (mu_vis / rho0_a) L[p]_a,   D(J) = 0.
#include "tlSph/ArtificialViscosity.hpp"

#include "core/Parallel.hpp"

namespace mfdyn {

KeywordSchema ArtificialViscosity::keywords() {
    return KeywordSchema(familyName, "artificialViscosity")
        .scalar("viscosity", "Pa s", "mu_vis of the viscous stress (mu_vis/rho0) grad0 p")
        .atLeast(0);
}

ArtificialViscosity::ArtificialViscosity(const Dictionary& dict) {
    viscosity_ = keywords().read(dict).scalar("viscosity");
}

void ArtificialViscosity::evaluate(const Block& b) const {
    if (!b.dissipationP || !b.lapP) return;
    const int d = b.dimension;
    parallelFor(b.size, [&](std::size_t a) {
        const double k = viscosity_ / b.rho0[a];
        for (int i = 0; i < d; ++i) b.dissipationP[a * d + i] = k * b.lapP[a * d + i];
    });
}

std::string ArtificialViscosity::describe() const {
    return "artificialViscosity: mu_vis " + std::to_string(viscosity_) + " Pa s";
}

MFDYN_REGISTER(TlDissipation, ArtificialViscosity, "artificialViscosity",
               "viscous stress (mu_vis/rho0) grad0 p (Lee et al. 2016 Remark 6)");

}  // namespace mfdyn
