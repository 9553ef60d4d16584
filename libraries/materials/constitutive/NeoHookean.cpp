// Nearly incompressible neo-Hookean law (Bonet, Gil & Ortigosa 2015, CMAME 283:689, section 5 with
// xi = 0; Lee, Gil, Greto, Kulasegaram & Bonet 2016, CMAME 311:71, section 2; Bonet, Gil & Wood
// 2016, Nonlinear Solid Mechanics for FEA: Statics, section 6.6):
//
//     W(F, J) = mu/2 (J^-2/3 F:F - 3) + kappa/2 (J - 1)^2,
//     P       = mu J^-2/3 F + [-1/3 mu J^-5/3 (F:F) + kappa (J - 1)] H,
//     p       = kappa (J - 1),
//
// which is mooneyRivlin's P = Sigma_F + Sigma_J H with zeta = mu/2, xi = 0 (the same code), and
// with H = cof F, J = det F is P = mu J^-2/3 [F - 1/3 (F:F) F^-T] + kappa (J - 1) cof F. With an
// independent J (the {p,F,J} formulation) J enters J^-2/3, J^-5/3 and kappa (J - 1) as written.
// Validity: any finite strain with J > 0; kappa/mu sets the compressibility (nu = 0.45: 10,
// nu = 0.499: 500).
#include "materials/constitutive/NeoHookean.hpp"

#include "materials/constitutive/MooneyRivlin.hpp"

namespace mfdyn {

KeywordSchema NeoHookean::keywords() {
    return KeywordSchema(familyName, "neoHookean").append(elasticKeywords());
}

NeoHookean::NeoHookean(const Dictionary& dict) : ConstitutiveLaw(dict, keywords().read(dict)) {}

void NeoHookean::stress(const Fields& f, bool) const {
    MooneyRivlin::evaluate(0.5 * mu_, 0.0, kappa_, f);
}

MFDYN_REGISTER(ConstitutiveLaw, NeoHookean, "neoHookean",
               "nearly incompressible neo-Hookean, P = mu J^-2/3 [F - (F:F) F^-T/3] + kappa (J-1) H");

}  // namespace mfdyn
