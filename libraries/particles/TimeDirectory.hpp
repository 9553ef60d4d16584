#pragma once
// Time directories of a case (<case>/<timeName>/particles.vtp plus the caller's restart files),
// written so that a run killed at any moment leaves either the previous state or the new one,
// never half of a time: everything goes into <case>/<timeName>.tmp-<pid>/ first, which is
// renamed into place when complete. rename(2) within one file system is atomic, so readers
// (restart, ParaView, listTimeDirectories) see the directory whole or not at all.
//
// Files are not fsync'ed: the guarantee is against the process dying, not against power loss,
// for which the cost of syncing every write would be paid on every run.
#include "particles/ParticleSetBase.hpp"

#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace mfdyn {

// (file name, contents) of a small file written next to particles.vtp (the solver's `state`).
using ExtraFile = std::pair<std::string, std::string>;

// The name of the particle file in each time directory.
inline constexpr const char* particleFileName = "particles.vtp";

// Writes <caseDir>/<timeName>/particles.vtp (with `time`, by default the value of timeName)
// and the extra files, atomically; an existing <timeName> is replaced. Returns the directory.
std::filesystem::path writeTimeDirectory(const std::filesystem::path& caseDir, const std::string& timeName,
                                         const ParticleSetBase& particles,
                                         const std::vector<ExtraFile>& extraFiles = {},
                                         std::optional<double> time = std::nullopt);

// The primitive beneath: `fill` writes into an empty temporary directory, which then replaces
// `target`. If `fill` throws, the temporary directory is removed, `target` is left as it was and
// the exception propagates.
void writeDirectoryAtomically(const std::filesystem::path& target,
                              const std::function<void(const std::filesystem::path& tmpDir)>& fill);

// Writes `contents` to `file` through <file>.tmp-<pid> and a rename.
void writeFileAtomically(const std::filesystem::path& file, const std::string& contents);

// Numeric directory names in caseDir ("0", "0.001", "1e-05"), as (value, name) sorted by
// value. Temporaries (*.tmp-*) and anything else that does not parse whole as a number are
// skipped.
std::vector<std::pair<double, std::string>> listTimeDirectories(const std::filesystem::path& caseDir);

// Removes <caseDir>/<timeName> (purgeWrite). Returns false when it did not exist.
bool removeTimeDirectory(const std::filesystem::path& caseDir, const std::string& timeName);

// Removes *.tmp-<pid> directories and files left in caseDir by killed runs. Returns how many.
std::size_t removeStaleTemporaries(const std::filesystem::path& caseDir);

}  // namespace mfdyn
