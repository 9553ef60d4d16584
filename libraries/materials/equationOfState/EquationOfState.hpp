#pragma once
// Equations of state: the family `equationOfState`.
//
// An equation of state gives the pressure P(rho, e) of a material from its density rho [kg/m^3]
// and specific internal energy e [J/kg], P positive in compression (doc/methods/sph-impact.md section 5.1,
// Zisis 2017 section 1.1.3, 5.1-5.3, 6.1), and the squared sound speed
//
//     c^2 = dP/drho|_s = dP/drho|_e + (P/rho^2) dP/de|_rho,
//
// the derivative along an isentrope, on which de = (P/rho^2) drho (first law with ds = 0), and the
// two partial derivatives that the pressure-rate form of the energy equation needs (the FPM solver's
// Dp/Dt = -rho c_e^2 div v + (g/rho) sigma:epsdot, doc/methods/fpm.md section 1, von Nida 2005
// Eq. 1.29):
//
//     g        = dP/de|_rho    [kg/m^3]   energyDerivative(rho, e), analytic in every model;
//     c_e^2    = dP/drho|_e    [m^2/s^2]  densityDerivative(rho, e) = c^2 - P g / rho^2,
//
// the second from the identity above, so that c^2, g and c_e^2 are consistent by construction.
//
// Family contract (checked for every registered type by tests/unit/materials/
// EquationOfStateContractTest.cpp):
//   - pressure(referenceDensity(), 0) is the model's reference pressure (0 for all types except
//     stiffenedGas, -gamma pRef, polytropic, K rho0^gamma, and linearEnergy, p0);
//   - soundSpeedSquared equals the isentropic derivative above, analytically;
//   - energyDerivative equals dP/de|_rho of pressure(), analytically, and densityDerivative
//     (from the identity) dP/drho|_e; a barotropic model's g is 0. Where a tension cut-off
//     (`minimumPressure` of mieGruneisen and tillotson) sets P = pMin, P does not depend on e and
//     g is 0, while c^2 stays the uncut value (the time step must still resolve the material), so
//     densityDerivative returns that uncut c^2 there;
//   - c^2 is returned as computed, also where it is not positive (strong tension, expanded
//     Tillotson states): the model does not clamp or throw, the caller decides (the solver's
//     time-step vote and its state check name the particle).
//   - needsEnergy() is false for barotropic models (P = P(rho)): the solver may then skip the
//     energy equation and pass e = nullptr to evaluate().
//
// Parameters. A model reads its parameters from its own dictionary and, when a keyword is not
// there, from the enclosing one (dict.parent()), so that material constants shared with the
// strength law are written once:
//
//     materials
//     {
//         al2
//         {
//             rho0 2785; c0 5330; s 1.338; gamma0 2.0;   // or #includeEtc "materials/Al2"
//             shearModulus 27.1e9; yieldStress 0.265e9;
//             equationOfState { type mieGruneisen; }
//         }
//     }
//
// An entry in the equationOfState dictionary wins over one in the material. Only one level up is
// searched: a material must not pick up a neighbour's or the file's constants by accident.
//
// Keywords: `type` selects the model; each model declares its own in a keyword schema,
// `static KeywordSchema keywords()` (core/KeywordSchema.hpp), and reads its dictionary through
// it. Parameters marked orEnclosing may be given in the material instead (see above); the schema
// is listed by `-describe equationOfState` and in doc/models/equationOfState/.
//
// Evaluation. pressure() and soundSpeedSquared() are virtual, for set-up, tests and utilities.
// Particle loops call evaluate() once per block: one virtual call per block, the models' loops
// inline their formulas, so a solver pays no virtual call per particle.
#include "core/Dictionary.hpp"
#include "core/Registry.hpp"

#include <cmath>
#include <cstddef>
#include <memory>
#include <optional>
#include <string>
#include <string_view>

