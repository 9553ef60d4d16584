#pragma once
// What unit tests that run a case read back: the last row of a function object's CSV, by column.
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>

namespace mfdyn::testing {

// The last row of `file` (header first, '#' lines skipped) as column name -> value; empty when the
// file has no row.
inline std::map<std::string, double> lastCsvRow(const std::filesystem::path& file) {
    std::ifstream in(file);
    std::string header, row, line;
    while (std::getline(in, line))
        if (!line.empty() && line[0] != '#') (header.empty() ? header : row) = line;
    std::map<std::string, double> values;
    std::stringstream h(header), r(row);
    std::string name, value;
    while (std::getline(h, name, ',') && std::getline(r, value, ',')) values[name] = std::stod(value);
    return values;
}

}  // namespace mfdyn::testing
