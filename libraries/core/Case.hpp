#pragma once
// A case directory: system/, constant/, time directories <time>/, postProcessing/.
#include "core/Dictionary.hpp"

#include <filesystem>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace mfdyn {

struct TimeDirectory {
    double value;
    std::string name;
};

class Case {
public:
    explicit Case(std::filesystem::path root);

    const std::filesystem::path& root() const { return root_; }
    std::filesystem::path systemFile(const std::string& name) const { return root_ / "system" / name; }
    std::filesystem::path constantFile(const std::string& name) const { return root_ / "constant" / name; }
    std::filesystem::path timeDir(const std::string& timeName) const { return root_ / timeName; }
    std::filesystem::path postProcessing() const { return root_ / "postProcessing"; }

    // Reads system/<name> or constant/<name>; a missing file is an InputError naming it.
    Dictionary readSystem(const std::string& name) const;
    Dictionary readConstant(const std::string& name) const;

    // Numeric directory names, sorted by value (temporary *.tmp-* directories are skipped).
    std::vector<TimeDirectory> timeDirectories() const;
    std::optional<TimeDirectory> latestTime() const;
    // The time directory whose value matches `value` to 1e-12 relative.
    std::optional<TimeDirectory> findTime(double value) const;

private:
    std::filesystem::path root_;
};

}  // namespace mfdyn
