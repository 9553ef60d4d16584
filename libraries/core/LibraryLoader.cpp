#include "core/LibraryLoader.hpp"

#include "core/Log.hpp"
#include "core/Registry.hpp"

#include <dlfcn.h>

#include <cstdlib>
#include <set>
#include <sstream>

namespace mfdyn {

namespace fs = std::filesystem;

std::vector<fs::path> LibraryLoader::searchPath(const fs::path& caseDir) {
    std::vector<fs::path> dirs{caseDir, caseDir / "lib"};
    if (const char* env = std::getenv("MFDYN_LIBRARY_PATH")) {
        std::stringstream s(env);
        std::string dir;
        while (std::getline(s, dir, ':'))
            if (!dir.empty()) dirs.emplace_back(dir);
    }
    return dirs;
}

std::string LibraryLoader::loadOne(const std::string& name, const fs::path& caseDir,
                                   const Dictionary& context, const std::string& key) {
    static std::set<std::string> loaded;
    std::vector<std::string> candidates;
    if (fs::path(name).is_absolute()) {
        candidates.push_back(name);
    } else {
        for (const fs::path& dir : searchPath(caseDir)) candidates.push_back((dir / name).string());
        candidates.push_back(name);  // the system loader path
    }

    std::ostringstream tried;
    for (const std::string& candidate : candidates) {
        const bool systemSearch = candidate == name && !fs::path(name).is_absolute();
        if (!systemSearch && !fs::exists(candidate)) {
            tried << "\n    " << candidate << ": no such file";
            continue;
        }
        dlerror();
        if (void* handle = dlopen(candidate.c_str(), RTLD_NOW | RTLD_GLOBAL)) {
            (void)handle;  // kept open for the life of the process: its models are in the registries
            const std::string resolved = systemSearch ? name : fs::canonical(candidate).string();
            if (loaded.insert(resolved).second) Log::info("Loaded library " + resolved);
            RegistryIndex::global().checkConflicts();
            return resolved;
        }
        const char* message = dlerror();
        tried << "\n    " << (systemSearch ? candidate + " (system loader path)" : candidate) << ": "
              << (message ? message : "unknown dlopen error");
    }
    throw context.error(key, "cannot load library '" + name + "'; tried:" + tried.str() +
                                 "\n    (set MFDYN_LIBRARY_PATH or give an absolute path)");
}

std::vector<std::string> LibraryLoader::load(const Dictionary& controlDict, const fs::path& caseDir) {
    std::vector<std::string> loaded;
    if (!controlDict.found("libs")) return loaded;
    for (const std::string& name : controlDict.get<std::vector<std::string>>("libs"))
        loaded.push_back(loadOne(name, caseDir, controlDict, "libs"));
    return loaded;
}

}  // namespace mfdyn
