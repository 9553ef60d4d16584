#pragma once
// A CSV file under postProcessing/: header line first, first column `time`, one row per call,
// flushed at once so a killed run keeps every row it computed.
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace mfdyn {

class CsvFile {
public:
    CsvFile(const std::filesystem::path& file, const std::vector<std::string>& columns);
    void row(const std::vector<double>& values);
    // A row whose second column is a word (errorNorms.csv: time,field,L1,L2,Linf).
    void row(double time, const std::string& label, const std::vector<double>& values);
    const std::filesystem::path& path() const { return path_; }

private:
    std::filesystem::path path_;
    std::ofstream out_;
};

}  // namespace mfdyn
