#pragma once
// A CSV file under postProcessing/: header line first, one row per call, flushed at once so a
// killed run keeps every row it computed.
//
// Nothing is touched until the first row: a run that stops while setting up (a bad function
// object after good ones) leaves every earlier file as it was.
//
// A file whose first column is `time` is a time series and continues across runs: when it exists
// with the same header, its rows before the run's start time are kept (rewritten atomically,
// temporary file then rename) and this run's rows follow. The row at the start time itself is
// not kept, since every function object writes one at the start. Rows from the start time on
// belong to an earlier run's future, which this run replaces: the whole earlier file is first
// copied to `<file>.old` (`.old1`, `.old2`, ... when taken). A file whose header differs
// (columns changed) is moved there instead, never mixed. A row cut off by a killed run (no
// newline) is dropped. Any other file (a profile at one time, a sampled line) is a table,
// written whole.
//
// Under mpirun only rank 0 writes: every rank makes the same calls with the same values (global
// reductions), and one writer keeps the file whole. The other ranks' calls do nothing.
#include <filesystem>
#include <fstream>
#include <limits>
#include <string>
#include <vector>

namespace mfdyn {

class CsvFile {
public:
    // `startTime`: the time this run started from (series only); NaN: the time of the first row.
    CsvFile(const std::filesystem::path& file, const std::vector<std::string>& columns,
            double startTime = std::numeric_limits<double>::quiet_NaN());
    // A table that got no row still gets its header (an empty profile is a result too).
    ~CsvFile();
    CsvFile(const CsvFile&) = delete;
    CsvFile& operator=(const CsvFile&) = delete;

    void row(const std::vector<double>& values);
    // A row whose second column is a word (errorNorms.csv: time,field,L1,L2,Linf).
    void row(double time, const std::string& label, const std::vector<double>& values);
    const std::filesystem::path& path() const { return path_; }
    bool series() const { return series_; }

private:
    void open(double firstTime);
    void openSeries(double cutoff);

    std::filesystem::path path_;
    std::string header_;
    std::size_t columns_;
    bool series_;
    double startTime_;
    std::ofstream out_;
    bool opened_ = false;
    bool writer_;  // this process writes the file: rank 0
};

}  // namespace mfdyn
