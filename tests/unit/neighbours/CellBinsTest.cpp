// CellBins: the binning itself (every particle once, in its own cell, cells in order) and point
// queries against brute force, at random points inside and far outside the box, in 1, 2 and 3D,
// open, bounded and periodic, with empty cells and a single particle.
#include "NeighbourTestClouds.hpp"
#include "particles/CellBins.hpp"

#include <gtest/gtest.h>

#include <limits>
#include <random>

namespace mfdyn {
namespace {

using Index = CellBins<3>::Index;

// Indices j with |domain.separation(x, x_j)|^2 < r^2, increasing.
template <int Dim>
std::vector<Index> bruteWithin(const std::vector<Vector<Dim>>& cloud, const NeighbourDomain<Dim>& domain,
                               const Vector<Dim>& x, double r) {
    std::vector<Index> out;
    for (std::size_t j = 0; j < cloud.size(); ++j)
        if (domain.separation(x, cloud[j]).squaredNorm() < r * r) out.push_back(Index(j));
    return out;
}

template <int Dim>
std::vector<Index> sorted(std::vector<Index> v) {
    std::sort(v.begin(), v.end());
    return v;
}

// Every particle is in exactly one cell, that cell is cellOf(its position), cells list their
// particles by increasing index, and sortedPositions follows order().
template <int Dim>
void expectConsistentBinning(const CellBins<Dim>& bins, const std::vector<Vector<Dim>>& cloud) {
    ASSERT_EQ(bins.size(), cloud.size());
    std::vector<int> seen(cloud.size(), 0);
    for (std::size_t c = 0; c < bins.cellCount(); ++c) {
        const auto members = bins.particlesOf(c);
        for (std::size_t m = 0; m < members.size(); ++m) {
            ++seen[members[m]];
            EXPECT_EQ(bins.cellOf(cloud[members[m]]), c) << "particle " << members[m];
            if (m > 0) EXPECT_LT(members[m - 1], members[m]) << "cell " << c << " not in index order";
        }
    }
    for (std::size_t i = 0; i < cloud.size(); ++i) EXPECT_EQ(seen[i], 1) << "particle " << i;
    for (std::size_t k = 0; k < cloud.size(); ++k)
        EXPECT_EQ(bins.sortedPositions()[k], cloud[bins.order()[k]]) << "place " << k;
}

// Random query points over [lo, hi] (wider than the cloud: many fall outside the box, some in
// empty cells) at radii from 0 to 0.4, each compared index for index with brute force.
template <int Dim>
void expectQueriesMatchBruteForce(const std::vector<Vector<Dim>>& cloud, const NeighbourDomain<Dim>& domain,
                                  double cellWidth, double lo, double hi, unsigned seed) {
    CellBins<Dim> bins(domain);
    bins.bin(cloud, cellWidth);
    expectConsistentBinning(bins, cloud);
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> u(lo, hi), radius(0.0, 0.4);
    std::size_t found = 0;
    for (int q = 0; q < 300; ++q) {
        Vector<Dim> x;
        for (int d = 0; d < Dim; ++d) x[d] = u(rng);
        const double r = q % 50 == 0 ? 0.0 : radius(rng);
        const auto expected = bruteWithin(cloud, domain, x, r);
        EXPECT_EQ(sorted<Dim>(bins.within(x, r)), expected) << "query " << q << " at r " << r;
        // forEachCandidate is a superset.
        std::vector<Index> candidates;
        bins.forEachCandidate(x, r, [&](Index j) { candidates.push_back(j); });
        candidates = sorted<Dim>(candidates);
        EXPECT_TRUE(std::includes(candidates.begin(), candidates.end(), expected.begin(), expected.end()))
            << "query " << q;
        // The separation handed to the visitor is the one the test used.
        bins.forEachWithin(x, r, [&](Index j, const Vector<Dim>& dx) {
            EXPECT_EQ(dx, domain.separation(x, cloud[j])) << "query " << q << " particle " << j;
        });
        found += expected.size();
    }
    // The test means something only if queries do find particles.
    EXPECT_GT(found, 300u);
}

TEST(CellBins, PointQueriesMatchBruteForceOpen1D) {
    expectQueriesMatchBruteForce<1>(test::randomCloud<1>(200, 1), {}, 0.05, -1.0, 2.0, 11);
}
TEST(CellBins, PointQueriesMatchBruteForceOpen2D) {
    expectQueriesMatchBruteForce<2>(test::randomCloud<2>(500, 2), {}, 0.05, -1.0, 2.0, 12);
}
TEST(CellBins, PointQueriesMatchBruteForceOpen3D) {
    expectQueriesMatchBruteForce<3>(test::randomCloud<3>(1000, 3), {}, 0.1, -1.0, 2.0, 13);
}

// Clusters and far outliers: mostly empty cells, coarsened by maxCellsPerParticle.
TEST(CellBins, PointQueriesMatchBruteForceClustered3D) {
    expectQueriesMatchBruteForce<3>(test::clusteredCloud<3>(800, 4), {}, 0.01, -1.0, 2.0, 14);
}

// A given box smaller than the cloud: particles and points outside it sit in the edge cells.
TEST(CellBins, PointQueriesMatchBruteForceBoundedBoxSmallerThanCloud2D) {
    const NeighbourDomain<2> domain(Vector<2>(0.25, 0.25), Vector<2>(0.75, 0.75));
    expectQueriesMatchBruteForce<2>(test::randomCloud<2>(500, 5), domain, 0.05, -1.0, 2.0, 15);
}

// Periodic in x and z, open in y: queries near and past the period's ends find the images.
TEST(CellBins, PointQueriesMatchBruteForcePeriodic3D) {
    const NeighbourDomain<3> domain(Vector<3>(0, 0, 0), Vector<3>(1, 1, 1), {true, false, true});
    expectQueriesMatchBruteForce<3>(test::randomCloud<3>(1000, 6), domain, 0.1, -1.0, 2.0, 16);
}

TEST(CellBins, SingleParticle) {
    for (double width : {0.0, 0.1}) {
        CellBins<3> bins;
        const std::vector<Vector<3>> one{Vector<3>(0.5, -2.0, 7.0)};
        bins.bin(one, width);
        EXPECT_EQ(bins.cellCount(), 1u);
        EXPECT_EQ(bins.within(Vector<3>(0.5, -2.0, 7.0), 1e-9), std::vector<Index>{0});
        EXPECT_EQ(bins.within(Vector<3>(0.6, -2.0, 7.0), 0.11), std::vector<Index>{0});
        EXPECT_TRUE(bins.within(Vector<3>(0.6, -2.0, 7.0), 0.09).empty());
        EXPECT_EQ(bins.within(Vector<3>(100.0, 100.0, 100.0), 1e3), std::vector<Index>{0});
    }
}

TEST(CellBins, NoParticlesAndNonFiniteQueriesFindNothing) {
    CellBins<2> bins;
    bins.bin({}, 0.1);
    EXPECT_EQ(bins.size(), 0u);
    EXPECT_TRUE(bins.within(Vector<2>(0, 0), 1.0).empty());
    bins.bin(test::randomCloud<2>(50, 7), 0.1);
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const double inf = std::numeric_limits<double>::infinity();
    EXPECT_TRUE(bins.within(Vector<2>(nan, 0.5), 1.0).empty());
    EXPECT_TRUE(bins.within(Vector<2>(0.5, 0.5), nan).empty());
    // An infinite radius is a valid question: everything.
    EXPECT_EQ(bins.within(Vector<2>(0.5, 0.5), inf).size(), 50u);
}

// Empty cells between two far groups: a query in the gap finds nothing, one at each group its own.
TEST(CellBins, EmptyCellsBetweenGroups) {
    std::vector<Vector<1>> x;
    for (int i = 0; i < 10; ++i) x.push_back(Vector<1>(0.01 * i));
    for (int i = 0; i < 10; ++i) x.push_back(Vector<1>(10.0 + 0.01 * i));
    CellBins<1> bins;
    bins.bin(x, 0.05);
    EXPECT_GT(bins.cellCount(), 100u);  // the gap is binned as empty cells, not skipped
    EXPECT_TRUE(bins.within(Vector<1>(5.0), 1.0).empty());
    EXPECT_EQ(bins.within(Vector<1>(0.045), 0.05).size(), 10u);
    EXPECT_EQ(bins.within(Vector<1>(10.045), 0.05).size(), 10u);
    EXPECT_TRUE(bins.particlesOf(bins.cellOf(Vector<1>(5.0))).empty());
}

TEST(CellBins, CellsAreNeverNarrowerThanAsked) {
    const auto cloud = test::randomCloud<3>(300, 8);
    CellBins<3> bins;
    bins.bin(cloud, 0.07);
    for (int d = 0; d < 3; ++d) EXPECT_GE(bins.width(d), 0.07);
    // A tiny width over many particles' box is coarsened to at most 32 cells per particle.
    bins.bin(cloud, 1e-6);
    EXPECT_LE(double(bins.cellCount()), 32.0 * 300);
    expectConsistentBinning(bins, cloud);
}

TEST(CellBins, BadInputIsRefused) {
    CellBins<2> bins;
    const double nan = std::numeric_limits<double>::quiet_NaN();
    EXPECT_THROW(bins.bin({Vector<2>(0, 0), Vector<2>(nan, 1)}, 0.1), Error);
    EXPECT_THROW(bins.bin({Vector<2>(0, 0)}, -1.0), Error);
    EXPECT_THROW(bins.bin({Vector<2>(0, 0)}, nan), Error);
    EXPECT_THROW(CellBins<2>({}, 0.0), Error);
}

// The neighbour search's cells are these bins: a point query at a particle with its radius gives
// its gather row.
TEST(CellBins, NeighbourSearchExposesItsBins) {
    const auto cloud = test::randomCloud<3>(600, 9);
    NeighbourSearchOptions options;
    options.criterion = PairCriterion::gather;
    options.includeSelf = true;
    options.sortRows = true;
    NeighbourSearch<3> search({}, options);
    const NeighbourList list = search.build(cloud, 0.15);
    for (std::size_t i = 0; i < cloud.size(); ++i) {
        const auto row = list[i];
        EXPECT_EQ(sorted<3>(search.bins().within(cloud[i], 0.15)), std::vector<Index>(row.begin(), row.end()))
            << "particle " << i;
    }
}

}  // namespace
}  // namespace mfdyn
