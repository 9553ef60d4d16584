#pragma once
// The particles of a time directory, however many ranks wrote it (TimeDirectory.hpp): its
// particles.vtp, or, when there is none, every piece its particles.pvtp lists, read into one
// ParticleSet. So a run restarts from a time written on any number of ranks, serially or under
// mpirun, and the utilities read either form.
//
// Every rank reads the whole time; under mpirun the decomposition then keeps each rank's share.
// Each rank so holds every particle once, for a moment: fine up to ~10^7 particles (a few GB),
// beyond which the pieces would have to be dealt out instead.
#include "particles/VtpReader.hpp"

#include <filesystem>

namespace mfdyn {

// <timeDir>/particles.vtp when it exists, else <timeDir>/particles.pvtp when that exists, else
// <timeDir>/particles.vtp (the file a "cannot find" names).
std::filesystem::path timeParticleFile(const std::filesystem::path& timeDir);

// The particles of timeDir (readVtp or readPvtp of timeParticleFile). InputError when neither
// file is there, naming the directory.
ParticleFile readTimeParticles(const std::filesystem::path& timeDir);

// Every piece an index lists (Piece Source, relative to the index), concatenated in one set
// sorted by globalId. The pieces must agree on the dimension, the fields (name and kind, in any
// order), the time and the region and material names (a shorter list must begin the longer one);
// nextGlobalId is the largest. An InputError names the index, and the piece where one is at fault:
// missing or unreadable, disagreeing, or holding a globalId another piece holds too.
ParticleFile readPvtp(const std::filesystem::path& file);

}  // namespace mfdyn
