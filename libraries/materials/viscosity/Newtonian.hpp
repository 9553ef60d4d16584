#pragma once
// `newtonian`: a constant dynamic viscosity mu, tau_v = 2 mu dev D. Equations in Newtonian.cpp.
//
//     viscosity { type newtonian; mu 1e-3; }
#include "materials/viscosity/Viscosity.hpp"

namespace mfdyn {

class Newtonian final : public Viscosity {
public:
    explicit Newtonian(const Dictionary& dict);
    static KeywordSchema keywords();

    double dynamicViscosity(double, double) const override { return mu_; }
    double maximumViscosity() const override { return mu_; }

private:
    double mu_ = 0.0;
};

}  // namespace mfdyn
