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

const char* const elasticChoices =
    "give either 'youngsModulus' and 'poissonRatio', or 'shearModulus' and 'bulkModulus' (in this "
    "dictionary or the material's)";

}  // namespace

std::unique_ptr<ConstitutiveLaw> ConstitutiveLaw::New(const Dictionary& dict) {
    return Selector::New(dict);
}

KeywordSchema ConstitutiveLaw::elasticKeywords() {
    return KeywordSchema(familyName, "")
        .scalar("rho0", "kg/m^3", "reference density rho0")
        .greaterThan(0)
        .orEnclosing()
        .scalar("youngsModulus", "Pa",
                "Young's modulus E, given with poissonRatio (or shearModulus and bulkModulus instead)")
        .greaterThan(0)
        .optional()
        .orEnclosing()
        .scalar("poissonRatio", "-", "Poisson's ratio nu, given with youngsModulus")
        .greaterThan(-1)
        .lessThan(0.5)
        .optional()
        .orEnclosing()
        .scalar("shearModulus", "Pa",
                "shear modulus mu, given with bulkModulus (or youngsModulus and poissonRatio instead)")
        .greaterThan(0)
        .optional()
        .orEnclosing()
        .scalar("bulkModulus", "Pa", "bulk modulus kappa, given with shearModulus")
        .greaterThan(0)
        .optional()
        .orEnclosing();
}

ConstitutiveLaw::ConstitutiveLaw(const Dictionary& dict, const KeywordValues& v,
                                 bool elasticConstantsRequired)
    : type_(dict.get<std::string>("type")) {
    rho0_ = v.scalar("rho0");

    const auto e = v.optionalScalar("youngsModulus");
    const auto nu = v.optionalScalar("poissonRatio");
    const auto g = v.optionalScalar("shearModulus");
    const auto k = v.optionalScalar("bulkModulus");
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
        for (const auto& [given, name] :
             {std::pair{e.has_value(), "youngsModulus"}, std::pair{nu.has_value(), "poissonRatio"},
              std::pair{g.has_value(), "shearModulus"}, std::pair{k.has_value(), "bulkModulus"}})
            if (given) found += (found.empty() ? "'" : ", '") + std::string(name) + "'";
        // At the dictionary holding the first constant given: the law's own, else the material's.
        const char* first = e ? "youngsModulus" : nu ? "poissonRatio" : g ? "shearModulus" : "bulkModulus";
        const Dictionary& at = dict.found(first) || !dict.parent() ? dict : *dict.parent();
        throw InputError(
            at.where(), at.scope(),
            "inconsistent elastic constants" + material + ": found " + found + "; " + elasticChoices);
    }
    if (engineering) {
        mu_ = *e / (2.0 * (1.0 + *nu));
        kappa_ = *e / (3.0 * (1.0 - 2.0 * *nu));
    } else {
        mu_ = *g;
        kappa_ = *k;
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
    std::ostringstream out;
    out.precision(10);
    out << value;
    return out.str();
}

}  // namespace mfdyn
