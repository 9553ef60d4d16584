#include "core/Case.hpp"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>

namespace mfdyn {

namespace fs = std::filesystem;

Case::Case(fs::path root) : root_(std::move(root)) {
    // Without std::error_code, a path the process may not look into threw filesystem_error
    // ("Error (internal)"); a file given as the case is not missing, it is the wrong kind of thing.
    std::error_code ec;
    if (fs::is_directory(root_, ec)) return;
    if (fs::exists(root_, ec)) throw InputError("case directory '" + root_.string() + "' is not a directory");
    throw InputError("case directory '" + root_.string() + "' does not exist");
}

namespace {
Dictionary readCaseFile(const fs::path& file) {
    std::error_code ec;
    if (!fs::exists(file, ec)) {
        // ec set: the file is there but cannot be looked at (a link to itself: ELOOP), not missing.
        if (ec) throw InputError("cannot read " + file.string() + ": " + ec.message());
        throw InputError("cannot find " + file.string());
    }
    return Dictionary::read(file);
}
}  // namespace

Dictionary Case::readSystem(const std::string& name) const {
    return readCaseFile(systemFile(name));
}
Dictionary Case::readConstant(const std::string& name) const {
    return readCaseFile(constantFile(name));
}

std::vector<TimeDirectory> Case::timeDirectories() const {
    std::vector<TimeDirectory> times;
    // With error codes: a case directory that cannot be listed (permissions, removed meanwhile)
    // threw filesystem_error, which reached the user as "Error (internal)".
    std::error_code ec;
    fs::directory_iterator it(root_, ec);
    if (ec) throw InputError("cannot list the case directory '" + root_.string() + "': " + ec.message());
    for (; it != fs::directory_iterator(); it.increment(ec)) {
        const fs::directory_entry& item = *it;
        std::error_code kind;
        if (!item.is_directory(kind)) continue;
        const std::string name = item.path().filename().string();
        char* end = nullptr;
        const double value = std::strtod(name.c_str(), &end);
        if (name.empty() || *end != '\0' || !std::isfinite(value)) continue;  // also skips *.tmp-<pid>
        times.push_back({value, name});
    }
    if (ec) throw InputError("cannot list the case directory '" + root_.string() + "': " + ec.message());
    std::sort(times.begin(), times.end(), [](const auto& a, const auto& b) { return a.value < b.value; });
    return times;
}

std::optional<TimeDirectory> Case::latestTime() const {
    auto times = timeDirectories();
    if (times.empty()) return std::nullopt;
    return times.back();
}

std::optional<TimeDirectory> Case::findTime(double value) const {
    for (const auto& t : timeDirectories())
        if (std::abs(t.value - value) <= 1e-12 * std::max(1.0, std::abs(value))) return t;
    return std::nullopt;
}

}  // namespace mfdyn
