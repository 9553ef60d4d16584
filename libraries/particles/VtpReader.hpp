#pragma once
// Reads the particle files of VtpWriter.hpp back into a ParticleSet of the right dimension.
//
// The dimension is the FieldData value mfdynDimension, or, in a file without it, the highest
// axis along which some point has a non-zero coordinate. Each PointData array becomes a field
// whose kind follows from its type and component count: integer types with 1 component are
// integer fields; Float64/Float32 with 1, 3, 9, 6 components are scalar, vector, tensor and
// symmTensor fields (padding beyond the dimension dropped). Float64 and Int64 arrays are copied
// bit for bit. A file without globalId gets 0..n-1, one without region gets region 0.
//
// Only appended raw data is read (what mfdyn writes); base64, compressed, inline and big-endian
// files are reported as such. Every error names the file and what is wrong.
#include "particles/ParticleSetBase.hpp"

#include <filesystem>
#include <memory>

namespace mfdyn {

struct ParticleFile {
    std::unique_ptr<ParticleSetBase> particles;
    double time = 0.0;
    bool hasTime = false;
};

ParticleFile readVtp(const std::filesystem::path& file);

}  // namespace mfdyn
