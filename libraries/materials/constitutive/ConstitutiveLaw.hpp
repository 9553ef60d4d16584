#pragma once
// Constitutive laws for total-Lagrangian solids: the family `constitutiveLaw`, the first
// Piola-Kirchhoff stress P of a deformation gradient F (doc/methods/tl-jst-sph.md section 1; Bonet, Gil &
// Ortigosa 2015, CMAME 283:689; Lee, Gil, Greto, Kulasegaram & Bonet 2016, "A new Jameson-Schmidt-
// Turkel smooth particle hydrodynamics algorithm for large strain explicit fast dynamics", CMAME
// 311:71).
//
// Conventions, fixed for every model:
//   - always 3x3: a plane-strain 2D caller embeds F with F33 = 1 (and F13 = F23 = F31 = F32 = 0);
//   - the mixed formulations evolve H = cof F and J = det F as independent fields ({p,F,H,J},
//     {p,F,J}); a caller that does not evolve them passes cof F and det F. A law uses the
//     supplied H and J wherever W(F,H,J) depends on them, so that P = Sigma_F + Sigma_H x F +
//     Sigma_J H reduces to dW/dF when H = cof F and J = det F;
//   - pressure p = dU/dJ = kappa (J - 1) for the finite-strain laws, kappa tr(F - I) for
//     linearElastic; energyDensity W is per unit reference volume, W(I) = 0.
//
// Keywords: each law declares them once in `static KeywordSchema keywords()` (core/
// KeywordSchema.hpp), appending elasticKeywords() (rho0 and the four elastic constants, shared by
// every law), and reads its dictionary through it; `-describe constitutiveLaw` and
// doc/models/constitutiveLaw/ list them. rho0 and the elastic constants may be given in the law's
// dictionary or in the enclosing material dictionary (orEnclosing), as in the strength family:
//
//     materials { rubber { rho0 1100; youngsModulus 17e6; poissonRatio 0.45;
//                          constitutiveLaw { type neoHookean; } } }
//
// Exactly one pair of elastic constants is given, youngsModulus and poissonRatio (E, nu) or
// shearModulus and bulkModulus (mu, kappa), with mu = E/(2(1+nu)), kappa = E/(3(1-2nu)),
// lambda = kappa - 2mu/3.
//
// Laws with history (usesPlasticState()) keep the inverse plastic right Cauchy-Green tensor
// Cp^-1 (initialised to I) and the equivalent plastic strain per particle; stress(fields, false)
// only reads them (a Runge-Kutta stage), stress(fields, true) advances them (end of a step).
#include "core/Dictionary.hpp"
#include "core/KeywordSchema.hpp"
#include "core/Registry.hpp"
#include "core/Tensor.hpp"

#include <cstddef>
#include <limits>
#include <memory>
#include <string>

namespace mfdyn {

// Tensor cross product (A x B)_iI = e_ijk e_IJK A_jJ B_kK (Bonet, Gil & Ortigosa 2015, Eq. 7):
// commutative, bilinear, cof F = 1/2 F x F and (F x F):F = 6 det F.
inline Tensor<3> tensorCross(const Tensor<3>& a, const Tensor<3>& b) {
    Tensor<3> c;
    for (int i = 0; i < 3; ++i) {
        const int j = (i + 1) % 3, k = (i + 2) % 3;
        for (int I = 0; I < 3; ++I) {
            const int J = (I + 1) % 3, K = (I + 2) % 3;
            c(i, I) = a(j, J) * b(k, K) - a(j, K) * b(k, J) - a(k, J) * b(j, K) + a(k, K) * b(j, J);
        }
    }
    return c;
}

// cof F = det(F) F^-T, without the division (exact for singular F too).
inline Tensor<3> cofactor(const Tensor<3>& f) {
    return 0.5 * tensorCross(f, f);
}

class ConstitutiveLaw {
public:
    static constexpr const char* familyName = "constitutiveLaw";
    using Selector = Registry<ConstitutiveLaw, const Dictionary&>;
    static std::unique_ptr<ConstitutiveLaw> New(const Dictionary& dict);

    // rho0 and the elastic constants (see the header comment): the keywords every law's
    // keywords() appends.
    static KeywordSchema elasticKeywords();

    virtual ~ConstitutiveLaw();
    ConstitutiveLaw(const ConstitutiveLaw&) = delete;
    ConstitutiveLaw& operator=(const ConstitutiveLaw&) = delete;

    // One block of particles; arrays have `size` entries.
    struct Fields {
        std::size_t size = 0;
        const Tensor<3>* F = nullptr;           // deformation gradient
        const Tensor<3>* H = nullptr;           // cofactor (independent in {p,F,H,J}, else cof F); never null
        const double* J = nullptr;              // Jacobian (independent in {p,F,J}, else det F); never null
        Tensor<3>* P = nullptr;                 // out: first Piola-Kirchhoff stress [Pa]
        double* pressure = nullptr;             // out, optional: p = dU/dJ [Pa]
        double* energyDensity = nullptr;        // out, optional: W per reference volume [J/m^3]
        SymmTensor<3>* plasticState = nullptr;  // in/out when usesPlasticState(): Cp^-1 (start: I)
        double* plasticStrain = nullptr;        // in/out when usesPlasticState(): equivalent eps_p
        // out, optional, with usesPlasticState(): what the return to the yield surface removed from W
        // per reference volume, the trial state's W less the returned one's [J/m^3] (0 when elastic)
        double* plasticDissipation = nullptr;
    };

    // P (and pressure, energy when non-null) for every particle of the block. With updateState
    // false the plastic state is read, never written; with true it is advanced to the state that
    // goes with F. Per particle, own data only: disjoint blocks may run in parallel.
    virtual void stress(const Fields& fields, bool updateState) const = 0;
    virtual bool usesPlasticState() const { return false; }

    const std::string& type() const { return type_; }
    double referenceDensity() const { return rho0_; }
    double shearModulus() const { return mu_; }
    double bulkModulus() const { return kappa_; }
    double lameLambda() const { return kappa_ - 2.0 * mu_ / 3.0; }
    // Small-strain p-wave speed sqrt((kappa + 4 mu/3)/rho0), the CFL speed of tlSph.
    double pWaveSpeed() const;
    // One line for the log: "neoHookean: rho0 1100, mu 5.86207e+06, kappa 5.66667e+07".
    std::string describe() const;

protected:
    // Reads rho0 and the elastic constants from the values read through the law's schema (which
    // appends elasticKeywords()) and checks that exactly one pair of constants is given. With
    // elasticConstantsRequired false (mooneyRivlin, which can derive them from its own parameters),
    // mu and kappa stay NaN when none of the four keywords is given, and the derived class sets them.
    ConstitutiveLaw(const Dictionary& dict, const KeywordValues& values,
                    bool elasticConstantsRequired = true);

    // Ten significant digits, for messages and describeParameters().
    static std::string formatNumber(double value);
    // Model parameters beyond rho0, mu, kappa for describe(): ", yieldStress 2.5e+08".
    virtual std::string describeParameters() const { return {}; }

    bool elasticConstantsGiven() const { return elasticGiven_; }

    double rho0_ = 0.0;
    double mu_ = std::numeric_limits<double>::quiet_NaN();
    double kappa_ = std::numeric_limits<double>::quiet_NaN();

private:
    std::string type_;
    bool elasticGiven_ = false;
};

}  // namespace mfdyn
