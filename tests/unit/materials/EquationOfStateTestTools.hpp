#pragma once
// Shared by the equation-of-state tests: building a model as a user does, a sample parameter set
// per registered type, and the isentropic derivative computed numerically, apart from the models'
// analytic sound speeds.
#include "core/Dictionary.hpp"
#include "materials/equationOfState/EquationOfState.hpp"

#include <cmath>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace mfdyn::test {

inline std::unique_ptr<EquationOfState> makeEos(const std::string& text) {
    return EquationOfState::New(Dictionary::parse(text, "test"));
}

struct EosSample {
    std::string type;
    // Every keyword; `required` lists those whose absence must be an error.
    std::vector<std::pair<std::string, std::string>> keywords;
    std::vector<std::string> required;
    double referencePressure;                       // P(rho0, 0) [Pa]
    std::vector<std::pair<double, double>> states;  // (rho, e), away from branch lines
};

inline std::string dictionaryText(const EosSample& s, const std::string& without = "") {
    std::string text = "type " + s.type + ";";
    for (const auto& [k, v] : s.keywords)
        if (k != without) text += " " + k + " " + v + ";";
    return text;
}

// Al2 of Table 6.1 for the Hugoniot models, Tillotson 1962 aluminium (Melosh 1989 Table AII.3).
inline std::vector<EosSample> eosSamples() {
    // Not at rho0 itself: P_H'' jumps there (mieGruneisen), which a central difference sees as an
    // O(h) error.
    const std::vector<std::pair<double, double>> solidStates = {{2785.0 * 1.002, 0.0},
                                                                {2785.0 * 1.05, 1e5},
                                                                {2785.0 * 1.3, 1e6},
                                                                {2785.0 * 0.97, 1e4},
                                                                {2785.0 * 1.6, 5e6}};
    return {
        {"linearEnergy",
         {{"c", "1480"}, {"g", "1000"}, {"rho0", "1000"}, {"p0", "1e5"}},
         {"c", "g", "rho0"},
         1e5,
         {{1000.0, 0.0}, {1100.0, 1e4}, {950.0, 2e3}}},
        {"linearBarotropic",
         {{"rho0", "1000"}, {"c0", "20"}},
         {"rho0", "c0"},
         0.0,
         {{1000.0, 0.0}, {1100.0, 0.0}, {900.0, 5.0}}},
        {"idealGas",
         {{"gamma", "1.4"}, {"rho0", "1.2"}},
         {"gamma"},
         0.0,
         {{1.2, 2.5e5}, {0.125, 2.0}, {10.0, 1e6}}},
        {"stiffenedGas",
         {{"gamma", "4.4"}, {"pRef", "6e8"}, {"rho0", "1000"}},
         {"gamma", "pRef"},
         -4.4 * 6e8,
         {{1000.0, 8e5}, {1000.0, 1e6}, {1200.0, 7e5}}},
        {"tait",
         {{"rho0", "1000"}, {"c0", "1480"}, {"gamma", "7"}},
         {"rho0"},
         0.0,
         {{1000.0, 0.0}, {1010.0, 0.0}, {990.0, 0.0}, {1300.0, 0.0}}},
        {"polytropic",
         {{"K", "2.5"}, {"gamma", "1.6666666666666667"}, {"rho0", "1"}},
         {"K", "gamma"},
         2.5,
         {{1.0, 0.0}, {0.1, 0.0}, {20.0, 0.0}}},
        {"cubicPolynomial",
         {{"rho0", "2785"}, {"c0", "5330"}, {"S0", "1.338"}, {"B0", "2"}},
         {"rho0", "c0", "S0", "B0"},
         0.0,
         solidStates},
        {"mieGruneisen",
         {{"rho0", "2785"}, {"c0", "5330"}, {"s", "1.338"}, {"gamma0", "2"}},
         {"rho0", "c0", "s", "gamma0"},
         0.0,
         solidStates},
        {"tillotson",
         {{"rho0", "2700"},
          {"A", "75.2e9"},
          {"B", "65e9"},
          {"a", "0.5"},
          {"b", "1.63"},
          {"alpha", "5"},
          {"beta", "5"},
          {"E0", "5e6"},
          {"Eiv", "3e6"},
          {"Ecv", "13.9e6"}},
         // alpha, beta, Eiv, Ecv: required with branch full (the default) by the constructor, not
         // the schema (tests/unit/materials/TillotsonTest.cpp).
         {"rho0", "A", "B", "a", "b", "E0"},
         0.0,
         // compressed; cold expanded (e < Eiv); blend; fully expanded (e > Ecv)
         {{2700.0, 0.0},
          {3200.0, 2e6},
          {2700.0 * 0.95, 1e6},
          {2700.0 * 0.9, 8e6},
          {1350.0, 2e7},
          {2500.0, 2e7}}},
    };
}

// Central differences of pressure() in e at constant rho and in rho at constant e, each with its
// round-off bound 4 eps (|P(x+h)| + |P(x-h)|) / (2h), for the tolerance.
struct Difference {
    double value, roundOff;
};
inline Difference energyDifference(const EquationOfState& eos, double rho, double e, double h) {
    const double pPlus = eos.pressure(rho, e + h), pMinus = eos.pressure(rho, e - h);
    return {(pPlus - pMinus) / (2 * h), 4 * 2.2e-16 * (std::abs(pPlus) + std::abs(pMinus)) / (2 * h)};
}
inline Difference densityDifference(const EquationOfState& eos, double rho, double e, double h) {
    const double pPlus = eos.pressure(rho + h, e), pMinus = eos.pressure(rho - h, e);
    return {(pPlus - pMinus) / (2 * h), 4 * 2.2e-16 * (std::abs(pPlus) + std::abs(pMinus)) / (2 * h)};
}

// dP/drho along the isentrope through (rho, e): central difference over rho +- h with e carried
// along de/drho = P/rho^2 by one classical Runge-Kutta step each way. RK4's local error is O(h^5),
// the difference's O(h^2) (relative (h/rho)^2 times rho^2 P'''/P'), round-off eps |P| / h.
inline double isentropicDerivative(const EquationOfState& eos, double rho, double e, double h) {
    auto f = [&](double r, double en) { return eos.pressure(r, en) / (r * r); };
    auto step = [&](double dr) {
        const double k1 = f(rho, e), k2 = f(rho + dr / 2, e + dr / 2 * k1),
                     k3 = f(rho + dr / 2, e + dr / 2 * k2), k4 = f(rho + dr, e + dr * k3);
        return e + dr / 6 * (k1 + 2 * k2 + 2 * k3 + k4);
    };
    return (eos.pressure(rho + h, step(h)) - eos.pressure(rho - h, step(-h))) / (2 * h);
}

}  // namespace mfdyn::test
