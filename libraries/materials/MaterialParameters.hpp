#pragma once
// Scalar, word and switch parameters of a material model (a strength law, a constitutive law),
// looked up in the model's own dictionary and then in its material's (dict.parent()), so that
// constants shared by several sub-models stay with the material:
//
//     materials { copper { rho0 8930; shearModulus 43.3e9; strength { type vonMises; yieldStress 0.4e9; } } }
//
// A missing required keyword, a value outside its bounds or a word outside its choices is an
// InputError at the file and line, naming the keyword, its meaning and unit; a default used is
// echoed through Dictionary::noteDefault.
#include "core/Dictionary.hpp"

#include <limits>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace mfdyn {

struct MaterialKeyword {
    const char* name;
    const char* unit;  // SI; "-" for dimensionless
    const char* meaning;
    std::optional<double> fallback;  // nullopt: required
    double lower = -std::numeric_limits<double>::infinity();
    bool lowerOpen = false;  // lower bound excluded (a modulus > 0)
    double upper = std::numeric_limits<double>::infinity();
    bool upperOpen = false;
};

namespace materialParameters {

// The dictionary holding `key`: the model's own, else the enclosing material's, else null.
const Dictionary* holderOf(const Dictionary& dict, std::string_view key);
// `family` names the model family in the missing-keyword message ("strength", "constitutiveLaw").
double read(const Dictionary& dict, const MaterialKeyword& key, const char* family);
// Only from `dict` itself: nullopt when absent (bounds checked when present).
std::optional<double> readOwn(const Dictionary& dict, const MaterialKeyword& key);
std::string readWord(const Dictionary& dict, const char* key, const std::string& fallback,
                     const std::vector<std::string>& allowed);
bool readSwitch(const Dictionary& dict, const char* key, bool fallback);
// Ten significant digits, for messages and logs.
std::string formatNumber(double value);

}  // namespace materialParameters

}  // namespace mfdyn
