#pragma once
// The von Mises equivalent stress of a Cauchy stress with its out-of-plane component (plane strain
// below 3D: sigma_zz is not zero), the standard
//
//     sigma_vM = sqrt(3/2 s:s),  s = sigma - tr(sigma)/3 I,
//              = sqrt(1/2 [(sxx - syy)^2 + (syy - szz)^2 + (szz - sxx)^2] + 3 (sxy^2 + syz^2 + sxz^2)),
//
// not the thesis code's "VonMisses", which drops the 1/2 and so overweights the normal part by 2
// inside the root (doc/methods/mpm.md section 3, "Code defects"): a uniaxial stress sigma gives
// sigma here, sqrt(2) sigma there.
//
// The particle fields of the material point method (MpmSolver.hpp): `cauchyStress`, a symmetric
// tensor of the run's dimension, and below 3D `cauchyStressZZ` (sigma_zz). In 1D, uniaxial strain
// has sigma_yy = sigma_zz (the two lateral directions are alike). fieldMinMax offers the derived
// field `vonMisesStress` from them (FieldMinMax.cpp).
#include "particles/FieldStore.hpp"

#include <cmath>
#include <string>

namespace mfdyn {

inline double vonMisesStress(double xx, double yy, double zz, double xy, double yz, double xz) {
    const double a = xx - yy, b = yy - zz, c = zz - xx;
    return std::sqrt(0.5 * (a * a + b * b + c * c) + 3.0 * (xy * xy + yz * yz + xz * xz));
}

// Reads the Cauchy stress of particle i from the fields above.
class VonMisesField {
public:
    static constexpr const char* name = "vonMisesStress";
    // The fields it needs, or an Error naming the missing one (`where`: the caller's context).
    VonMisesField(const FieldStore& store, const std::string& where);
    double operator()(std::size_t i) const;

private:
    const FieldBase* sigma_;
    const FieldBase* zz_ = nullptr;
    int dim_;
};

}  // namespace mfdyn
