#include "particles/TimeDirectory.hpp"

#include "core/Case.hpp"

#include "core/Communicator.hpp"
#include "core/Error.hpp"
#include "core/RankZero.hpp"
#include "particles/VtpWriter.hpp"

#include <signal.h>
#include <unistd.h>
#include <algorithm>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <iterator>

namespace fs = std::filesystem;

namespace mfdyn {

namespace {

std::string tmpSuffix() {
    return ".tmp-" + std::to_string(::getpid());
}

// A name that parses whole as a finite number.
bool parseTime(const std::string& name, double& value) {
    if (name.empty()) return false;
    const char* end = name.data() + name.size();
    auto [ptr, ec] = std::from_chars(name.data(), end, value);
    return ec == std::errc() && ptr == end && std::isfinite(value);
}

void renameOrThrow(const fs::path& from, const fs::path& to) {
    std::error_code ec;
    fs::rename(from, to, ec);
    if (ec) throw Error("cannot rename '" + from.string() + "' to '" + to.string() + "': " + ec.message());
}

// An empty <target>.tmp-<pid> to fill.
fs::path freshTemporary(const fs::path& target) {
    const fs::path tmp = target.string() + tmpSuffix();
    std::error_code ec;
    fs::remove_all(tmp, ec);  // a leftover of this pid, from a previous attempt
    if (!fs::create_directories(tmp, ec) && ec)
        throw Error("cannot create directory '" + tmp.string() + "': " + ec.message());
    return tmp;
}

// The complete `tmp` replaces `target`; if that fails, `target` is as it was.
void putInPlace(const fs::path& tmp, const fs::path& target) {
    // rename(2) will not replace a non-empty directory, so the old one is moved aside first;
    // between the two renames the complete old state still exists under the aside name.
    std::error_code ec;
    const fs::path old = target.string() + ".old" + tmpSuffix();
    const bool replacing = fs::exists(target);
    if (replacing) {
        fs::remove_all(old, ec);
        renameOrThrow(target, old);
    }
    try {
        renameOrThrow(tmp, target);
    } catch (...) {
        if (replacing) fs::rename(old, target, ec);
        fs::remove_all(tmp, ec);
        throw;
    }
    if (replacing) fs::remove_all(old, ec);
}

// The time written into the particle file: `time`, or the value of the directory's name.
double timeValue(const std::string& timeName, std::optional<double> time) {
    double value = 0.0;
    if (!time && !parseTime(timeName, value))
        throw Error("time directory name '" + timeName + "' is not a number and no time was given");
    return time ? *time : value;
}

// Extra files are plain names, and none is a particle file: the reader takes particles.vtp
// before particles.pvtp, so an extra file of either name would replace the particles read back.
void checkExtraFileNames(const std::vector<ExtraFile>& extraFiles, const std::string& timeName) {
    for (const auto& [name, contents] : extraFiles) {
        bool particleFile = name == particleFileName || name == particleIndexFileName;
        for (int r = 0; r < Communicator::size() && !particleFile; ++r)
            particleFile = name == particlePieceFileName(r);
        if (name.empty() || name.find('/') != std::string::npos || particleFile || name == "." ||
            name == "..")
            throw Error("extra file name '" + name + "' in time directory '" + timeName +
                        "' is not a plain name");
    }
}

void writeExtraFiles(const fs::path& dir, const std::vector<ExtraFile>& extraFiles) {
    for (const auto& [name, contents] : extraFiles) {
        std::FILE* out = std::fopen((dir / name).c_str(), "wb");
        if (!out) throw Error("cannot write '" + (dir / name).string() + "': " + std::strerror(errno));
        bool bad = std::fwrite(contents.data(), 1, contents.size(), out) != contents.size();
        bad = std::fclose(out) != 0 || bad;
        if (bad) throw Error("cannot write '" + (dir / name).string() + "': " + std::strerror(errno));
    }
}

std::string joined(const std::vector<std::string>& lines) {
    std::string text;
    for (const auto& line : lines) text += (text.empty() ? "" : "\n") + line;
    return text;
}

std::vector<std::string> splitLines(const std::string& text) {
    std::vector<std::string> lines;
    if (text.empty()) return lines;
    std::size_t begin = 0;
    for (std::size_t end = text.find('\n'); end != std::string::npos; end = text.find('\n', begin)) {
        lines.push_back(text.substr(begin, end - begin));
        begin = end + 1;
    }
    lines.push_back(text.substr(begin));
    return lines;
}

// Pieces that disagree in their fields cannot be read back as one set (TimeDirectoryReader), so
// they are refused before anything is written. Every rank sees every rank's list and reaches the
// same verdict: all throw together, with the same words.
void checkRanksHaveTheSameFields(const ParticleSetBase& particles, const std::string& timeName) {
    // Sorted: the order the fields were made in may differ between ranks; the reader matches names.
    std::vector<std::string> mine = pointDataAttributes(particles);
    std::sort(mine.begin(), mine.end());
    const std::string text = joined(mine);
    const auto all = Communicator::allGatherVariable(std::vector<char>(text.begin(), text.end()));
    const std::string first(all[0].begin(), all[0].end());
    for (std::size_t r = 1; r < all.size(); ++r) {
        const std::string theirs(all[r].begin(), all[r].end());
        if (theirs == first) continue;
        const auto a = splitLines(first), b = splitLines(theirs);
        std::vector<std::string> onlyZero, onlyThem;
        std::set_difference(a.begin(), a.end(), b.begin(), b.end(), std::back_inserter(onlyZero));
        std::set_difference(b.begin(), b.end(), a.begin(), a.end(), std::back_inserter(onlyThem));
        throw Error("cannot write time " + timeName + ": the ranks' particles have different fields, so " +
                    "the pieces could not be read back as one set; rank 0 alone has [" + joined(onlyZero) +
                    "], rank " + std::to_string(r) + " alone has [" + joined(onlyThem) + "]");
    }
}

std::string broadcastText(std::string text, int root) {
    std::uint64_t length = text.size();
    Communicator::broadcast(&length, sizeof length, root);
    text.resize(length);
    Communicator::broadcast(text.data(), length, root);
    return text;
}

fs::path writePieces(const fs::path& target, const std::string& timeName, const ParticleSetBase& particles,
                     const std::vector<ExtraFile>& extraFiles, std::optional<double> time,
                     const std::vector<ExtraFile>& pieceFiles) {
    const int rank = Communicator::rank();
    double value = 0.0;
    std::exception_ptr failure;
    try {
        value = timeValue(timeName, time);
        checkExtraFileNames(extraFiles, timeName);
        checkExtraFileNames(pieceFiles, timeName);
    } catch (...) {
        failure = std::current_exception();
    }
    shareFailure(failure);
    checkRanksHaveTheSameFields(particles, timeName);
    // Ids are never reused after a restart from the pieces, whichever rank removed the highest.
    std::vector<std::int64_t> nextIds(std::size_t(Communicator::size()));
    const std::int64_t mine = particles.nextGlobalId();
    Communicator::allGather(&mine, sizeof mine, nextIds.data());
    const std::int64_t nextGlobalId = *std::max_element(nextIds.begin(), nextIds.end());

    fs::path tmp;
    onRankZero([&] { tmp = freshTemporary(target); });
    tmp = broadcastText(tmp.string(), 0);
    failure = nullptr;
    try {
        writeVtp(tmp / particlePieceFileName(rank), particles, value, nextGlobalId);
        writeExtraFiles(tmp, pieceFiles);
    } catch (...) {
        failure = std::current_exception();
    }
    try {
        shareFailure(failure);  // also the barrier: every piece is complete after it
    } catch (...) {
        std::error_code ec;
        if (rank == 0) fs::remove_all(tmp, ec);
        throw;
    }
    onRankZero([&] {
        try {
            std::vector<std::string> pieces;
            for (int r = 0; r < Communicator::size(); ++r) pieces.push_back(particlePieceFileName(r));
            writePvtp(tmp / particleIndexFileName, particles, pieces);
            writeExtraFiles(tmp, extraFiles);
        } catch (...) {
            std::error_code ec;
            fs::remove_all(tmp, ec);
            throw;
        }
        putInPlace(tmp, target);
    });  // no rank goes on before the directory is in place
    return target;
}

}  // namespace

std::string particlePieceFileName(int rank) {
    return "particles_" + std::to_string(rank) + ".vtp";
}

const char* writtenParticleFileName() {
    return Communicator::distributed() ? particleIndexFileName : particleFileName;
}

void writeDirectoryAtomically(const fs::path& target, const std::function<void(const fs::path&)>& fill) {
    const fs::path tmp = freshTemporary(target);
    try {
        fill(tmp);
    } catch (...) {
        std::error_code ec;
        fs::remove_all(tmp, ec);
        throw;
    }
    putInPlace(tmp, target);
}

void writeFileAtomically(const fs::path& file, const std::string& contents) {
    const fs::path tmp = file.string() + tmpSuffix();
    std::FILE* out = std::fopen(tmp.c_str(), "wb");
    if (!out) throw Error("cannot write '" + tmp.string() + "': " + std::strerror(errno));
    bool bad = std::fwrite(contents.data(), 1, contents.size(), out) != contents.size();
    bad = std::fclose(out) != 0 || bad;
    if (bad) {
        std::error_code ec;
        fs::remove(tmp, ec);
        throw Error("cannot write '" + tmp.string() + "': " + std::strerror(errno));
    }
    renameOrThrow(tmp, file);
}

fs::path writeTimeDirectory(const fs::path& caseDir, const std::string& timeName,
                            const ParticleSetBase& particles, const std::vector<ExtraFile>& extraFiles,
                            std::optional<double> time, const std::vector<ExtraFile>& pieceFiles) {
    const fs::path target = caseDir / timeName;
    if (Communicator::distributed())
        return writePieces(target, timeName, particles, extraFiles, time, pieceFiles);
    const double value = timeValue(timeName, time);
    checkExtraFileNames(extraFiles, timeName);
    checkExtraFileNames(pieceFiles, timeName);
    writeDirectoryAtomically(target, [&](const fs::path& tmp) {
        writeVtp(tmp / particleFileName, particles, value);
        writeExtraFiles(tmp, pieceFiles);
        writeExtraFiles(tmp, extraFiles);
    });
    return target;
}

std::vector<std::pair<double, std::string>> listTimeDirectories(const fs::path& caseDir) {
    std::vector<std::pair<double, std::string>> times;
    for (const auto& t : Case(caseDir).timeDirectories()) times.emplace_back(t.value, t.name);
    return times;
}

bool removeTimeDirectory(const fs::path& caseDir, const std::string& timeName) {
    const fs::path dir = caseDir / timeName;
    std::error_code ec;
    if (!fs::exists(dir, ec)) return false;
    // Renamed first so that a removal interrupted half-way does not leave a partial time that
    // listTimeDirectories would offer for restart.
    const fs::path doomed = dir.string() + ".old" + tmpSuffix();
    renameOrThrow(dir, doomed);
    fs::remove_all(doomed, ec);
    if (ec) throw Error("cannot remove '" + doomed.string() + "': " + ec.message());
    return true;
}

namespace {

// The parts of a temporary's name, "<base>[.old].tmp-<pid>"; false when it is not one of ours.
struct Temporary {
    std::string base;  // the time name or particles.pvd
    bool old = false;
    long pid = 0;
};

bool parseTemporary(const std::string& name, Temporary& t) {
    const std::size_t at = name.rfind(".tmp-");
    if (at == std::string::npos || at == 0) return false;
    const std::string digits = name.substr(at + 5);
    if (digits.empty() || digits.size() > 9 || digits.find_first_not_of("0123456789") != std::string::npos)
        return false;
    t.pid = std::stol(digits);
    t.base = name.substr(0, at);
    t.old = t.base.size() > 4 && t.base.compare(t.base.size() - 4, 4, ".old") == 0;
    if (t.old) t.base.resize(t.base.size() - 4);
    double value = 0;
    return t.pid > 0 && (t.base == "particles.pvd" || parseTime(t.base, value));
}

// The writer of a temporary is gone: no such process, or this one (which has written nothing
// yet when the sweep runs, so the temporary is a dead earlier process's that had our pid).
bool writerGone(long pid) {
    if (pid == long(::getpid())) return true;
    return ::kill(pid_t(pid), 0) != 0 && errno == ESRCH;
}

}  // namespace

std::size_t removeStaleTemporaries(const fs::path& caseDir) {
    std::size_t removed = 0;
    std::error_code ec;
    std::vector<std::pair<fs::path, Temporary>> stale;
    for (const auto& entry : fs::directory_iterator(caseDir, ec)) {
        Temporary t;
        if (parseTemporary(entry.path().filename().string(), t) && writerGone(t.pid))
            stale.emplace_back(entry.path(), t);
    }
    // Killed between the renames: the new directory was complete (fill had returned) and the
    // old one is its predecessor; keep the new one.
    for (auto& [path, t] : stale) {
        if (t.old || t.base == "particles.pvd") continue;
        const fs::path target = caseDir / t.base;
        const fs::path old = caseDir / (t.base + ".old.tmp-" + std::to_string(t.pid));
        if (!fs::exists(target, ec) && fs::is_directory(old, ec) && fs::is_directory(path, ec)) {
            fs::rename(path, target, ec);
            if (!ec) {
                ++removed;
                path.clear();
            }
        }
    }
    for (const auto& [path, t] : stale)
        if (!path.empty()) removed += fs::remove_all(path, ec) > 0;
    return removed;
}

fs::path moveAsideTimeDirectories(const fs::path& caseDir, const std::vector<std::string>& timeNames) {
    fs::path aside;
    for (int n = 1;; ++n) {
        aside = caseDir / ("abandoned." + std::to_string(n));
        std::error_code ec;
        if (fs::exists(aside, ec)) continue;
        if (fs::create_directory(aside, ec)) break;
        if (ec) throw Error("cannot create directory '" + aside.string() + "': " + ec.message());
    }
    for (const auto& name : timeNames) renameOrThrow(caseDir / name, aside / name);
    return aside;
}

}  // namespace mfdyn
