#include "materials/MaterialParameters.hpp"

#include "core/Error.hpp"

#include <cmath>
#include <sstream>

namespace mfdyn::materialParameters {

namespace {

std::string describeBounds(const MaterialKeyword& key) {
    std::string s;
    if (std::isfinite(key.lower)) s += (key.lowerOpen ? "> " : ">= ") + formatNumber(key.lower);
    if (std::isfinite(key.upper))
        s += (s.empty() ? "" : " and ") + std::string(key.upperOpen ? "< " : "<= ") + formatNumber(key.upper);
    return s;
}

std::string scopeOf(const Dictionary& dict, const char* key) {
    return (dict.scope().empty() ? std::string() : dict.scope() + "/") + key;
}

}  // namespace

std::string formatNumber(double value) {
    std::ostringstream out;
    out.precision(10);
    out << value;
    return out.str();
}

const Dictionary* holderOf(const Dictionary& dict, std::string_view key) {
    if (dict.found(key)) return &dict;
    if (const Dictionary* material = dict.parent(); material && material->found(key)) return material;
    return nullptr;
}

double read(const Dictionary& dict, const MaterialKeyword& key, const char* family) {
    const Dictionary* holder = holderOf(dict, key.name);
    if (!holder) {
        if (key.fallback) {
            dict.noteDefault(scopeOf(dict, key.name) + " " + formatNumber(*key.fallback));
            return *key.fallback;
        }
        const std::string scope =
            dict.parent() ? " or in the material dictionary '" + dict.parent()->scope() + "'" : std::string();
        throw InputError(dict.where(), dict.scope(),
                         "missing keyword '" + std::string(key.name) + "': " + key.meaning + " [" + key.unit +
                             "], required by " + family + " type '" + dict.get<std::string>("type") +
                             "' (give it in this dictionary" + scope + ")");
    }
    return *readOwn(*holder, key);
}

std::optional<double> readOwn(const Dictionary& dict, const MaterialKeyword& key) {
    if (!dict.found(key.name)) return std::nullopt;
    const double value = dict.get<double>(key.name);
    const bool below = key.lowerOpen ? !(value > key.lower) : !(value >= key.lower);
    const bool above = key.upperOpen ? !(value < key.upper) : !(value <= key.upper);
    if (below || above || !std::isfinite(value))
        throw dict.error(key.name, "expected " + std::string(key.meaning) + " [" + key.unit + "] " +
                                       describeBounds(key) + ", found " + formatNumber(value));
    return value;
}

std::string readWord(const Dictionary& dict, const char* key, const std::string& fallback,
                     const std::vector<std::string>& allowed) {
    const Dictionary* holder = holderOf(dict, key);
    if (!holder) {
        dict.noteDefault(scopeOf(dict, key) + " " + fallback);
        return fallback;
    }
    const auto value = holder->get<std::string>(key);
    for (const auto& a : allowed)
        if (value == a) return value;
    std::string list;
    for (const auto& a : allowed) list += (list.empty() ? "" : " | ") + a;
    throw holder->error(key, "expected one of " + list + ", found '" + value + "'");
}

bool readSwitch(const Dictionary& dict, const char* key, bool fallback) {
    const Dictionary* holder = holderOf(dict, key);
    if (!holder) {
        dict.noteDefault(scopeOf(dict, key) + (fallback ? " yes" : " no"));
        return fallback;
    }
    return holder->get<bool>(key);
}

}  // namespace mfdyn::materialParameters
