#pragma once
// Numerical dissipation of the total-Lagrangian mixed SPH (the family `tlDissipation`), in
// constant/tlSphProperties:
//
//     dissipation { type jst; momentum (0 0.125); jacobian (0 0); }      // (eps2 eps4) per variable
//     dissipation { type artificialViscosity; viscosity 50; }           // mu_vis [Pa s]
//     dissipation { type none; }
//
// jst (Jameson-Schmidt-Turkel; Lee et al. 2016 eqs. 35-38), constant coefficients, no sensor:
//     D(U_a) = eps2_U c_p h L[U]_a - eps4_U c_p h^3 L^2[U]_a,   U in {p, J}, never F or H
// artificialViscosity (Remark 6): P_vis = (mu_vis/rho0) grad0 p, i.e. D(p) = (mu_vis/rho0) L[p].
// L is the corrected Laplacian, h the particle spacing, c_p the largest p-wave speed.
// The terms are evaluated in the solver's loops; a model states its coefficients.
#include "core/KeywordSchema.hpp"
#include "core/Registry.hpp"

#include <memory>
#include <string>

namespace mfdyn {

struct TlDissipationCoefficients {
    double momentum2 = 0, momentum4 = 0;  // eps2_p, eps4_p
    double jacobian2 = 0, jacobian4 = 0;  // eps2_J, eps4_J
    double viscosity = 0;                 // mu_vis [Pa s]
    bool any() const { return momentum2 || momentum4 || jacobian2 || jacobian4 || viscosity; }
    bool needsBiLaplacian() const { return momentum4 || jacobian4; }
};

class TlDissipation {
public:
    static constexpr const char* familyName = "tlDissipation";
    using Selector = Registry<TlDissipation, const Dictionary&>;
    static std::unique_ptr<TlDissipation> New(const Dictionary& dict);

    virtual ~TlDissipation();
    virtual TlDissipationCoefficients coefficients() const = 0;
    virtual std::string describe() const = 0;
};

}  // namespace mfdyn
