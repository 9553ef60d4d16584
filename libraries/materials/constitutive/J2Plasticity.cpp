// Multiplicative finite-strain J2 plasticity with linear isotropic hardening (Simo 1992,
// "Algorithms for static and dynamic multiplicative plasticity that preserve the classical return
// mapping schemes of the infinitesimal theory", CMAME 99:61; Simo & Hughes 1998, Computational
// Inelasticity, Box 9.1; de Souza Neto, Peric & Owen 2008, ch. 14). Per particle, from the stored
// Cp^-1 (inverse plastic right Cauchy-Green tensor) and eps_p:
//
//     Fiso        = (det F)^-1/3 F,            b_trial = Fiso Cp^-1 Fiso^T   (b_e_bar, det 1),
//     s_trial     = mu dev(b_trial),           f = |s_trial| - sqrt(2/3) (sigma_Y0 + H eps_p),
//     if f > 0:   mu_bar = mu tr(b_trial)/3,   dgamma = f / (2 mu_bar (1 + H/(3 mu_bar))),
//                 s = s_trial - 2 mu_bar dgamma n,   n = s_trial/|s_trial|,
//                 eps_p <- eps_p + sqrt(2/3) dgamma,
//                 b_e_bar = s/mu + a I,  a the root near tr(b_trial)/3 of det(s/mu + a I) = 1,
//                 Cp^-1 <- Fiso^-1 b_e_bar Fiso^-T,
//     p = kappa (J - 1),   P = s F^-T + p H,
//     W = mu/2 (tr b_e_bar - 3) + kappa/2 (J - 1)^2   (the elastic stored energy).
//
// Choices. (1) The trace of the updated b_e_bar: Simo & Hughes (Box 9.1, step 5) keep
// tr(b_trial)/3, which leaves det b_e_bar = 1 + O(dgamma^2), so det Cp^-1 drifts from 1; we solve
// the cubic a^3 - (D:D/2) a + det D - 1 = 0 (D = s/mu) by Newton from tr(b_trial)/3 instead
// (Simo 1992, section 3.3, the volume-preserving correction), so plastic flow is exactly
// isochoric, det Cp^-1 = 1 to rounding. The stress s is the same either way. (2) The volumetric
// response uses the supplied J and the supplied cofactor H (the mixed {p,F,H,J} / {p,F,J}
// formulations), the isochoric one det F of the supplied F: P = s F^-T + p H reduces to Simo's
// tau F^-T, tau = J p I + s, when J = det F and H = cof F. In the elastic range (f <= 0) with
// Cp^-1 = I the law is neoHookean.
//
// Validity: rate-independent, isothermal; the return is exact for perfect plasticity and linear
// hardening along the radial direction (the consistency condition holds exactly at the end of the
// step: sqrt(3/2)|s| = sigma_Y0 + H eps_p). Elastic strains are measured by b_e_bar (neo-Hookean
// deviator), not logarithmically, so a large elastic shear differs from Hencky models.
#include "materials/constitutive/J2Plasticity.hpp"

#include <Eigen/LU>

#include <cmath>
#include <stdexcept>

namespace mfdyn {

namespace {

const double sqrtTwoThirds = std::sqrt(2.0 / 3.0);

// The root near `start` of det(D + a I) = 1 for a deviatoric D: a^3 - (D:D/2) a + det D - 1 = 0.
double isochoricTrace(const Tensor<3>& d, double start) {
    const double half = 0.5 * d.squaredNorm();
    const double c = d.determinant() - 1.0;
    double a = start;
    for (int it = 0; it < 50; ++it) {
        const double g = (a * a - half) * a + c;
        const double step = g / (3.0 * a * a - half);
        a -= step;
        if (std::abs(step) <= 1e-16 * std::abs(a)) break;
    }
    return a;
}

}  // namespace

KeywordSchema J2Plasticity::keywords() {
    return KeywordSchema(familyName, "j2Plasticity")
        .append(elasticKeywords())
        .scalar("yieldStress", "Pa", "initial yield stress sigma_Y0")
        .greaterThan(0)
        .orEnclosing()
        .scalar("hardeningModulus", "Pa",
                "linear isotropic hardening modulus H, slope of sigma_Y against eps_p")
        .atLeast(0)
        .orDefault(0.0)
        .orEnclosing();
}

J2Plasticity::J2Plasticity(const Dictionary& dict) : J2Plasticity(dict, keywords().read(dict)) {}

J2Plasticity::J2Plasticity(const Dictionary& dict, const KeywordValues& v)
    : ConstitutiveLaw(dict, v), yield0_(v.scalar("yieldStress")), hardening_(v.scalar("hardeningModulus")) {}

void J2Plasticity::stress(const Fields& f, bool updateState) const {
    if (f.size > 0 && (!f.plasticState || !f.plasticStrain))
        throw std::invalid_argument("j2Plasticity needs the plasticState and plasticStrain fields");
    const Tensor<3> identity = Tensor<3>::Identity();
    for (std::size_t i = 0; i < f.size; ++i) {
        const Tensor<3>& F = f.F[i];
        const double detF = F.determinant();
        const Tensor<3> fIso = F / std::cbrt(detF);
        const Tensor<3> trial = fIso * f.plasticState[i].full() * fIso.transpose();
        const double trTrial = trial.trace();
        Tensor<3> s = mu_ * (trial - trTrial / 3.0 * identity);
        const double norm = s.norm();
        const double epsP = f.plasticStrain[i];
        const double excess = norm - sqrtTwoThirds * (yield0_ + hardening_ * epsP);
        double trB = trTrial, dissipation = 0.0;
        if (excess > 0.0) {
            const double muBar = mu_ * trTrial / 3.0;
            const double dGamma = excess / (2.0 * muBar * (1.0 + hardening_ / (3.0 * muBar)));
            s *= 1.0 - 2.0 * muBar * dGamma / norm;
            // The flow's dissipation, the returned Kirchhoff deviator times the plastic increment
            // (Simo 1992, CMAME 99, the J2 return's D = |s| dgamma); W_trial - W exceeds it by
            // mu dgamma^2, which is not small where one step carries much plastic strain.
            dissipation = (norm - 2.0 * muBar * dGamma) * dGamma;
            const Tensor<3> d = s / mu_;
            const double a = isochoricTrace(d, trTrial / 3.0);
            trB = 3.0 * a;
            if (updateState) {
                const Tensor<3> fIsoInv = fIso.inverse();
                const Tensor<3> b = d + a * identity;
                f.plasticState[i] = SymmTensor<3>::fromFull(fIsoInv * b * fIsoInv.transpose());
                f.plasticStrain[i] = epsP + sqrtTwoThirds * dGamma;
            }
        }
        const double J = f.J[i];
        const double p = kappa_ * (J - 1.0);
        f.P[i] = s * F.inverse().transpose() + p * f.H[i];
        if (f.pressure) f.pressure[i] = p;
        if (f.energyDensity)
            f.energyDensity[i] = 0.5 * mu_ * (trB - 3.0) + 0.5 * kappa_ * (J - 1.0) * (J - 1.0);
        if (f.plasticDissipation) f.plasticDissipation[i] = dissipation;
    }
}

std::string J2Plasticity::describeParameters() const {
    return ", yieldStress " + formatNumber(yield0_) + ", hardeningModulus " + formatNumber(hardening_);
}

MFDYN_REGISTER(ConstitutiveLaw, J2Plasticity, "j2Plasticity",
               "multiplicative finite-strain J2 plasticity, linear isotropic hardening (Simo 1992)");

}  // namespace mfdyn
