#pragma once
// What the function-object unit tests share: a case directory of their own under the temporary
// directory (system/controlDict written), a RunContext over a hand-made particle set and a Time
// that a test moves by hand, and the rows of a CSV a function object wrote.
#include "core/Dictionary.hpp"
#include "functionObjects/FunctionObject.hpp"
#include "particles/ParticleSet.hpp"

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace mfdyn::functionObjectTest {

inline const char* controlDictText = "endTime 1; deltaT 1e-3; writeControl timeStep; writeInterval 1;\n";

template <int Dim>
class TestContext final : public RunContext {
public:
    explicit TestContext(const std::filesystem::path& root)
        : case_(root),
          time_(root / "system" / "controlDict", Dictionary::parse(controlDictText, "controlDict")) {
        time_.start(0, "0");
    }
    const Case& runCase() const override { return case_; }
    const Time& time() const override { return time_; }
    const FieldStore& fields() const override { return particles; }
    const std::string& startTimeName() const override { return start_; }
    void at(double t) { time_.start(t, "0"); }
    ParticleSet<Dim> particles;

private:
    Case case_;
    Time time_;
    std::string start_ = "0";
};

// A fresh case directory mfdyn<prefix>-<tag>-<pid> with its controlDict (the pid keeps parallel
// ctest runs apart).
inline std::filesystem::path freshCase(const std::string& prefix, const std::string& tag) {
    namespace fs = std::filesystem;
    const fs::path root =
        fs::temp_directory_path() / ("mfdyn" + prefix + "-" + tag + "-" + std::to_string(::getpid()));
    fs::remove_all(root);
    fs::create_directories(root / "system");
    std::ofstream(root / "system" / "controlDict") << controlDictText;
    return root;
}

// The numbers of a CSV's rows after its header.
inline std::vector<std::vector<double>> csvRows(const std::filesystem::path& file) {
    std::ifstream in(file);
    std::vector<std::vector<double>> out;
    std::string line;
    std::getline(in, line);  // header
    while (std::getline(in, line)) {
        std::vector<double> row;
        std::istringstream cells(line);
        for (std::string cell; std::getline(cells, cell, ',');) row.push_back(std::stod(cell));
        out.push_back(row);
    }
    return out;
}

}  // namespace mfdyn::functionObjectTest
