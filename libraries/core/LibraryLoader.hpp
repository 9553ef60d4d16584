#pragma once
// Loads the user model libraries named in controlDict's `libs ("libmyModels.so" ...);` before
// any model is selected. Their static registrations (MFDYN_REGISTER) make the new types
// selectable by name. A library that cannot be loaded is fatal: the error names the entry's
// file:line:column, every path tried and the loader's message for each.
#include "core/Dictionary.hpp"

#include <filesystem>
#include <string>
#include <vector>

namespace mfdyn {

class LibraryLoader {
public:
    // Search order for a relative name: the case directory, <case>/lib, each directory of
    // $MFDYN_LIBRARY_PATH (colon-separated), then the system loader path (plain dlopen).
    static std::vector<std::filesystem::path> searchPath(const std::filesystem::path& caseDir);

    // Loads every library of `libs` in `controlDict` (if present). Returns the paths loaded.
    static std::vector<std::string> load(const Dictionary& controlDict, const std::filesystem::path& caseDir);

    // Loads one library; `where` locates the error.
    static std::string loadOne(const std::string& name, const std::filesystem::path& caseDir,
                               const Dictionary& context, const std::string& key);
};

}  // namespace mfdyn
