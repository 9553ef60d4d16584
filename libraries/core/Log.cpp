#include "core/Log.hpp"

#include "core/Parallel.hpp"

#include <sys/resource.h>
#include <unistd.h>

#include <atomic>
#include <cstdio>
#include <iostream>

#ifndef MFDYN_GIT_REVISION
#define MFDYN_GIT_REVISION "unknown"
#endif

namespace mfdyn {

namespace {
std::atomic<int> warnings{0};
}

void Log::info(const std::string& message) {
    std::cout << message << std::endl;
}

void Log::warning(const std::string& message) {
    ++warnings;
    std::cout << "Warning: " << message << std::endl;
}

int Log::warningCount() {
    return warnings.load();
}

bool Log::interactive() {
    return isatty(STDOUT_FILENO) != 0;
}

std::string banner(const std::string& application, const std::filesystem::path& caseDir,
                   const std::string& commandLine) {
    std::string line(72, '-');
    return line + "\n" + application +
           "  (mfdyn " MFDYN_VERSION ", git " MFDYN_GIT_REVISION ", " MFDYN_BUILD_TYPE ")\n" +
           "  command: " + commandLine +
           "\n  case:    " + std::filesystem::absolute(caseDir).lexically_normal().string() +
           "\n  threads: " + std::to_string(threadCount()) + "\n" + line;
}

std::size_t peakMemoryBytes() {
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    return std::size_t(usage.ru_maxrss) * 1024;  // Linux reports kilobytes
}

std::string formatBytes(double bytes) {
    const char* units[] = {"B", "KiB", "MiB", "GiB", "TiB"};
    int u = 0;
    while (bytes >= 1024 && u < 4) bytes /= 1024, ++u;
    char s[32];
    std::snprintf(s, sizeof s, u == 0 ? "%.0f %s" : "%.1f %s", bytes, units[u]);
    return s;
}

std::string formatSeconds(double seconds) {
    char s[48];
    if (seconds < 60)
        std::snprintf(s, sizeof s, "%.3g s", seconds);
    else if (seconds < 3600)
        std::snprintf(s, sizeof s, "%dm%02ds", int(seconds) / 60, int(seconds) % 60);
    else
        std::snprintf(s, sizeof s, "%dh%02dm", int(seconds) / 3600, (int(seconds) % 3600) / 60);
    return s;
}

}  // namespace mfdyn
