#pragma once
// One writer per case at a time. A solver (and particleGen, which rewrites 0/) holds
// <case>/.mfdyn.lock with flock(LOCK_EX | LOCK_NB) for as long as it may write: two solvers in
// one case would otherwise interleave their time directories and rewrite particles.pvd over each
// other's entries. The holder's pid and application are written into the file so that the
// refused run can name it.
//
// flock, not the file's existence, is the lock: the kernel drops it when the holder exits, even
// by SIGKILL, so a lock file left by a killed run is no obstacle. The file is removed when the
// lock is released; a run that opened it just before the removal sees (after its flock) that the
// path no longer names the file it locked, and starts again on a fresh one.
#include <filesystem>
#include <string>

namespace mfdyn {

class CaseLock {
public:
    static constexpr const char* fileName = ".mfdyn.lock";

    // Takes the case's lock for `application`; an Error naming the holder (pid, application)
    // when another process holds it.
    CaseLock(const std::filesystem::path& caseDir, const std::string& application);
    ~CaseLock();
    CaseLock(const CaseLock&) = delete;
    CaseLock& operator=(const CaseLock&) = delete;

    const std::filesystem::path& file() const { return file_; }

private:
    std::filesystem::path file_;
    int fd_ = -1;
};

}  // namespace mfdyn
