#pragma once
// Time directories of a case (<case>/<timeName>/particles.vtp plus the caller's restart files),
// written so that a run killed at any moment leaves either the previous state or the new one,
// never half of a time: everything goes into <case>/<timeName>.tmp-<pid>/ first, which is
// renamed into place when complete. rename(2) within one file system is atomic, so readers
// (restart, ParaView, listTimeDirectories) see the directory whole or not at all.
//
// Files are not fsync'ed: the guarantee is against the process dying, not against power loss,
// for which the cost of syncing every write would be paid on every run.
//
// Under mpirun (Communicator::distributed()) each rank holds only its own particles, and a time
// is written in pieces: rank 0 makes the temporary directory, every rank writes its owned
// particles into it as particles_<rank>.vtp, rank 0 adds particles.pvtp (the index of the
// pieces, VtpWriter.hpp) and the extra files, and renames the directory into place. The same
// atomicity holds: the pieces appear together or not at all. A failure on any rank fails the
// write on every rank (core/RankZero.hpp), and no rank returns before the directory is in place.
// readTimeParticles (TimeDirectoryReader.hpp) reads either form, on any number of ranks.
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

// The name of the particle file in each time directory written by one process.
inline constexpr const char* particleFileName = "particles.vtp";
// The index of the pieces in a time directory written by several ranks, and rank r's piece.
inline constexpr const char* particleIndexFileName = "particles.pvtp";
std::string particlePieceFileName(int rank);
// The file that opens a time this run writes (particles.pvd's entry): particleFileName on one
// process, particleIndexFileName under mpirun.
const char* writtenParticleFileName();

// Writes <caseDir>/<timeName>/particles.vtp (with `time`, by default the value of timeName)
// and the extra files, atomically; an existing <timeName> is replaced. Returns the directory.
// Distributed: collective; the pieces and their index instead of particles.vtp (above), the
// extra files rank 0's (the state is the same on every rank), and each rank's `pieceFiles` its
// own (names that differ between ranks: grid_<rank>.vti); on one process the piece files are
// written as the extra files are.
std::filesystem::path writeTimeDirectory(const std::filesystem::path& caseDir, const std::string& timeName,
                                         const ParticleSetBase& particles,
                                         const std::vector<ExtraFile>& extraFiles = {},
                                         std::optional<double> time = std::nullopt,
                                         const std::vector<ExtraFile>& pieceFiles = {});

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

// Removes the temporaries that killed runs left in caseDir, and only those: the names the
// functions above produce, <time>.tmp-<pid> and <time>.old.tmp-<pid> (time directories) and
// particles.pvd.tmp-<pid>, whose <pid> is no live process (kill(pid, 0) fails with ESRCH) or is
// this process (a dead earlier one had our pid: call this before writing). Anything else with
// ".tmp-" in its name is the user's and is left alone. A run killed between the two renames of
// writeDirectoryAtomically left a complete <time>.tmp-<pid> and the old <time>.old.tmp-<pid> but
// no <time>: the new directory is put in place instead of being removed. Returns how many
// temporaries were removed or put in place.
std::size_t removeStaleTemporaries(const std::filesystem::path& caseDir);

// Moves the time directories `timeNames` of caseDir into a new caseDir/abandoned.<N>/ (the
// smallest N >= 1 not in use), where listTimeDirectories and Case::timeDirectories no longer see
// them, and returns that directory. For a fresh start: the later times of an earlier run would
// otherwise be taken up by startFrom latestTime although they no longer follow from the start.
std::filesystem::path moveAsideTimeDirectories(const std::filesystem::path& caseDir,
                                               const std::vector<std::string>& timeNames);

}  // namespace mfdyn
