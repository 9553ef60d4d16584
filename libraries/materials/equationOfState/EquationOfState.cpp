#include "materials/equationOfState/EquationOfState.hpp"

#include <cmath>
#include <sstream>

namespace mfdyn {

namespace {

// The dictionary that holds `key`: the model's own, else its parent, else nullptr. peek() first so
// that a parent is not recorded as having been asked for a key the model's dictionary has.
const Dictionary* holder(const Dictionary& dict, std::string_view key) {
    if (dict.peek(key)) return &dict;
    dict.noteAsked(key);
    if (const Dictionary* up = dict.parent(); up && up->peek(key)) return up;
    return nullptr;
}

std::string formatNumber(double x) {
    std::ostringstream s;
    s.precision(10);
    s << x;
    return s.str();
}

}  // namespace

std::unique_ptr<EquationOfState> EquationOfState::New(const Dictionary& dict) {
    return Selector::New(dict);
}

EquationOfState::EquationOfState(const Dictionary& dict, double rho0)
    : type_(dict.get<std::string>("type")), rho0_(rho0) {}

std::optional<double> EquationOfState::optionalParameter(const Dictionary& dict, std::string_view key) {
    if (const Dictionary* d = holder(dict, key)) return d->get<double>(key);
    return std::nullopt;
}

double EquationOfState::parameter(const Dictionary& dict, std::string_view key) {
    if (auto value = optionalParameter(dict, key)) return *value;
    std::string message =
        "missing keyword '" + std::string(key) + "' (a real number), looked for in '" + dict.scope() + "'";
    if (const Dictionary* up = dict.parent()) message += " and in the enclosing '" + up->scope() + "'";
    throw InputError(dict.where(), dict.scope(), message);
}

double EquationOfState::parameterOrDefault(const Dictionary& dict, std::string_view key, double fallback) {
    if (auto value = optionalParameter(dict, key)) return *value;
    dict.noteDefault((dict.scope().empty() ? std::string() : dict.scope() + "/") + std::string(key) + " " +
                     formatNumber(fallback));
    return fallback;
}

double EquationOfState::positiveParameter(const Dictionary& dict, std::string_view key, bool allowZero) {
    const double value = parameter(dict, key);
    if (!std::isfinite(value) || value < 0.0 || (!allowZero && value == 0.0))
        throw parameterError(dict, key,
                             std::string("expected a ") + (allowZero ? "non-negative" : "positive") +
                                 " real number, found " + formatNumber(value));
    return value;
}

double EquationOfState::checkAbove(const Dictionary& dict, std::string_view key, double value, double lower) {
    if (!std::isfinite(value) || !(value > lower))
        throw parameterError(
            dict, key,
            "expected a real number greater than " + formatNumber(lower) + ", found " + formatNumber(value));
    return value;
}

InputError EquationOfState::parameterError(const Dictionary& dict, std::string_view key,
                                           const std::string& message) {
    const Dictionary* d = holder(dict, key);
    return (d ? *d : dict).error(key, message);
}

void EquationOfState::evaluate(std::size_t n, const double* rho, const double* e, double* p,
                               double* c) const {
    for (std::size_t i = 0; i < n; ++i) {
        const double ei = e ? e[i] : 0.0;
        p[i] = pressure(rho[i], ei);
        c[i] = std::sqrt(soundSpeedSquared(rho[i], ei));
    }
}

}  // namespace mfdyn