namespace mfdyn {

class EquationOfState {
public:
    static constexpr const char* familyName = "equationOfState";
    using Selector = Registry<EquationOfState, const Dictionary&>;
    // Out of line, so that a program calling only New still links (and loads) libmfdyn_materials,
    // whose static registrations fill the table.
    static std::unique_ptr<EquationOfState> New(const Dictionary& dict);

    virtual ~EquationOfState() = default;
    EquationOfState(const EquationOfState&) = delete;
    EquationOfState& operator=(const EquationOfState&) = delete;

    const std::string& type() const { return type_; }

    // P [Pa] at density rho [kg/m^3] and specific internal energy e [J/kg].
    virtual double pressure(double rho, double e) const = 0;
    // c^2 [m^2/s^2] = dP/drho at constant entropy; may be <= 0 in unphysical states (see above).
    virtual double soundSpeedSquared(double rho, double e) const = 0;
    // g [kg/m^3] = dP/de at constant rho; 0 for a barotropic model and where a tension cut-off
    // holds P at pMin (see above).
    virtual double energyDerivative(double rho, double e) const = 0;
    // c_e^2 [m^2/s^2] = dP/drho at constant e, from c^2 = dP/drho|_e + (P/rho^2) dP/de|_rho:
    // c^2 - P g / rho^2 (the uncut c^2 where P is cut, g being 0 there). May be <= 0.
    double densityDerivative(double rho, double e) const {
        const double g = energyDerivative(rho, e);
        const double c2 = soundSpeedSquared(rho, e);
        return g == 0.0 ? c2 : c2 - pressure(rho, e) * g / (rho * rho);
    }
    // False when P depends on rho only.
    virtual bool needsEnergy() const { return true; }
    // rho0 [kg/m^3]: the density at which the material is unstressed (the gases: the optional
    // `rho0`, 0 when not given, since a gas has none).
    double referenceDensity() const { return rho0_; }

    // Block form: p[i] = P(rho[i], e[i]), c[i] = sqrt(c^2(rho[i], e[i])) for i < n (c[i] is NaN
    // where c^2 < 0, so that the solver's NaN check reports the particle). e may be nullptr when
    // needsEnergy() is false. The default loops over the virtual members; models override it with
    // an inlined loop.
    virtual void evaluate(std::size_t n, const double* rho, const double* e, double* p, double* c) const;

protected:
    // Reads `type`; `rho0` is the reference density (0: none).
    EquationOfState(const Dictionary& dict, double rho0 = 0.0);

    // The real parameter `key` from dict or, failing that, dict.parent() (marking the entry read).
    // Throws InputError naming the keyword and both scopes when it is in neither.
    static double parameter(const Dictionary& dict, std::string_view key);
    static std::optional<double> optionalParameter(const Dictionary& dict, std::string_view key);
    static double parameterOrDefault(const Dictionary& dict, std::string_view key, double fallback);
    // As parameter(), also requiring value > 0 (or >= 0 with allowZero) and finite.
    static double positiveParameter(const Dictionary& dict, std::string_view key, bool allowZero = false);
    // `value` of `key`, checked to be finite and > lower; throws parameterError otherwise.
    static double checkAbove(const Dictionary& dict, std::string_view key, double value, double lower);
    // An InputError at `key` in whichever of dict and its parent holds it.
    static InputError parameterError(const Dictionary& dict, std::string_view key,
                                     const std::string& message);

    void setReferenceDensity(double rho0) { rho0_ = rho0; }

    // The loop of a model's evaluate(): Model::state(rho, e, p, c2) is called by its qualified
    // name, so it is bound statically and inlined (no virtual call per particle).
    template <class Model>
    static void evaluateBlock(const Model& model, std::size_t n, const double* rho, const double* e,
                              double* p, double* c) {
        for (std::size_t i = 0; i < n; ++i) {
            double c2;
            model.Model::state(rho[i], e ? e[i] : 0.0, p[i], c2);
            c[i] = std::sqrt(c2);
        }
    }

private:
    std::string type_;
    double rho0_ = 0.0;
};

}  // namespace mfdyn
