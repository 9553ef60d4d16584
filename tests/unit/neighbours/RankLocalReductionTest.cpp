// The neighbour search, CellBins and the Verlet list work on this rank's particles only: they
// must never reach the global (MPI) reduction hook. Before the Reduce split they summed and
// maximised through Reduce, the global kind, behind early returns (a rebuild that is not needed,
// an empty cloud, a throw on bad input): under MPI a rank taking the early return leaves the
// others waiting in the collective. The hook counts its calls; these tests assert none.
#include "NeighbourTestClouds.hpp"
#include "core/Parallel.hpp"
#include "particles/CellBins.hpp"
#include "particles/VerletList.hpp"

#include <gtest/gtest.h>

#include <limits>

namespace mfdyn {
namespace {

TEST(RankLocalReduction, NeighbourSearchAndVerletListNeverReduceGlobally) {
    auto cloud = test::randomCloud<3>(5000, 21);  // above parallelThreshold: the threaded path too
    std::vector<double> radius(cloud.size(), 0.05);
    radius[7] = 0.08;
    const auto before = globalReductionCount.load();

    NeighbourSearch<3> search;
    search.build(cloud, radius);
    search.build(cloud, 0.05);
    CellBins<3> bins;
    bins.bin(cloud, 0.1);
    (void)bins.within(cloud[0], 0.1);
    VerletList<3> verlet(0.01);
    EXPECT_TRUE(verlet.update(cloud, radius));   // first build
    EXPECT_FALSE(verlet.update(cloud, radius));  // the early return: no rebuild needed
    for (auto& x : cloud) x[0] += 0.006;         // 2 x 0.006 > skin: rebuild
    EXPECT_TRUE(verlet.update(cloud, radius));
    (void)verlet.maxDisplacement(cloud);
    // The throwing paths count too: a rank that throws alone must not have entered a collective.
    auto bad = cloud;
    bad[3][1] = std::numeric_limits<double>::quiet_NaN();
    EXPECT_THROW(search.build(bad, 0.05), Error);
    EXPECT_THROW(bins.bin(bad, 0.1), Error);

    EXPECT_EQ(globalReductionCount.load(), before) << "a rank-local neighbour structure reduced globally";
}

// The counter sees what it must: each GlobalReduce once, LocalReduce never.
TEST(RankLocalReduction, GlobalReduceReachesTheHookOnceAndLocalReduceNever) {
    const auto before = globalReductionCount.load();
    EXPECT_EQ(LocalReduce::sum<double>(10, [](std::size_t i) { return double(i); }), 45.0);
    EXPECT_EQ(LocalReduce::max(10, [](std::size_t i) { return double(i); }), 9.0);
    EXPECT_EQ(globalReductionCount.load(), before);
    EXPECT_EQ(GlobalReduce::sum<double>(10, [](std::size_t i) { return double(i); }), 45.0);
    EXPECT_EQ(GlobalReduce::min(10, [](std::size_t i) { return double(i) - 3; }), -3.0);
    EXPECT_EQ(GlobalReduce::max(10, [](std::size_t i) { return double(i); }), 9.0);
    EXPECT_EQ(globalReductionCount.load(), before + 3);
}

}  // namespace
}  // namespace mfdyn
