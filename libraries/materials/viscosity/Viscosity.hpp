#pragma once
// Viscosity laws: the family `viscosity`, the deviatoric stress of a fluid from its rate of
// deformation. A fluid is an equationOfState (the pressure p) with a viscosity in place of a
// strength law:
//
//     materials
//     {
//         water { equationOfState { type tait; rho0 997.5; B 2e6; gamma 7; }
//                 viscosity { type newtonian; mu 0.01; } }
//     }
//
// sigma = tau_v - p I with tau_v = 2 mu dev D, D = sym L, dev D = D - tr(D)/3 I (Stokes'
// hypothesis: no bulk viscosity). Below 3D the motion is plane strain (D_zz = 0), so the trace is
// the in-plane one and tau_v,zz = -2 mu tr(D)/3 (doc/methods/mpm.md section 1 item 3). The
// viscous work tau_v : D = 2 mu dev D : dev D >= 0 heats the fluid (it enters e).
//
// Only mpmFsi takes a viscosity (materials/MaterialSet.hpp refuses it elsewhere, and on a
// material with a strength law or a constitutive law: a viscosity is a fluid's deviator).
#include "core/Dictionary.hpp"
#include "core/Registry.hpp"

#include <memory>
#include <string>

namespace mfdyn {

class Viscosity {
public:
    static constexpr const char* familyName = "viscosity";
    using Selector = Registry<Viscosity, const Dictionary&>;
    // Out of line, so that a program calling only New links libmfdyn_materials' registrations.
    static std::unique_ptr<Viscosity> New(const Dictionary& dict);

    virtual ~Viscosity() = default;
    Viscosity(const Viscosity&) = delete;
    Viscosity& operator=(const Viscosity&) = delete;

    const std::string& type() const { return type_; }
    // The dynamic (shear) viscosity mu [Pa s] at density rho [kg/m^3] and specific internal
    // energy e [J/kg]; 0 is an inviscid fluid.
    virtual double dynamicViscosity(double rho, double e) const = 0;
    // The largest mu the law gives (for the viscous time-step vote rho dx^2 / (4 mu)).
    virtual double maximumViscosity() const = 0;

protected:
    explicit Viscosity(const Dictionary& dict);

private:
    std::string type_;
};

}  // namespace mfdyn
