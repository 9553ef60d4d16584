// Polyconvex nearly incompressible Mooney-Rivlin law in {F, H, J} (Bonet, Gil & Ortigosa 2015,
// "A computational framework for polyconvex large strain elasticity", CMAME 283:689, section 5;
// Lee, Gil, Greto, Kulasegaram & Bonet 2016, "A new Jameson-Schmidt-Turkel smooth particle
// hydrodynamics algorithm for large strain explicit fast dynamics", CMAME 311:71, Eqs. 8-12;
// doc/methods/tl-jst-sph.md section 1):
//
//     W(F, H, J) = zeta (J^-2/3 F:F - 3) + xi (J^-2 (H:H)^3/2 - 3^3/2) + kappa/2 (J - 1)^2,
//     Sigma_F = 2 zeta J^-2/3 F,
//     Sigma_H = 3 xi J^-2 (H:H)^1/2 H,
//     Sigma_J = -2/3 zeta J^-5/3 (F:F) - 2 xi J^-3 (H:H)^3/2 + kappa (J - 1),
//     P       = Sigma_F + Sigma_H x F + Sigma_J H,     (A x B)_iI = e_ijk e_IJK A_jJ B_kK,
//     p       = dU/dJ = kappa (J - 1).
//
// The constants -3 zeta and -3^3/2 xi (not in the papers) make W(I) = 0 and leave every stress
// unchanged. With H = cof F and J = det F, P = dW/dF (dH/dF : Sigma_H = Sigma_H x F, dJ/dF = H);
// with independent H, J (the mixed {p,F,H,J} and {p,F,J} formulations) the supplied H and J enter
// the formula as written. Linearised at F = I: P = lambda tr(e) I + 2 mu e when
// 2 zeta + 3 sqrt(3) xi = mu. Polyconvex for zeta, xi, kappa >= 0 (Bonet et al. 2015), hence
// real wave speeds at any finite strain; J <= 0 is outside its domain (the solver stops first).
#include "materials/constitutive/MooneyRivlin.hpp"

#include <algorithm>
#include <cmath>

