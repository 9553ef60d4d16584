#pragma once
// A whole input file read into memory, from a regular file only. A FIFO (or a device, socket or
// directory) in place of particles.vtp or particles.pvd would make a plain open() or read()
// wait for a writer that never comes, so the file is stat()ed first, opened with O_NONBLOCK
// (which returns at once even for a FIFO) and fstat()ed again on the open descriptor, so that a
// swap between the two checks cannot slip a FIFO through. A file that is not regular is the
// InputError "'<file>' is not a regular file (...)".
#include <cstddef>
#include <filesystem>
#include <memory>
#include <string_view>

namespace mfdyn {

class RegularFile {
public:
    // InputError naming the file when it is missing, not regular, unreadable or too large for
    // the memory there is.
    explicit RegularFile(const std::filesystem::path& file);

    const char* data() const { return data_.get(); }
    std::size_t size() const { return size_; }
    std::string_view view() const { return {data_.get(), size_}; }

private:
    std::unique_ptr<char[]> data_;  // size_ bytes, not NUL-terminated
    std::size_t size_ = 0;
};

}  // namespace mfdyn
