// Exact reals of the restart state (ExactReal.hpp).
#include "core/ExactReal.hpp"

#include "core/Dictionary.hpp"
#include "core/MessageText.hpp"

#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace mfdyn {

std::string exactRealText(double x) {
    char s[64];
    std::snprintf(s, sizeof s, "%a", x);
    return s;
}

double readExactReal(const Dictionary& state, const std::string& key) {
    const std::string text = state.get<std::string>(key);
    char* end = nullptr;
    const double x = std::strtod(text.c_str(), &end);
    if (text.empty() || *end != '\0' || !std::isfinite(x))
        throw state.error(key, "expected an exact finite (hexadecimal) real, found '" + excerpt(text) +
                                   "': the state file is damaged; restart from an earlier time");
    return x;
}

}  // namespace mfdyn