namespace mfdyn {

namespace {

const double sqrt3 = std::sqrt(3.0);

}  // namespace

KeywordSchema MooneyRivlin::keywords() {
    return KeywordSchema(familyName, "mooneyRivlin")
        .append(elasticKeywords())
        .scalar("zeta", "Pa",
                "Mooney-Rivlin coefficient zeta of J^-2/3 F:F; zeta, xi or both unless hDominated, with "
                "2 zeta + 3 sqrt(3) xi = mu when the elastic constants are given")
        .atLeast(0)
        .optional()
        .scalar("xi", "Pa", "Mooney-Rivlin coefficient xi of J^-2 (H:H)^3/2")
        .atLeast(0)
        .optional()
        .scalar("kappa", "Pa",
                "bulk modulus kappa of U(J); default: that of the elastic constants, required without them")
        .greaterThan(0)
        .optional()
        .flag("hDominated", "zeta = 0, xi = mu/(3 sqrt 3) (Lee et al. 2016, section 8.7)")
        .orDefault(false)
        .orEnclosing();
}

MooneyRivlin::MooneyRivlin(const Dictionary& dict) : MooneyRivlin(dict, keywords().read(dict)) {}

MooneyRivlin::MooneyRivlin(const Dictionary& dict, const KeywordValues& v) : ConstitutiveLaw(dict, v, false) {
    const auto zeta = v.optionalScalar("zeta");
    const auto xi = v.optionalScalar("xi");
    const auto kappa = v.optionalScalar("kappa");
    const bool hDominated = v.flag("hDominated");
    const double mu = shearModulus();
    const std::string sum = "2 zeta + 3 sqrt(3) xi";

    if (hDominated) {
        if (zeta || xi)
            throw v.error(zeta ? "zeta" : "xi",
                          "hDominated yes sets zeta = 0 and xi = mu/(3 sqrt 3); give "
                          "either hDominated or zeta/xi, not both");
        if (!elasticConstantsGiven())
            throw InputError(dict.where(), dict.scope(),
                             "hDominated yes needs the shear modulus: give either 'youngsModulus' and "
                             "'poissonRatio', or 'shearModulus' and 'bulkModulus' (here or in the material)");
        zeta_ = 0.0;
        xi_ = mu / (3.0 * sqrt3);
    } else if (!zeta && !xi) {
        throw InputError(
            dict.where(), dict.scope(),
            "missing keyword 'zeta' or 'xi' [Pa]: constitutiveLaw type 'mooneyRivlin' needs at least "
            "one of them in its own dictionary (or 'hDominated yes;')");
    } else if (elasticConstantsGiven()) {
        if (zeta && xi) {
            zeta_ = *zeta;
            xi_ = *xi;
            const double given = 2.0 * zeta_ + 3.0 * sqrt3 * xi_;
            if (!(std::abs(given - mu) <= 1e-6 * mu))
                throw v.error("zeta", sum + " = " + formatNumber(given) +
                                          " differs from the shear modulus mu = " + formatNumber(mu) +
                                          " of the elastic constants (relative tolerance 1e-6)");
        } else if (zeta) {
            // A zeta of mu/2 as printed to a few digits leaves xi a rounding below 0: clip.
            zeta_ = *zeta;
            xi_ = std::max(0.0, (mu - 2.0 * zeta_) / (3.0 * sqrt3));
            if (2.0 * zeta_ > mu * (1.0 + 1e-6))
                throw v.error("zeta", "expected zeta <= mu/2 = " + formatNumber(mu / 2) +
                                          " (xi = (mu - 2 zeta)/(3 sqrt 3) >= 0), found " +
                                          formatNumber(zeta_));
        } else {
            xi_ = *xi;
            zeta_ = std::max(0.0, (mu - 3.0 * sqrt3 * xi_) / 2.0);
            if (3.0 * sqrt3 * xi_ > mu * (1.0 + 1e-6))
                throw v.error("xi", "expected xi <= mu/(3 sqrt 3) = " + formatNumber(mu / (3 * sqrt3)) +
                                        " (zeta = (mu - 3 sqrt(3) xi)/2 >= 0), found " + formatNumber(xi_));
        }
    } else {
        zeta_ = zeta.value_or(0.0);
        xi_ = xi.value_or(0.0);
        mu_ = 2.0 * zeta_ + 3.0 * sqrt3 * xi_;
        if (!(mu_ > 0.0)) throw v.error(zeta ? "zeta" : "xi", "expected " + sum + " = mu > 0, found 0");
    }

    if (kappa)
        kappa_ = *kappa;
    else if (!elasticConstantsGiven())
        throw InputError(
            dict.where(), dict.scope(),
            "missing keyword 'kappa': bulk modulus kappa of U(J) [Pa], required by constitutiveLaw "
            "type 'mooneyRivlin' when the material gives no elastic constants");
}

void MooneyRivlin::evaluate(double zeta, double xi, double kappa, const Fields& f) {
    for (std::size_t i = 0; i < f.size; ++i) {
        const Tensor<3>& F = f.F[i];
        const Tensor<3>& H = f.H[i];
        const double J = f.J[i];
        const double ff = F.squaredNorm();
        const double jm23 = 1.0 / std::cbrt(J * J);
        double sigmaJ = -2.0 / 3.0 * zeta * jm23 / J * ff + kappa * (J - 1.0);
        f.P[i] = 2.0 * zeta * jm23 * F;
        double w = zeta * (jm23 * ff - 3.0) + 0.5 * kappa * (J - 1.0) * (J - 1.0);
        if (xi != 0.0) {
            const double hh = H.squaredNorm();
            const double rootHH = std::sqrt(hh);
            const double jm2 = 1.0 / (J * J);
            f.P[i] += tensorCross(3.0 * xi * jm2 * rootHH * H, F);
            sigmaJ -= 2.0 * xi * jm2 / J * hh * rootHH;
            w += xi * (jm2 * hh * rootHH - 3.0 * sqrt3);
        }
        f.P[i] += sigmaJ * H;
        if (f.pressure) f.pressure[i] = kappa * (J - 1.0);
        if (f.energyDensity) f.energyDensity[i] = w;
    }
}

void MooneyRivlin::stress(const Fields& f, bool) const {
    evaluate(zeta_, xi_, kappa_, f);
}

std::string MooneyRivlin::describeParameters() const {
    return ", zeta " + formatNumber(zeta_) + ", xi " + formatNumber(xi_);
}

MFDYN_REGISTER(ConstitutiveLaw, MooneyRivlin, "mooneyRivlin",
               "polyconvex nearly incompressible Mooney-Rivlin in {F,H,J} (Bonet, Gil & Ortigosa 2015)");

}  // namespace mfdyn
