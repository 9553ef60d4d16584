// The constitutiveLaw family: elastic constants and keyword handling shared by the laws (see
// ConstitutiveLaw.hpp). Isotropic moduli (e.g. Bonet, Gil & Wood 2016, Nonlinear Solid Mechanics
// for Finite Element Analysis: Statics, section 6.5):
//
//     mu = E / (2 (1 + nu)),   kappa = E / (3 (1 - 2 nu)),   lambda = kappa - 2 mu / 3,
//
// valid for E > 0 and -1 < nu < 1/2 (positive definite strain energy); the p-wave speed of the
// small-strain tangent is c_p = sqrt((lambda + 2 mu) / rho0) = sqrt((kappa + 4 mu / 3) / rho0).
#include "materials/constitutive/ConstitutiveLaw.hpp"

#include <cmath>
#include <sstream>

namespace mfdyn {

namespace {

using materialParameters::holderOf;

const char* const elasticChoices =
    "give either 'youngsModulus' and 'poissonRatio', or 'shearModulus' and 'bulkModulus' (in this "
    "dictionary or the material's)";

}  // namespace

std::unique_ptr<ConstitutiveLaw> ConstitutiveLaw::New(const Dictionary& dict) {
    return Selector::New(dict);
}

ConstitutiveLaw::ConstitutiveLaw(const Dictionary& dict) : ConstitutiveLaw(dict, true) {}

ConstitutiveLaw::ConstitutiveLaw(const Dictionary& dict, bool elasticConstantsRequired)
    : type_(dict.get<std::string>("type")) {
    rho0_ = read(dict, {"rho0", "kg/m^3", "reference density rho0", std::nullopt, 0.0, true});

    const Dictionary* e = holderOf(dict, "youngsModulus");
    const Dictionary* nu = holderOf(dict, "poissonRatio");
    const Dictionary* g = holderOf(dict, "shearModulus");
    const Dictionary* k = holderOf(dict, "bulkModulus");
    const std::string material =
        dict.parent() ? " (law '" + dict.scope() + "', material '" + dict.parent()->scope() + "')"
                      : std::string();
    if (!e && !nu && !g && !k) {
        if (!elasticConstantsRequired) return;
        throw InputError(dict.where(), dict.scope(),
                         "missing elastic constants for constitutiveLaw type '" + type_ + "'" + material +
                             ": " + elasticChoices);
    }
    const bool engineering = e && nu && !g && !k;
    const bool moduli = g && k && !e && !nu;
    if (!engineering && !moduli) {
        std::string found;
        for (const auto& [holder, name] : {std::pair{e, "youngsModulus"}, std::pair{nu, "poissonRatio"},
                                           std::pair{g, "shearModulus"}, std::pair{k, "bulkModulus"}})
            if (holder) found += (found.empty() ? "'" : ", '") + std::string(name) + "'";
        const Dictionary& at = e ? *e : nu ? *nu : g ? *g : *k;
        throw InputError(
            at.where(), at.scope(),
            "inconsistent elastic constants" + material + ": found " + found + "; " + elasticChoices);
    }
    if (engineering) {
        const double youngs =
            read(dict, {"youngsModulus", "Pa", "Young's modulus E", std::nullopt, 0.0, true});
        const double poisson = read(dict, {"poissonRatio", "-", "Poisson's ratio nu (-1 < nu < 1/2)",
                                           std::nullopt, -1.0, true, 0.5, true});
        mu_ = youngs / (2.0 * (1.0 + poisson));
        kappa_ = youngs / (3.0 * (1.0 - 2.0 * poisson));
    } else {
        mu_ = read(dict, {"shearModulus", "Pa", "shear modulus mu", std::nullopt, 0.0, true});
        kappa_ = read(dict, {"bulkModulus", "Pa", "bulk modulus kappa", std::nullopt, 0.0, true});
    }
    elasticGiven_ = true;
}

ConstitutiveLaw::~ConstitutiveLaw() = default;

double ConstitutiveLaw::pWaveSpeed() const {
    return std::sqrt((kappa_ + 4.0 * mu_ / 3.0) / rho0_);
}

std::string ConstitutiveLaw::describe() const {
    std::ostringstream out;
    out << type_ << ": rho0 " << rho0_ << ", mu " << mu_ << ", kappa " << kappa_ << describeParameters();
    return out.str();
}

std::string ConstitutiveLaw::formatNumber(double value) {
    return materialParameters::formatNumber(value);
}

double ConstitutiveLaw::read(const Dictionary& dict, const Keyword& key) {
    return materialParameters::read(dict, key, "constitutiveLaw");
}

std::optional<double> ConstitutiveLaw::readOwn(const Dictionary& dict, const Keyword& key) {
    return materialParameters::readOwn(dict, key);
}

bool ConstitutiveLaw::readSwitch(const Dictionary& dict, const char* key, bool fallback) {
    return materialParameters::readSwitch(dict, key, fallback);
}

}  // namespace mfdyn
