#include "core/CaseLock.hpp"

#include "core/Error.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <string>

namespace mfdyn {

namespace {

// What the holder wrote ("<pid> <application>"), trimmed; empty when it has not written yet.
std::string holderOf(int fd) {
    char text[256] = {};
    const ssize_t n = ::pread(fd, text, sizeof text - 1, 0);
    std::string s(text, n > 0 ? std::size_t(n) : 0);
    while (!s.empty() && (s.back() == '\n' || s.back() == ' ')) s.pop_back();
    return s;
}

}  // namespace

CaseLock::CaseLock(const std::filesystem::path& caseDir, const std::string& application)
    : file_(caseDir / fileName) {
    // A few rounds at most: each retry means a holder released the lock (and removed the file)
    // between our open and our flock.
    for (int attempt = 0; attempt < 100; ++attempt) {
        const int fd = ::open(file_.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
        if (fd < 0)
            throw Error("cannot open the case lock '" + file_.string() + "': " + std::strerror(errno));
        if (::flock(fd, LOCK_EX | LOCK_NB) != 0) {
            const int err = errno;
            const std::string holder = holderOf(fd);
            ::close(fd);
            if (err != EWOULDBLOCK)
                throw Error("cannot lock '" + file_.string() + "': " + std::strerror(err));
            const std::string pid = holder.substr(0, holder.find(' '));
            const std::string app =
                holder.find(' ') == std::string::npos ? "" : holder.substr(holder.find(' ') + 1);
            throw Error("the case " + caseDir.string() + " is in use: " +
                        (holder.empty() ? std::string("another process")
                                        : (app.empty() ? "process" : app) + " (pid " + pid + ")") +
                        " holds its lock " + file_.string() +
                        " and may be writing results; wait for it to end" +
                        (pid.empty() ? std::string(".") : " or stop it (kill -INT " + pid + ")."));
        }
        // Locked: but is it still the file at the path? A holder that released it removed the
        // file first, and another run may since have created and locked a new one.
        struct stat byFd {
        }, byPath{};
        if (::fstat(fd, &byFd) == 0 && ::stat(file_.c_str(), &byPath) == 0 && byFd.st_dev == byPath.st_dev &&
            byFd.st_ino == byPath.st_ino) {
            const std::string holder = std::to_string(::getpid()) + " " + application + "\n";
            if (::ftruncate(fd, 0) != 0 ||
                ::pwrite(fd, holder.data(), holder.size(), 0) != ssize_t(holder.size())) {
                const int err = errno;
                ::close(fd);
                throw Error("cannot write the case lock '" + file_.string() + "': " + std::strerror(err));
            }
            fd_ = fd;
            return;
        }
        ::close(fd);
    }
    throw Error("cannot take the case lock '" + file_.string() + "': it keeps being replaced");
}

CaseLock::~CaseLock() {
    if (fd_ < 0) return;
    // Removed while still locked, so nobody can lock the old file and believe it current.
    ::unlink(file_.c_str());
    ::close(fd_);
}

}  // namespace mfdyn
