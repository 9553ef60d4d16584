#pragma once
// The particles of a run dealt out over ranks, for the tests of time directories written in
// pieces (TimeDirectoryReaderTest here, the tests run under mpirun in tests/unit/mpi): rank r of
// R holds the ids r, r + R, r + 2R, ..., and every value follows from the id alone, so a reader of
// any number of pieces can be checked particle by particle.
#include "particles/ParticleSet.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <string>
#include <vector>

namespace mfdyn::test {

inline Vector<2> pieceVelocity(std::int64_t id) {
    return Vector<2>(double(id), -2.0 * double(id) + 0.125);
}
inline double pieceDensity(std::int64_t id) {
    return 1000.0 + double(id) / 3.0;  // not a short binary fraction: the bits must survive the trip
}
inline Vector<2> piecePosition(std::int64_t id) {
    return Vector<2>(0.1 * double(id), 1.0 / (1.0 + double(id)));
}

// Rank `rank`'s share of `total` particles dealt out over `ranks`, in 2D, with a scalar
// (density) and a vector (velocity) field; regions alternate between "left" and "right".
inline ParticleSet<2> pieceOfRank(int rank, int ranks, std::int64_t total) {
    std::vector<std::int64_t> ids;
    for (std::int64_t id = rank; id < total; id += ranks) ids.push_back(id);
    ParticleSet<2> p(ids.size());
    auto& density = p.scalarField("density");
    auto& velocity = p.vectorField("velocity");
    for (std::size_t k = 0; k < ids.size(); ++k) {
        const std::int64_t id = ids[k];
        p.globalId()[k] = id;
        p.region()[k] = id % 2;
        p.position()[k] = piecePosition(id);
        density[k] = pieceDensity(id);
        velocity[k] = pieceVelocity(id);
    }
    p.regionNames = {"left", "right"};
    return p;
}

// `set` holds ids 0 .. total - 1 in order with the values pieceOfRank gave them, bit for bit.
inline void expectAllPiecesInIdOrder(const ParticleSetBase& set, std::int64_t total) {
    ASSERT_EQ(set.dimension(), 2);
    const auto& p = particleSetCast<2>(set);
    ASSERT_EQ(p.size(), std::size_t(total));
    const auto& density = p.requireField<double>("density");
    const auto& velocity = p.requireField<Vector<2>>("velocity");
    for (std::int64_t id = 0; id < total; ++id) {
        const std::size_t k = std::size_t(id);
        EXPECT_EQ(p.globalId()[k], id) << "particle " << k << " out of globalId order";
        EXPECT_EQ(p.region()[k], id % 2) << "id " << id;
        EXPECT_EQ(p.position()[k], piecePosition(id)) << "id " << id;
        EXPECT_EQ(density[k], pieceDensity(id)) << "id " << id;
        EXPECT_EQ(velocity[k], pieceVelocity(id)) << "id " << id;
    }
    EXPECT_EQ(p.regionNames, (std::vector<std::string>{"left", "right"}));
}

}  // namespace mfdyn::test
