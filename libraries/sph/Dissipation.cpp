#include "sph/Dissipation.hpp"

#include <vector>

namespace mfdyn {

namespace {

void readPair(const Dictionary& dict, const std::string& key, double& a, double& b, double aDefault, double bDefault) {
    if (!dict.found(key)) {
        a = aDefault, b = bDefault;
        dict.noteDefault(key + " (" + std::to_string(aDefault) + " " + std::to_string(bDefault) + ")");
        return;
    }
    const auto values = dict.get<std::vector<double>>(key);
    if (values.size() != 2) throw dict.error(key, "expected (a b): a coefficient and a signal-velocity factor");
    if (values[0] < 0 || values[1] < 0) throw dict.error(key, "coefficients must be non-negative");
    a = values[0], b = values[1];
}

}  // namespace

class RiemannDissipation final : public Dissipation {
public:
    explicit RiemannDissipation(const Dictionary& dict) : Dissipation(dict) {
        p_.kind = DissipationParameters::Kind::riemann;
        readPair(dict, "velocity", p_.av, p_.bv, 1.0, 2.0);
        readPair(dict, "density", p_.arho, p_.brho, 0.5, 2.0);
        readPair(dict, "energy", p_.ae, p_.be, 0.1, 2.0);
        const std::string signal = dict.getOrDefault<std::string>("signal", "riemann");
        if (signal != "riemann" && signal != "alternative")
            throw dict.error("signal", "'" + signal + "' is not a valid signal; valid choices: riemann (4.22) | alternative (4.24)");
        p_.alternativeSignal = signal == "alternative";
        const std::string pairs = dict.getOrDefault<std::string>("pairs", "approaching");
        if (pairs != "approaching" && pairs != "all")
            throw dict.error("pairs", "'" + pairs + "' is not valid; valid choices: approaching | all");
        p_.allPairs = pairs == "all";
    }
    DissipationParameters parameters() const override { return p_; }

private:
    DissipationParameters p_;
};

class MonaghanGingoldViscosity final : public Dissipation {
public:
    explicit MonaghanGingoldViscosity(const Dictionary& dict) : Dissipation(dict) {
        p_.kind = DissipationParameters::Kind::monaghanGingold;
        p_.alpha = dict.getOrDefault<double>("alpha", 1.0);
        p_.beta = dict.getOrDefault<double>("beta", 2.0);
        p_.balsara = dict.getOrDefault<bool>("balsara", false);
        // The artificial mass flux combines with any viscosity (the elliptical drop of Zisis 2017
        // §4.5.1 pairs Monaghan's viscosity with a_ρ = 0.5, b_ρ = 0); off unless given.
        readPair(dict, "density", p_.arho, p_.brho, 0.0, 0.0);
        if (p_.alpha < 0 || p_.beta < 0) throw dict.error("alpha", "alpha and beta must be non-negative");
    }
    DissipationParameters parameters() const override { return p_; }

private:
    DissipationParameters p_;
};

class NoDissipation final : public Dissipation {
public:
    using Dissipation::Dissipation;
    DissipationParameters parameters() const override { return {}; }
};

MFDYN_REGISTER(Dissipation, RiemannDissipation, "riemann",
               "Riemann-like signal-velocity dissipation on v, rho (mass flux) and e (Zisis 2017, Price 2008)");
MFDYN_REGISTER(Dissipation, MonaghanGingoldViscosity, "monaghanGingold",
               "alpha/beta artificial viscosity with optional Balsara switch");
MFDYN_REGISTER(Dissipation, NoDissipation, "none", "no artificial dissipation");

}  // namespace mfdyn
