#pragma once
// Particles as a VTK XML PolyData file (.vtp) that ParaView opens as it is and that restart
// reads back bit for bit (VtpReader.hpp).
//
// Layout (VTK XML format version 1.0, https://docs.vtk.org/en/latest/vtk_file_formats/):
//   <VTKFile type="PolyData" version="1.0" byte_order="LittleEndian" header_type="UInt64">
//     <PolyData>
//       <FieldData>   mfdynDimension (Int32, 1 tuple), time (Float64, 1 tuple), and, when not
//                     empty, regionNames and materialNames (type="String": one tuple per name,
//                     stored as the names each followed by a NUL byte, index = id), and
//                     nextGlobalId (Int64) when it is above the largest globalId + 1
//                     (ParticleSetBase::nextGlobalId: ids are never reused after a restart)
//       <Piece NumberOfPoints="n" NumberOfVerts="n" ...>
//         <PointData> one DataArray per field except position: Float64 or Int64 (integer
//                     fields), NumberOfComponents 1 (scalar, integer), 3 (vector), 9 (tensor,
//                     row-major 3x3), 6 (symmTensor, XX YY ZZ XY YZ XZ); components beyond the
//                     particle dimension are written as zero
//         <Points>    position, Float64, 3 components (zero-padded below 3D)
//         <Verts>     connectivity 0..n-1 and offsets 1..n (Int64): one vertex cell per
//                     particle, so ParaView draws the points without a Glyph filter
//     <AppendedData encoding="raw">_ then every array as a UInt64 byte count and raw bytes
//
// Every array is format="appended" and raw: no base64 or compression, so writing is one pass of
// fwrite and reading a memcpy per field, and doubles round-trip exactly.
//
// A run on several ranks writes one such file per rank, its piece (particles_<rank>.vtp: that
// rank's owned particles), and an index of them, particles.pvtp (VTK's parallel PolyData, which
// ParaView opens as one data set):
//   <VTKFile type="PPolyData" version="1.0" byte_order="LittleEndian" header_type="UInt64">
//     <PPolyData GhostLevel="0">
//       <PPointData> one PDataArray per PointData array of the pieces (type, Name,
//                    NumberOfComponents as there)
//       <PPoints>    the PDataArray of the Points
//       <Piece Source="particles_0.vtp"/> ... one per rank, in rank order
#include "particles/ParticleSetBase.hpp"

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace mfdyn {

// `runNextGlobalId`: the next id of the whole run when the particles are one rank's piece (the
// largest nextGlobalId() over the ranks), so that the pieces read together never reuse an id;
// 0: this set's own. FieldData nextGlobalId is written when the larger of the two is above this
// set's largest id + 1.
void writeVtp(const std::filesystem::path& file, const ParticleSetBase& particles, double time,
              std::int64_t runNextGlobalId = 0);

// The index of `pieces` (file names relative to the index), whose arrays are those writeVtp
// writes for `particles` (every rank's set has the same fields).
void writePvtp(const std::filesystem::path& file, const ParticleSetBase& particles,
               const std::vector<std::string>& pieces);
// The attributes (type, Name, NumberOfComponents) of each PointData array writeVtp writes for
// `particles`, in its order: what the pieces of one time must agree on.
std::vector<std::string> pointDataAttributes(const ParticleSetBase& particles);

// Components a field of this kind has in the file: 1, 3, 9, 6, 1.
int vtkComponents(FieldKind kind);
// For each file component of a field of `kind` in `dim` dimensions, the index of the in-memory
// component it holds (see componentNames()), or -1 for a zero pad. Used both ways by the writer
// and the reader.
std::vector<int> vtkComponentSource(FieldKind kind, int dim);

}  // namespace mfdyn
