#pragma once
// The log: what an application prints. Messages go to standard output (runApplication in the
// tutorials' Allrun redirects it to log.<application>); warnings are counted for the summary.
#include <chrono>
#include <cstddef>
#include <filesystem>
#include <string>

namespace mfdyn {

namespace Log {
void info(const std::string& message);
void warning(const std::string& message);
int warningCount();
// Whether standard output is a terminal (progress lines are throttled otherwise).
bool interactive();
}  // namespace Log

// "mfdyn 0.1.0 (git abc1234, Release), 2 threads, case /path" plus the command line.
std::string banner(const std::string& application, const std::filesystem::path& caseDir,
                   const std::string& commandLine);

// Peak resident memory of this process in bytes (getrusage).
std::size_t peakMemoryBytes();
std::string formatBytes(double bytes);
std::string formatSeconds(double seconds);

// Wall-clock stopwatch.
class Stopwatch {
public:
    Stopwatch() : start_(std::chrono::steady_clock::now()) {}
    double seconds() const {
        return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    }
    void restart() { start_ = std::chrono::steady_clock::now(); }

private:
    std::chrono::steady_clock::time_point start_;
};

}  // namespace mfdyn
