#pragma once
// particles.pvd: the ParaView collection that lists each written time and its particle file,
// so ParaView opens the whole run as one time series. A time may have further parts beside the
// particles (part 0): a grid method's node fields, grid.vti, are part 1 of the same time
// (grid/VtiWriter.hpp), so ParaView opens particles and grid together, each as its own block. It is rewritten whole (atomically) after
// every write and read back on restart, where entries later than the restart time are dropped:
// they belong to the abandoned continuation and will be written again.
//
//   <?xml version="1.0"?>
//   <VTKFile type="Collection" version="1.0" byte_order="LittleEndian">
//     <Collection>
//       <DataSet timestep="0.001" part="0" file="0.001/particles.vtp"/>
//       <DataSet timestep="0.001" part="1" file="0.001/grid.vti"/>
//     </Collection>
//   </VTKFile>
#include <filesystem>
#include <string>
#include <vector>

namespace mfdyn {

class PvdIndex {
public:
    struct Entry {
        double time;
        std::string file;  // relative to the .pvd
        int part = 0;      // 0: the particles; 1, 2, ...: other files of the same time
    };

    // An empty index that will be written to `file`.
    explicit PvdIndex(std::filesystem::path file);
    // The index in `file`, or an empty one if it does not exist; InputError naming the file if
    // it exists but cannot be read.
    static PvdIndex read(const std::filesystem::path& file);

    // Drops entries with time > `time` (restart), every part of them.
    void truncateAfter(double time);
    // Adds an entry, replacing one at the same time and part, keeping entries sorted by time,
    // then part. A file without part attributes reads as part 0 throughout.
    void add(double time, const std::string& file, int part = 0);
    // Rewrites the file atomically.
    void write() const;

    const std::vector<Entry>& entries() const { return entries_; }
    const std::filesystem::path& file() const { return file_; }

private:
    std::filesystem::path file_;
    std::vector<Entry> entries_;
};

}  // namespace mfdyn
