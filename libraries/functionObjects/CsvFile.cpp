#include "functionObjects/CsvFile.hpp"

#include "core/Communicator.hpp"
#include "core/Error.hpp"
#include "core/Log.hpp"

#include <unistd.h>
#include <algorithm>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <exception>

namespace mfdyn {

namespace fs = std::filesystem;

namespace {

std::string number(double x) {
    char s[32];
    std::snprintf(s, sizeof s, "%.10g", x);
    return s;
}

// The time in a row's first cell; false when the row is not a complete row of `columns` cells.
bool rowTime(const std::string& line, std::size_t columns, double& time) {
    if (std::size_t(std::count(line.begin(), line.end(), ',')) + 1 != columns) return false;
    const std::size_t comma = std::min(line.find(','), line.size());
    const char* begin = line.data();
    auto [ptr, ec] = std::from_chars(begin, begin + comma, time);
    return ec == std::errc() && ptr == begin + comma;
}

// `<file>.old`, or `<file>.old1`, `.old2`, ... when an earlier one is there: nothing is replaced.
fs::path asideName(const fs::path& file) {
    fs::path aside = file.string() + ".old";
    for (int k = 1; fs::exists(aside); ++k) aside = file.string() + ".old" + std::to_string(k);
    return aside;
}

}  // namespace

CsvFile::CsvFile(const fs::path& file, const std::vector<std::string>& columns, double startTime)
    : path_(file),
      columns_(columns.size()),
      series_(!columns.empty() && columns[0] == "time"),
      startTime_(startTime),
      writer_(Communicator::rank() == 0) {
    for (std::size_t k = 0; k < columns.size(); ++k) header_ += (k ? "," : "") + columns[k];
}

CsvFile::~CsvFile() {
    // Not while an exception unwinds: a failed write must not leave a header-only file behind.
    if (!writer_ || opened_ || series_ || std::uncaught_exceptions() > 0) return;
    try {
        open(startTime_);
    } catch (const std::exception& e) {
        Log::warning(e.what());
    }
}

void CsvFile::open(double firstTime) {
    opened_ = true;
    std::error_code ec;
    fs::create_directories(path_.parent_path(), ec);
    if (ec) throw Error("cannot create directory " + path_.parent_path().string() + ": " + ec.message());
    if (series_) {
        openSeries(std::isnan(startTime_) ? firstTime : startTime_);
    } else {
        out_.open(path_, std::ios::trunc);
        if (!out_) throw Error("cannot write " + path_.string() + ": " + std::strerror(errno));
        out_ << header_ << std::endl;
    }
}

void CsvFile::openSeries(double cutoff) {
    std::vector<std::string> kept;
    std::size_t dropped = 0;
    fs::path aside;
    if (fs::exists(path_)) {
        std::ifstream in(path_, std::ios::binary);
        if (!in) throw Error("cannot read " + path_.string() + ": " + std::strerror(errno));
        const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
        in.close();
        // Complete lines only: a last line without its newline is a row cut off by a killed run.
        std::vector<std::string> lines;
        for (std::size_t begin = 0; begin < text.size();) {
            const std::size_t end = text.find('\n', begin);
            if (end == std::string::npos) break;
            lines.push_back(text.substr(begin, end - begin));
            begin = end + 1;
        }
        if (lines.empty() || lines[0] != header_) {
            if (!text.empty()) {
                const fs::path aside = asideName(path_);
                std::error_code ec;
                fs::rename(path_, aside, ec);
                if (ec)
                    throw Error("cannot move " + path_.string() + " aside to " + aside.string() + ": " +
                                ec.message());
                Log::warning(path_.string() + " has other columns than this run writes (" + header_ +
                             "); the old file is kept as " + aside.string());
            }
        } else {
            // Rows before the cutoff, to within the 10 digits a row's time is written with; rows
            // are in time order, so the first one at or past it ends the kept part.
            const double before = cutoff - 1e-9 * std::abs(cutoff);
            std::size_t n = 1;
            double t;
            while (n < lines.size() && rowTime(lines[n], columns_, t) && t < before) ++n;
            kept.assign(lines.begin(), lines.begin() + long(n));
            dropped = lines.size() - n;
            if (dropped == 0 && text.back() == '\n') {
                out_.open(path_, std::ios::app);
                if (!out_) throw Error("cannot write " + path_.string() + ": " + std::strerror(errno));
                return;
            }
            // The rows from the start time on were computed by an earlier run that went on from
            // there (or from a state since replaced): this run writes its own, and the earlier
            // ones are copied aside whole first, as the solver moves that run's time directories.
            if (dropped > 0) {
                aside = asideName(path_);
                std::error_code ec;
                fs::copy_file(path_, aside, ec);
                if (ec)
                    throw Error("cannot copy " + path_.string() + " to " + aside.string() + ": " +
                                ec.message());
            }
        }
    }
    if (kept.empty()) kept.push_back(header_);
    // The kept part goes to a temporary first: a crash now leaves either the old file or the new.
    const fs::path tmp = path_.string() + ".tmp-" + std::to_string(::getpid());
    {
        std::ofstream out(tmp, std::ios::trunc | std::ios::binary);
        for (const auto& line : kept) out << line << '\n';
        out.flush();
        if (!out) throw Error("cannot write " + tmp.string() + ": " + std::strerror(errno));
    }
    std::error_code ec;
    fs::rename(tmp, path_, ec);
    if (ec) {
        fs::remove(tmp, ec);
        throw Error("cannot replace " + path_.string() + ": " + ec.message());
    }
    if (dropped > 0)
        Log::info(path_.string() + ": " + std::to_string(kept.size() - 1) + " rows before t = " +
                  number(cutoff) + " kept, this run's rows follow; the earlier run's file (" +
                  std::to_string(dropped) + " rows from then on) is kept as " + aside.string());
    out_.open(path_, std::ios::app);
    if (!out_) throw Error("cannot write " + path_.string() + ": " + std::strerror(errno));
}

void CsvFile::row(const std::vector<double>& values) {
    if (!writer_) return;
    if (!opened_) open(values.empty() ? startTime_ : values[0]);
    for (std::size_t k = 0; k < values.size(); ++k) out_ << (k ? "," : "") << number(values[k]);
    out_ << std::endl;
}

void CsvFile::row(double time, const std::string& label, const std::vector<double>& values) {
    if (!writer_) return;
    if (!opened_) open(time);
    out_ << number(time) << "," << label;
    for (double v : values) out_ << "," << number(v);
    out_ << std::endl;
}

}  // namespace mfdyn
