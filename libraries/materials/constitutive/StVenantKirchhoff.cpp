// St Venant-Kirchhoff hyperelasticity, the linear stress-strain law in the Green-Lagrange strain
// (doc/methods/mpm.md section 1, law 1; the thesis's eq. 44-46):
//
//     E = 1/2 (F^T F - I),
//     S = lambda tr(E) I + 2 mu E,             P = F S,       sigma = P F^T / J = F S F^T / J,
//     W = lambda/2 (tr E)^2 + mu E:E           (P = dW/dF),
//     p = kappa tr(E) = tr(S)/3                (kappa (J - 1) linearised).
//
// In plane strain (F33 = 1) sigma_zz = lambda tr(E) / J. W is a function of F alone, so H and J are
// not used: the law is the same in every mixed formulation, as linearElastic (tlSph's {p,F,J}
// check, TlSphSolver.cpp, finds P independent of the supplied J and evaluates it as it is; its
// evolved J then carries no stress). The pressure is the Lagrangian mean stress tr(S)/3 rather
// than tr(sigma)/3 so that it is finite for every F (also det F <= 0, where StVK still has a
// stress).
// Validity: moderate strains. In compression the law softens: in 1D (nu = 0) P = E f (f^2 - 1)/2
// has its extreme -E/(3 sqrt 3) = -0.19 E at the stretch f = 1/sqrt(3) and falls back to 0 as
// f -> 0, so a strongly compressed StVK body collapses (the thesis's section 8.2.1); use
// neoHookeanLogJ or neoHookean for large strain.
#include "materials/constitutive/StVenantKirchhoff.hpp"

namespace mfdyn {

KeywordSchema StVenantKirchhoff::keywords() {
    return KeywordSchema(familyName, "stVenantKirchhoff").append(elasticKeywords());
}

StVenantKirchhoff::StVenantKirchhoff(const Dictionary& dict) : ConstitutiveLaw(dict, keywords().read(dict)) {}

void StVenantKirchhoff::stress(const Fields& f, bool) const {
    const double lambda = lameLambda();
    const Tensor<3> identity = Tensor<3>::Identity();
    for (std::size_t i = 0; i < f.size; ++i) {
        const Tensor<3>& F = f.F[i];
        const Tensor<3> E = 0.5 * (F.transpose() * F - identity);
        const double trace = E.trace();
        const Tensor<3> S = lambda * trace * identity + 2.0 * mu_ * E;
        f.P[i] = F * S;
        if (f.pressure) f.pressure[i] = kappa_ * trace;
        if (f.energyDensity) f.energyDensity[i] = 0.5 * lambda * trace * trace + mu_ * E.squaredNorm();
    }
}

MFDYN_REGISTER(ConstitutiveLaw, StVenantKirchhoff, "stVenantKirchhoff",
               "St Venant-Kirchhoff, S = lambda tr(E) I + 2 mu E, P = F S (soft in compression)");

}  // namespace mfdyn
