// Compressible neo-Hookean law with a logarithmic volumetric energy (doc/methods/mpm.md section 1,
// law 2; the thesis's eq. 47, after Korelc & Wriggers; Bonet & Wood, Nonlinear Continuum Mechanics
// for FEA, 2nd ed., section 6.4.3):
//
//     W     = mu/2 (tr C - 3) - mu ln J + lambda/2 (ln J)^2,
//     P     = mu (F - F^-T) + lambda ln J F^-T,
//     sigma = mu/J (B - I) + lambda ln J / J I          (sigma_zz = lambda ln J / J in plane strain).
//
// Why two neo-Hookean laws: `neoHookean` (NeoHookean.cpp) is the nearly incompressible form of
// the total-Lagrangian SPH papers, W = mu/2 (J^-2/3 tr C - 3) + kappa/2 (J - 1)^2, with an
// isochoric part and a bulk modulus kappa. This one has no isochoric split and uses lambda, not
// kappa: the two agree at small strain (both are linear elasticity with mu, lambda) and differ at
// finite strain, in tension and compression alike (uniaxial strain F = diag(1.5, 1, 1) with
// E = 1e5, nu = 0.3: P11 = 4.765e4 here, 5.797e4 for neoHookean), and this one's stress grows
// without bound as J -> 0 through ln J. The material point method's examples (hanging block,
// two disks) are computed with this energy, so it is kept under its own name.
//
// Mixed formulations ({p,F,J}, {p,F,H,J}; ConstitutiveLaw.hpp): W is written as
//     W(F, J) = mu/2 (F:F - 3) - mu ln(det F) + lambda/2 (ln J)^2,
// the shear-like part in F alone (det F of F, not the supplied J) and the volumetric part in the
// supplied J:
//     P = mu (F - F^-T) + lambda ln J / J H,     p = dW/dJ = lambda ln J / J,
// which is dW/dF when H = cof F and J = det F. The part in F has a positive volumetric stiffness
// at fixed J (linearised mu (e + e^T), trace 2 mu tr e), so tlSph's {p,F,J} may evaluate the law as
// it is (P(J1) - P(J0) = (p(J1) - p(J0)) H exactly). Putting -mu ln J on the supplied J instead
// would give p(I) = -mu, a pressure that is not zero at rest.
// Validity: any finite strain with det F > 0 and J > 0 (ln of a non-positive number is NaN,
// which the solvers' state checks report).
#include "materials/constitutive/NeoHookeanLogJ.hpp"

#include <Eigen/LU>

#include <cmath>

namespace mfdyn {

KeywordSchema NeoHookeanLogJ::keywords() {
    return KeywordSchema(familyName, "neoHookeanLogJ").append(elasticKeywords());
}

NeoHookeanLogJ::NeoHookeanLogJ(const Dictionary& dict) : ConstitutiveLaw(dict, keywords().read(dict)) {}

void NeoHookeanLogJ::stress(const Fields& f, bool) const {
    const double lambda = lameLambda();
    for (std::size_t i = 0; i < f.size; ++i) {
        const Tensor<3>& F = f.F[i];
        const double detF = F.determinant();
        // F^-T = cof F / det F: the cofactor of F itself (the -mu ln det F term is F's).
        const Tensor<3> invT = cofactor(F) / detF;
        const double J = f.J[i], logJ = std::log(J);
        const double p = lambda * logJ / J;
        f.P[i] = mu_ * (F - invT) + p * f.H[i];
        if (f.pressure) f.pressure[i] = p;
        if (f.energyDensity)
            f.energyDensity[i] =
                0.5 * mu_ * (F.squaredNorm() - 3.0) - mu_ * std::log(detF) + 0.5 * lambda * logJ * logJ;
    }
}

MFDYN_REGISTER(ConstitutiveLaw, NeoHookeanLogJ, "neoHookeanLogJ",
               "compressible neo-Hookean, sigma = mu/J (B - I) + lambda ln J / J I (the MPM thesis's)");

}  // namespace mfdyn
