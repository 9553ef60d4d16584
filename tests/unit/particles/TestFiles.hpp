#pragma once
// Scratch directories and file helpers shared by the particle tests.
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <exception>
#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>
#include <string>
#include <thread>

namespace mfdyn::test {

// A fresh directory under the system temp dir, removed at the end of the test.
class ScratchDir {
public:
    explicit ScratchDir(const std::string& tag)
        : path_(std::filesystem::temp_directory_path() /
                ("mfdynParticles-" + tag + "-" + std::to_string(::getpid()))) {
        std::filesystem::remove_all(path_);
        std::filesystem::create_directories(path_);
    }
    ~ScratchDir() {
        std::error_code ec;
        std::filesystem::remove_all(path_, ec);
    }
    const std::filesystem::path& path() const { return path_; }

private:
    std::filesystem::path path_;
};

inline std::string readFile(const std::filesystem::path& file) {
    std::ifstream in(file, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

inline void writeFile(const std::filesystem::path& file, const std::string& contents) {
    std::ofstream(file, std::ios::binary) << contents;
}

// What happened when a reader was pointed at a FIFO.
struct FifoResult {
    double seconds = 0;    // until the reader returned or threw
    bool blocked = false;  // it had to be released by opening the FIFO's writing end
    std::string message;   // what() of the exception it threw, "" if none
};

// Makes a FIFO at `fifo` and runs `read` on it. A reader that blocks in open() or read() would
// hang the test, so after `patience` a watchdog opens the writing end and closes it again, which
// releases the reader with an empty file: the test then fails on `blocked` instead of hanging.
inline FifoResult readFifo(const std::filesystem::path& fifo, const std::function<void()>& read,
                           std::chrono::milliseconds patience = std::chrono::milliseconds(3000)) {
    FifoResult result;
    if (::mkfifo(fifo.c_str(), 0600) != 0) {
        result.message = "mkfifo failed";
        return result;
    }
    std::atomic<bool> done{false};
    const auto start = std::chrono::steady_clock::now();
    std::thread watchdog([&] {
        while (!done) {
            std::this_thread::sleep_for(std::chrono::milliseconds(5));
            if (done || std::chrono::steady_clock::now() - start < patience) continue;
            // Succeeds only while a reader has the FIFO open (or is opening it).
            const int fd = ::open(fifo.c_str(), O_WRONLY | O_NONBLOCK);
            if (fd >= 0) {
                result.blocked = true;
                ::close(fd);
            }
        }
    });
    try {
        read();
    } catch (const std::exception& e) {
        result.message = e.what();
    }
    result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    done = true;
    watchdog.join();
    return result;
}

}  // namespace mfdyn::test
