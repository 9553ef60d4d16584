#pragma once
// Quoting input in messages, for the dictionary reader and the keyword schemas (core only; kept
// out of Error.hpp so that no other library recompiles for it).
#include <cstddef>
#include <string>
#include <string_view>

namespace mfdyn {

// At most `maxBytes` of `text`, for quoting input in a message: cut at a UTF-8 character boundary
// and marked "...", control bytes shown as '?'. A message quotes what the user wrote so they can
// find it, never a whole file (a word can run to the end of a file that is not a dictionary, such
// as /etc/passwd) nor terminal escape sequences. Defined in Error.cpp.
std::string excerpt(std::string_view text, std::size_t maxBytes = 60);

}  // namespace mfdyn
