// -time / -latestTime: see TimeSelection.hpp.
#include "core/TimeSelection.hpp"

#include "core/Error.hpp"

#include <algorithm>
#include <cmath>
#include <exception>

namespace mfdyn {

std::vector<std::size_t> selectTimes(const Arguments& args, const std::vector<double>& values,
                                     const std::vector<std::string>& names, double tolerance,
                                     const std::string& what) {
    if (args.has("time") && args.has("latestTime")) throw InputError("give -time or -latestTime, not both");
    std::vector<std::size_t> chosen;
    if (values.empty()) return chosen;
    if (args.has("latestTime")) return {values.size() - 1};
    const auto spec = args.find("time");
    if (!spec) {
        for (std::size_t k = 0; k < values.size(); ++k) chosen.push_back(k);
        return chosen;
    }
    const auto number = [&](const std::string& text, double fallback) {
        if (text.empty()) return fallback;
        std::size_t used = 0;
        double v = 0;
        try {
            v = std::stod(text, &used);
        } catch (const std::exception&) {
            used = 0;
        }
        if (used != text.size()) throw InputError("-time '" + *spec + "': '" + text + "' is not a number");
        return v;
    };
    // relative to the larger magnitude, and absolute near 0 (0.1:0.3 takes 0.30000000000000004)
    const auto within = [&](double t, double target) {
        return std::abs(t - target) <= tolerance * std::max({1.0, std::abs(t), std::abs(target)});
    };
    if (const auto colon = spec->find(':'); colon != std::string::npos) {
        const double lo = number(spec->substr(0, colon), -HUGE_VAL),
                     hi = number(spec->substr(colon + 1), HUGE_VAL);
        for (std::size_t k = 0; k < values.size(); ++k)
            if ((values[k] >= lo || within(values[k], lo)) && (values[k] <= hi || within(values[k], hi)))
                chosen.push_back(k);
    } else {
        const double target = number(*spec, 0.0);
        for (std::size_t k = 0; k < values.size(); ++k)
            if (within(values[k], target)) chosen.push_back(k);
    }
    if (chosen.empty()) {
        std::string have;
        for (const auto& n : names) have += " " + n;
        throw InputError("-time " + *spec + " matches no time " + what + "; there are:" + have);
    }
    return chosen;
}

}  // namespace mfdyn
