// Hypoelastic deviatoric stress (Libersky, Petschek, Carney, Hipp & Allahdadi 1993, J. Comput.
// Phys. 109:67, Eqs. 5-7; Zisis 2017 Eq. 6.7, doc/methods/sph-impact.md section 5.2):
//
//     dtau/dt = W tau - tau W + 2mu (D - alpha tr(D) I),   D = sym L, W = skew L, L_ab = dv_a/dx_b,
//
// 2mu = 2G (shearFactor 2; the thesis prints G, erratum 8: shearFactor 1 reproduces the print),
// alpha = 1/d (the thesis: no out-of-plane deviator in 2D) or 1/3 (plane strain in 2D, uniaxial
// strain in 1D, with the out-of-plane components implied by tr tau = 0). Note that with alpha =
// 1/d a 1D run has D' = 0 and hence no strength; use `deviator three` there.
//
// Integration: forward Euler, tau <- tau + dt dtau/dt, as in the thesis's leapfrog (step 5). The
// rotation terms keep J2 only to second order per step: |tau|^2 grows by dt^2 |W tau - tau W|^2,
// i.e. O(dt) over a fixed rotation angle; an incrementally objective scheme (Hughes & Winget 1980)
// would remove it and is the natural next option.
//
// Validity: small elastic strains (hypoelasticity is not path-independent for large ones); no yield.
#include "materials/strength/Hookean.hpp"

#include <limits>

namespace mfdyn {

template <int Dim>
KeywordSchema Hookean<Dim>::keywords() {
    return KeywordSchema(Strength<Dim>::familyName, "hookean")
        .scalar("shearModulus", "Pa", "shear modulus G")
        .greaterThan(0)
        .orEnclosing()
        .scalar("shearFactor", "-",
                "factor of G in the Jaumann law: 2 (standard) or 1 (thesis Eq. 6.7 as printed)")
        .atLeast(1)
        .atMost(2)
        .orDefault(2.0)
        .orEnclosing()
        .word("deviator", {"dimension", "three"},
              "trace weight of the deviator: 1/d (the thesis) or 1/3 (plane strain in 2D, uniaxial strain in "
              "1D)")
        .orDefault("dimension")
        .orEnclosing();
}

template <int Dim>
Hookean<Dim>::Hookean(const Dictionary& dict) : Hookean(dict, keywords().read(dict)) {}

template <int Dim>
Hookean<Dim>::Hookean(const Dictionary& dict, const KeywordValues& v) : Strength<Dim>(dict) {
    this->shearModulus_ = v.scalar("shearModulus");
    const double factor = v.scalar("shearFactor");
    if (factor != 1.0 && factor != 2.0)
        throw v.error("shearFactor",
                      "expected 2 (standard) or 1 (thesis Eq. 6.7), found " + this->formatNumber(factor));
    twoMu_ = factor * this->shearModulus_;
    if (v.word("deviator") == "three") {
        this->deviatorWeight_ = 1.0 / 3.0;
        this->impliedComponents_ = 3 - Dim;
    } else {
        this->deviatorWeight_ = 1.0 / Dim;
        this->impliedComponents_ = 0;
    }
}

template <int Dim>
void Hookean<Dim>::update(const Fields& f, double dt) const {
    for (std::size_t i = 0; i < f.size; ++i) {
        const SymmTensor<Dim> rate = jaumannRate(f.tau[i], f.velocityGradient[i]);
        for (int k = 0; k < SymmTensor<Dim>::size; ++k) f.tau[i].c[k] += dt * rate.c[k];
    }
    this->returnToYieldSurface(f, dt);
}

template <int Dim>
void Hookean<Dim>::stressRate(const Fields& f) const {
    for (std::size_t i = 0; i < f.size; ++i) f.tauRate[i] = jaumannRate(f.tau[i], f.velocityGradient[i]);
}

template <int Dim>
void Hookean<Dim>::returnToYieldSurface(const Fields& f, double) const {
    if (f.plasticWorkRate)
        for (std::size_t i = 0; i < f.size; ++i) f.plasticWorkRate[i] = 0.0;
}

template <int Dim>
double Hookean<Dim>::yieldStress(double, double, double) const {
    return std::numeric_limits<double>::infinity();
}

template class Hookean<1>;
template class Hookean<2>;
template class Hookean<3>;

MFDYN_REGISTER_DIM(Strength, Hookean, "hookean",
                   "hypoelastic Jaumann-rate Hooke law, no yield (Libersky 1993)");

}  // namespace mfdyn
