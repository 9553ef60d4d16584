// The strength family: conventions and shared helpers (see Strength.hpp). The equivalent stress
// and strain rate are those of von Mises plasticity (Hill 1950, The Mathematical Theory of
// Plasticity, ch. II): sigmaEq = sqrt(3 J2) with J2 = tau:tau/2, epsDotEq = sqrt(2/3 D':D').
#include "materials/strength/Strength.hpp"

#include <cmath>
#include <sstream>

namespace mfdyn {

namespace {

// The dictionary holding `key`: the model's own, else the enclosing material's, else null.
const Dictionary* holderOf(const Dictionary& dict, std::string_view key) {
    if (dict.found(key)) return &dict;
    if (const Dictionary* material = dict.parent(); material && material->found(key)) return material;
    return nullptr;
}

std::string number(double value) {
    std::ostringstream out;
    out.precision(10);
    out << value;
    return out.str();
}

std::string describeBounds(double lower, bool lowerOpen, double upper) {
    std::string s;
    if (std::isfinite(lower)) s += (lowerOpen ? "> " : ">= ") + number(lower);
    if (std::isfinite(upper)) s += (s.empty() ? "<= " : " and <= ") + number(upper);
    return s;
}

}  // namespace

template <int Dim>
std::string Strength<Dim>::formatNumber(double value) {
    return number(value);
}

template <int Dim>
Strength<Dim>::Strength(const Dictionary& dict) : type_(dict.get<std::string>("type")) {}

template <int Dim>
double Strength<Dim>::read(const Dictionary& dict, const Keyword& key) {
    const Dictionary* holder = holderOf(dict, key.name);
    const std::string what = std::string(key.meaning) + " [" + key.unit + "]";
    if (!holder) {
        if (key.fallback) {
            dict.noteDefault((dict.scope().empty() ? std::string() : dict.scope() + "/") + key.name + " " +
                             number(*key.fallback));
            return *key.fallback;
        }
        const std::string scope =
            dict.parent() ? " or in the material dictionary '" + dict.parent()->scope() + "'" : std::string();
        throw InputError(dict.where(), dict.scope(),
                         "missing keyword '" + std::string(key.name) + "': " + what +
                             ", required by strength type '" + dict.get<std::string>("type") +
                             "' (give it in this dictionary" + scope + ")");
    }
    const double value = holder->get<double>(key.name);
    const bool below = key.lowerOpen ? !(value > key.lower) : !(value >= key.lower);
    if (below || !(value <= key.upper) || !std::isfinite(value))
        throw holder->error(key.name, "expected " + what + " " +
                                          describeBounds(key.lower, key.lowerOpen, key.upper) + ", found " +
                                          number(value));
    return value;
}

template <int Dim>
std::string Strength<Dim>::readWord(const Dictionary& dict, const char* key, const std::string& fallback,
                                    const std::vector<std::string>& allowed) {
    const Dictionary* holder = holderOf(dict, key);
    if (!holder) {
        dict.noteDefault((dict.scope().empty() ? std::string() : dict.scope() + "/") + key + " " + fallback);
        return fallback;
    }
    const auto value = holder->get<std::string>(key);
    for (const auto& a : allowed)
        if (value == a) return value;
    std::string list;
    for (const auto& a : allowed) list += (list.empty() ? "" : " | ") + a;
    throw holder->error(key, "expected one of " + list + ", found '" + value + "'");
}

template <int Dim>
bool Strength<Dim>::readSwitch(const Dictionary& dict, const char* key, bool fallback) {
    const Dictionary* holder = holderOf(dict, key);
    if (!holder) {
        dict.noteDefault((dict.scope().empty() ? std::string() : dict.scope() + "/") + key +
                         (fallback ? " yes" : " no"));
        return fallback;
    }
    return holder->get<bool>(key);
}

template <int Dim>
double Strength<Dim>::equivalentStress(const SymmTensor<Dim>& tau) const {
    double ss = 0.0, trace = 0.0;
    for (int i = 0; i < Dim; ++i) {
        ss += tau(i, i) * tau(i, i);
        trace += tau(i, i);
        for (int j = i + 1; j < Dim; ++j) ss += 2.0 * tau(i, j) * tau(i, j);
    }
    // Each of the k implied normal components is -trace/k: together trace^2/k.
    if (impliedComponents_ > 0) ss += trace * trace / impliedComponents_;
    return std::sqrt(1.5 * ss);
}

template <int Dim>
double Strength<Dim>::equivalentStrainRate(const Tensor<Dim>& velocityGradient) const {
    const Tensor<Dim> d = 0.5 * (velocityGradient + velocityGradient.transpose());
    const double trace = d.trace();
    Tensor<Dim> dev = d;
    dev.diagonal().array() -= deviatorWeight_ * trace;
    double dd = dev.squaredNorm();
    // Out of the plane D = 0, so each implied component of D' is -alpha tr D.
    if (impliedComponents_ > 0)
        dd += impliedComponents_ * (deviatorWeight_ * trace) * (deviatorWeight_ * trace);
    return std::sqrt(2.0 / 3.0 * dd);
}

template class Strength<1>;
template class Strength<2>;
template class Strength<3>;

}  // namespace mfdyn
