#include "core/Error.hpp"

#include "core/MessageText.hpp"

namespace mfdyn {

std::string SourceLocation::str() const {
    if (!file) return {};
    std::string s = *file;
    if (line > 0) s += ":" + std::to_string(line) + ":" + std::to_string(column);
    return s;
}

std::string excerpt(std::string_view text, std::size_t maxBytes) {
    std::size_t n = text.size();
    if (n > maxBytes) {
        n = maxBytes;
        // Back off UTF-8 continuation bytes (10xxxxxx) so the cut does not split a character.
        while (n > 0 && (static_cast<unsigned char>(text[n]) & 0xC0) == 0x80) --n;
    }
    std::string s;
    s.reserve(n + 3);
    for (std::size_t i = 0; i < n; ++i) {
        const auto c = static_cast<unsigned char>(text[i]);
        s += c < ' ' || c == 127 ? '?' : char(c);
    }
    if (n < text.size()) s += "...";
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
