// Function objects of scope owned on several ranks (run serially by ctest, and on three ranks
// under mpiexec where MPI is built): what they keep from one write to the next and what they name
// in a message is every rank's, not the share of the rank that computed it. On one process these
// pass whatever the code does; on several they fail where a rank keeps or names its own only.
#include "DistributedTestCase.hpp"
#include "core/Error.hpp"

#include <gtest/gtest.h>

#include <string>

using namespace mfdyn;
using namespace mfdyn::distributedTest;

namespace {

// A 5 x 5 block, particle id = 5 j + i at (stretch i, j).
void placeBlock(ParticleSet<2>& p, const std::vector<std::int64_t>& ids, double stretch) {
    p.resize(ids.size());
    p.regionNames = {"block"};
    for (std::size_t k = 0; k < ids.size(); ++k) {
        p.globalId()[k] = ids[k];
        p.region()[k] = 0;
        p.position()[k] = Vector<2>(stretch * double(ids[k] % 5), double(ids[k] / 5));
    }
}

// mode lines picks the top row and the centre column at its first write; when their particles
// then live on other ranks (each particle moved to the next rank), every rank must still know
// them (before, each kept the ids it held itself, and none was found: "no particle on the top row").
TEST(GlobalReductions, bodyExtentsLinesFollowTheirParticlesToOtherRanks) {
    SteppedContext run(functionObjectTest::freshCase("Global", "lines"));
    placeBlock(run.particles, myShare(25, 0), 1.0);
    const auto extents = FunctionObject::New(
        Dictionary::parse("type bodyExtents; mode lines; reference (8 4);", "lines"), "lines", run);
    extents->write();  // the top row y = 4 (ids 20-24) and the column x = 2 (ids 2, 7, ..., 22)
    placeBlock(run.particles, myShare(25, 1), 2.0);
    run.step();
    EXPECT_NO_THROW(extents->write());
    const auto measured = extents->referenceValues();
    ASSERT_EQ(measured.size(), 2u);
    EXPECT_EQ(measured[0].value, 8.0);  // the row from x = 0 to 2 x 4
    EXPECT_EQ(measured[1].value, 4.0);
}

// maxEnergyGrowth's diagnosis names the fastest particle, wherever it lives, with the same text on
// every rank (before, each rank named its own fastest).
TEST(GlobalReductions, energyGrowthNamesTheFastestParticleOfAnyRank) {
    SteppedContext run(functionObjectTest::freshCase("Global", "growth"));
    place(run.particles, myShare());
    auto& v = run.particles.vectorField("velocity");
    for (auto& vk : v) vk = Vector<2>(1, 0);
    const auto conserved = FunctionObject::New(
        Dictionary::parse("type conservedQuantities; maxEnergyGrowth 2;", "energy"), "energy", run);
    conserved->write();  // E0 = sum 1/2 (id/2) 1 = 63.25
    for (std::size_t k = 0; k < v.size(); ++k)
        if (run.particles.globalId()[k] == 13) v[k] = Vector<2>(0, 100);
    run.step();
    std::string message;
    try {
        conserved->write();
    } catch (const RunError& e) {
        message = e.what();
    }
    EXPECT_NE(message.find("Fastest particle: globalId 13 at (13 -26), |v| = 100"), std::string::npos)
        << message;
}

}  // namespace
