#pragma once
// The node fields of a CartesianGrid as a VTK XML ImageData file (.vti), the grid beside the
// particles in ParaView. A solver returns it from extraOutput() as an ExtraFile
// {"grid.vti", text}; SolverRun writes it into the time directory with particles.vtp and lists
// it in particles.pvd as part 1 of that time (PvdIndex.hpp), so ParaView opens both as one
// time series.
//
// Layout (VTK XML format version 1.0), the encoding of particles.vtp (particles/VtpWriter.hpp):
//   <VTKFile type="ImageData" version="1.0" byte_order="LittleEndian" header_type="UInt64">
//     <ImageData WholeExtent="0 nx 0 ny 0 nz" Origin="x0 y0 z0" Spacing="dx dy dz">
//       <FieldData>  mfdynDimension (Int32), time (Float64)
//       <Piece Extent="0 nx 0 ny 0 nz">
//         <PointData> one DataArray per node field: Float64 or Int64, 1, 3, 9 or 6 components
//                     (vectors and tensors padded with zeros to 3D, as in particles.vtp)
//     <AppendedData encoding="raw">_ then every array as a UInt64 byte count and raw bytes
// Below 3D the missing axes have extent 0 (a 2D grid is one layer of nodes, a 1D grid one line)
// and spacing equal to the first axis's, which ParaView needs positive. VTK's point order (x
// fastest) is the grid's node numbering, so each field is written as it is in memory.
#include "grid/CartesianGrid.hpp"
#include "particles/TimeDirectory.hpp"

#include <array>
#include <cstdint>
#include <functional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace mfdyn {

// The text of the .vti of `grid`'s node fields at `time`: the fields named in `fields`, in that
// order, or every node field in creation order when `fields` is empty. Error naming a field
// asked for that the grid does not have, with the fields it has.
template <int Dim>
std::string vtiText(const CartesianGrid<Dim>& grid, double time, const std::vector<std::string>& fields = {});

// {name, vtiText(...)}: what a solver's extraOutput() returns.
template <int Dim>
ExtraFile vtiFile(const CartesianGrid<Dim>& grid, double time, const std::string& name = "grid.vti",
                  const std::vector<std::string>& fields = {});

// On several ranks the image is written in pieces with an index (VTK's parallel image format),
// so that each rank writes its part and ParaView opens the whole:
//   grid.pvti     <VTKFile type="PImageData" ...><PImageData WholeExtent=".." GhostLevel="0"
//                 Origin=".." Spacing=".."> the arrays' types (PPointData) and one
//                 <Piece Extent=".." Source="grid_<r>.vti"/> per piece
//   grid_<r>.vti  the .vti above of piece r's nodes, its extents the piece's
// A piece is a slab of node layers along the grid's last axis (z in 3D, y in 2D): of C cells and
// P pieces, piece r holds the cells [C r / P, C (r + 1) / P) and their nodes, so neighbouring
// pieces share one node layer (the values there are the same in both), as VTK's pieces do.

// The node layers [first, last] of piece `piece` of `pieces` over `cells` cells.
std::pair<std::int64_t, std::int64_t> gridSlab(std::int64_t cells, int piece, int pieces);

// How many pieces `ranks` ranks write: one each, at most one per cell layer.
template <int Dim>
int gridPieceCount(const CartesianGrid<Dim>& grid, int ranks);

// The .vti of piece `piece` of `pieces` (fields as vtiText).
template <int Dim>
std::string vtiPieceText(const CartesianGrid<Dim>& grid, double time, const std::vector<std::string>& fields,
                         int piece, int pieces);

// The .pvti that indexes `pieces` pieces, piece r in the file pieceName(r).
template <int Dim>
std::string pvtiText(const CartesianGrid<Dim>& grid, const std::vector<std::string>& fields, int pieces,
                     const std::function<std::string(int)>& pieceName);

// A .vti read back (what vtiText writes; tests and tools). Arrays as in the file: `components`
// values per node (padding included), doubles (Int64 arrays converted exactly below 2^53).
struct VtiImage {
    struct Array {
        std::string name;
        std::string type;  // "Float64" or "Int64"
        int components = 0;
        std::vector<double> values;
    };
    int dimension = 0;
    double time = 0.0;
    std::array<std::int64_t, 3> cells{0, 0, 0};  // the upper WholeExtent per axis
    std::array<std::int64_t, 3> first{0, 0, 0};  // the lower one (a piece's first node layer)
    std::array<double, 3> origin{0, 0, 0}, spacing{0, 0, 0};
    std::vector<Array> arrays;

    const Array* find(std::string_view name) const;
};

// Parses `text` (the contents of a .vti mfdyn wrote); InputError naming `fileName` for anything
// else (another encoding, a truncated file, sizes that disagree).
VtiImage parseVti(std::string_view text, const std::string& fileName);

extern template std::string vtiText<1>(const CartesianGrid<1>&, double, const std::vector<std::string>&);
extern template std::string vtiText<2>(const CartesianGrid<2>&, double, const std::vector<std::string>&);
extern template std::string vtiText<3>(const CartesianGrid<3>&, double, const std::vector<std::string>&);
extern template ExtraFile vtiFile<1>(const CartesianGrid<1>&, double, const std::string&,
                                     const std::vector<std::string>&);
extern template ExtraFile vtiFile<2>(const CartesianGrid<2>&, double, const std::string&,
                                     const std::vector<std::string>&);
extern template ExtraFile vtiFile<3>(const CartesianGrid<3>&, double, const std::string&,
                                     const std::vector<std::string>&);

}  // namespace mfdyn
