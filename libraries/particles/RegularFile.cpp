#include "particles/RegularFile.hpp"

#include "core/Error.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>
#include <cerrno>
#include <cstring>
#include <new>
#include <string>

namespace mfdyn {

namespace {

const char* modeName(mode_t mode) {
    if (S_ISDIR(mode)) return "a directory";
    if (S_ISFIFO(mode)) return "a FIFO (named pipe)";
    if (S_ISCHR(mode)) return "a character device";
    if (S_ISBLK(mode)) return "a block device";
    if (S_ISSOCK(mode)) return "a socket";
    return "not a plain file";
}

[[noreturn]] void notRegular(const std::filesystem::path& file, mode_t mode) {
    throw InputError("'" + file.string() + "' is not a regular file (it is " + modeName(mode) +
                     "); mfdyn reads particle and index files from regular files only");
}

[[noreturn]] void systemFailure(const std::filesystem::path& file, const char* what, int error) {
    throw InputError("cannot " + std::string(what) + " '" + file.string() + "': " + std::strerror(error));
}

// Closes the descriptor on every way out, errors included.
struct Descriptor {
    int fd;
    ~Descriptor() {
        if (fd >= 0) ::close(fd);
    }
};

}  // namespace

RegularFile::RegularFile(const std::filesystem::path& file) {
    // stat() first so that a device is never even opened (opening one can have effects).
    struct stat st {};
    if (::stat(file.c_str(), &st) != 0) systemFailure(file, "open", errno);
    if (!S_ISREG(st.st_mode)) notRegular(file, st.st_mode);
    Descriptor in{::open(file.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC)};
    if (in.fd < 0) systemFailure(file, "open", errno);
    // The file may have been replaced since the stat(): judge the one actually opened.
    if (::fstat(in.fd, &st) != 0) systemFailure(file, "read the size of", errno);
    if (!S_ISREG(st.st_mode)) notRegular(file, st.st_mode);
    if (st.st_size < 0) throw InputError("'" + file.string() + "' has a negative size");
    size_ = std::size_t(st.st_size);
    try {
        // Uninitialised on purpose: the whole file is read over it.
        data_ = std::make_unique_for_overwrite<char[]>(size_ == 0 ? 1 : size_);
    } catch (const std::bad_alloc&) {
        throw InputError("'" + file.string() + "' has " + std::to_string(size_) +
                         " bytes, more than the memory there is");
    }
    std::size_t got = 0;
    while (got < size_) {
        const ssize_t n = ::read(in.fd, data_.get() + got, size_ - got);
        if (n < 0 && errno == EINTR) continue;
        if (n < 0) systemFailure(file, "read", errno);
        if (n == 0) break;
        got += std::size_t(n);
    }
    if (got != size_)
        throw InputError("'" + file.string() + "' shrank from " + std::to_string(size_) + " to " +
                         std::to_string(got) + " bytes while being read");
}

}  // namespace mfdyn
