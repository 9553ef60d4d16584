#include "core/Error.hpp"

namespace mfdyn {

std::string SourceLocation::str() const {
    if (!file) return {};
    std::string s = *file;
    if (line > 0) s += ":" + std::to_string(line) + ":" + std::to_string(column);
    return s;
}

namespace {
std::string compose(const SourceLocation& where, const std::string& scope, const std::string& message) {
    std::string s;
    if (where.file) s += where.str() + ": ";
    if (!scope.empty()) s += "in '" + scope + "': ";
    return s + message;
}
}  // namespace

InputError::InputError(const SourceLocation& where, const std::string& scope, const std::string& message)
    : Error(compose(where, scope, message)) {}

}  // namespace mfdyn
