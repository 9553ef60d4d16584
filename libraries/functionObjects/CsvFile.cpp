#include "functionObjects/CsvFile.hpp"

#include "core/Error.hpp"

#include <cstdio>

namespace mfdyn {

namespace {
std::string number(double x) {
    char s[32];
    std::snprintf(s, sizeof s, "%.10g", x);
    return s;
}
}  // namespace

CsvFile::CsvFile(const std::filesystem::path& file, const std::vector<std::string>& columns) : path_(file) {
    std::filesystem::create_directories(file.parent_path());
    out_.open(file, std::ios::trunc);
    if (!out_) throw Error("cannot write " + file.string());
    for (std::size_t k = 0; k < columns.size(); ++k) out_ << (k ? "," : "") << columns[k];
    out_ << std::endl;
}

void CsvFile::row(const std::vector<double>& values) {
    for (std::size_t k = 0; k < values.size(); ++k) out_ << (k ? "," : "") << number(values[k]);
    out_ << std::endl;
}

void CsvFile::row(double time, const std::string& label, const std::vector<double>& values) {
    out_ << number(time) << "," << label;
    for (double v : values) out_ << "," << number(v);
    out_ << std::endl;
}

}  // namespace mfdyn
