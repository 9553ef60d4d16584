// NeighbourSearch against a brute-force search over all pairs: exact equality of every row, for
// the three pair criteria, with and without self, on random, lattice and clustered clouds with
// variable radii, in 1, 2 and 3 dimensions, open and periodic.
#include "NeighbourTestClouds.hpp"

#include <gtest/gtest.h>
#include <omp.h>

#include <cmath>
#include <numbers>
#include <numeric>
#include <type_traits>

namespace mfdyn::test {
namespace {

constexpr PairCriterion allCriteria[] = {PairCriterion::either, PairCriterion::both, PairCriterion::gather};

const char* name(PairCriterion c) {
    return c == PairCriterion::either ? "either" : c == PairCriterion::both ? "both" : "gather";
}

// The radius at which a uniform cloud of n points in a unit box has `count` neighbours on average.
template <int Dim>
double radiusFor(std::size_t n, double count) {
    const double ball = Dim == 1 ? 2.0 : Dim == 2 ? std::numbers::pi : 4.0 / 3.0 * std::numbers::pi;
    return std::pow(count / (double(n) * ball), 1.0 / Dim);
}

template <int Dim>
void expectMatchesBruteForce(const NeighbourDomain<Dim>& domain, const std::vector<Vector<Dim>>& x,
                             const std::vector<double>& r, int cellsPerRadius = 2) {
    for (PairCriterion criterion : allCriteria)
        for (bool self : {false, true})
            for (bool sortRows : {true, false}) {
                SCOPED_TRACE(std::string(name(criterion)) + (self ? " with self" : "") +
                             (sortRows ? " sorted" : " cell order") + " cellsPerRadius " +
                             std::to_string(cellsPerRadius));
                NeighbourSearchOptions options;
                options.criterion = criterion;
                options.includeSelf = self;
                options.sortRows = sortRows;
                options.cellsPerRadius = cellsPerRadius;
                NeighbourSearch<Dim> search(domain, options);
                const NeighbourList list = search.build(x, r);
                const Rows expected = bruteForce(domain, x, r, criterion, self);
                ASSERT_EQ(list.size(), x.size());
                EXPECT_EQ(sortedRows(list), expected);
                if (sortRows) {
                    for (std::size_t i = 0; i < list.size(); ++i) {
                        ASSERT_TRUE(std::is_sorted(list[i].begin(), list[i].end()));
                    }
                }
                if (criterion != PairCriterion::gather) {
                    EXPECT_TRUE(list.symmetric());
                }
            }
}

template <class T>
class NeighbourSearchDim : public ::testing::Test {};
using Dims = ::testing::Types<std::integral_constant<int, 1>, std::integral_constant<int, 2>,
                              std::integral_constant<int, 3>>;
TYPED_TEST_SUITE(NeighbourSearchDim, Dims);

TYPED_TEST(NeighbourSearchDim, RandomCloudMatchesBruteForce) {
    constexpr int Dim = TypeParam::value;
    const std::size_t n = 1500;
    const auto x = randomCloud<Dim>(n, 11);
    const auto r = variableRadii(n, radiusFor<Dim>(n, 25), 12);
    expectMatchesBruteForce<Dim>({}, x, r);
    EXPECT_GT(meanRowSize(bruteForce<Dim>({}, x, r, PairCriterion::both, false)), 5u);
}

TYPED_TEST(NeighbourSearchDim, LatticeMatchesBruteForce) {
    constexpr int Dim = TypeParam::value;
    const int perSide = Dim == 1 ? 1500 : Dim == 2 ? 40 : 12;
    const auto x = latticeCloud<Dim>(perSide, 0.1);
    const auto r = variableRadii(x.size(), 0.23, 13);
    for (int cellsPerRadius : {1, 2, 3}) expectMatchesBruteForce<Dim>({}, x, r, cellsPerRadius);
}

TYPED_TEST(NeighbourSearchDim, ClusteredCloudMatchesBruteForceAndKeepsTheGridSmall) {
    constexpr int Dim = TypeParam::value;
    const std::size_t n = 1500;
    const auto x = clusteredCloud<Dim>(n, 14);
    const auto r = variableRadii(n, 0.01, 15);
    expectMatchesBruteForce<Dim>({}, x, r);
    // Far outliers make the box 1e5 radii wide: the grid is coarsened to the cap of cells per
    // particle (maxCellsPerParticle) instead of filling memory with empty cells.
    NeighbourSearch<Dim> search;
    search.bin(x, r);
    EXPECT_LE(double(search.cellCount()), NeighbourSearchOptions{}.maxCellsPerParticle * double(n));
    EXPECT_GT(meanRowSize(bruteForce<Dim>({}, x, r, PairCriterion::both, false)), 3u);
}

TYPED_TEST(NeighbourSearchDim, GivenBoxWithParticlesOutsideMatchesBruteForce) {
    constexpr int Dim = TypeParam::value;
    const std::size_t n = 1200;
    const auto x = randomCloud<Dim>(n, 16, -0.3, 1.3);
    const auto r = variableRadii(n, radiusFor<Dim>(n, 20), 17);
    const NeighbourDomain<Dim> box(Vector<Dim>::Zero(), Vector<Dim>::Ones());
    expectMatchesBruteForce<Dim>(box, x, r);
}

TYPED_TEST(NeighbourSearchDim, PeriodicMatchesMinimumImageBruteForce) {
    constexpr int Dim = TypeParam::value;
    const std::size_t n = 1500;
    // Particles up to half a period outside the box are images of particles inside it.
    const auto x = randomCloud<Dim>(n, 18, -1.5, 2.5);
    const auto r = variableRadii(n, 3 * radiusFor<Dim>(n, 25), 19);
    const Vector<Dim> lo = Vector<Dim>::Constant(-1.0), hi = Vector<Dim>::Constant(2.0);
    std::array<bool, Dim> all;
    all.fill(true);
    expectMatchesBruteForce<Dim>(NeighbourDomain<Dim>(lo, hi, all), x, r);
    if constexpr (Dim > 1) {
        std::array<bool, Dim> firstOnly{};
        firstOnly[0] = true;
        expectMatchesBruteForce<Dim>(NeighbourDomain<Dim>(lo, hi, firstOnly), x, r);
        std::array<bool, Dim> lastOnly{};
        lastOnly[Dim - 1] = true;
        expectMatchesBruteForce<Dim>(NeighbourDomain<Dim>(lo, hi, lastOnly), x, r);
    }
}

// Radii close to half the period leave one, two or three cells across the box, where a query
// box wraps onto itself.
TYPED_TEST(NeighbourSearchDim, SmallPeriodicBoxMatchesBruteForce) {
    constexpr int Dim = TypeParam::value;
    const std::size_t n = Dim == 1 ? 60 : 300;
    const auto x = randomCloud<Dim>(n, 20);
    std::array<bool, Dim> all;
    all.fill(true);
    const NeighbourDomain<Dim> torus(Vector<Dim>::Zero(), Vector<Dim>::Ones(), all);
    for (double rmax : {0.5, 0.45, 0.34, 0.26}) {
        std::vector<double> r = variableRadii(n, rmax / 1.5, 21);
        r[0] = rmax;
        for (int cellsPerRadius : {1, 2, 3}) expectMatchesBruteForce<Dim>(torus, x, r, cellsPerRadius);
    }
}

TYPED_TEST(NeighbourSearchDim, ConstantRadiusEqualsUniformRadii) {
    constexpr int Dim = TypeParam::value;
    const std::size_t n = 2000;
    const auto x = randomCloud<Dim>(n, 22);
    const double radius = radiusFor<Dim>(n, 30);
    for (PairCriterion criterion : allCriteria) {
        NeighbourSearchOptions options;
        options.criterion = criterion;
        NeighbourSearch<Dim> search({}, options);
        EXPECT_EQ(search.build(x, radius), search.build(x, std::vector<double>(n, radius)));
    }
}

TYPED_TEST(NeighbourSearchDim, OrderSortsByCellAndReorderedParticlesGiveThePermutedList) {
    constexpr int Dim = TypeParam::value;
    const std::size_t n = 3000;
    const auto x = randomCloud<Dim>(n, 23);
    const auto r = variableRadii(n, radiusFor<Dim>(n, 20), 24);
    NeighbourSearch<Dim> search;
    const NeighbourList list = search.build(x, r);
    std::vector<NeighbourList::Index> order = search.order();

    std::vector<NeighbourList::Index> sorted = order;
    std::sort(sorted.begin(), sorted.end());
    std::vector<NeighbourList::Index> identity(n);
    std::iota(identity.begin(), identity.end(), 0);
    ASSERT_EQ(sorted, identity);

    // Apply the permutation to positions, radii and a field of width 2.
    auto xs = x;
    auto rs = r;
    std::vector<double> field(2 * n);
    for (std::size_t i = 0; i < n; ++i) field[2 * i] = double(i), field[2 * i + 1] = -double(i);
    search.applyOrder(xs);
    search.applyOrder(rs);
    search.applyOrder(field, 2);
    for (std::size_t k = 0; k < n; ++k) {
        ASSERT_EQ(xs[k], x[order[k]]);
        ASSERT_EQ(field[2 * k], double(order[k]));
        ASSERT_EQ(field[2 * k + 1], -double(order[k]));
    }
    EXPECT_THROW(search.applyOrder(field, 3), Error);

    // Binning reordered particles again is the identity, and the list is the old one renumbered.
    const NeighbourList reordered = search.build(xs, rs);
    EXPECT_EQ(search.order(), identity);
    std::vector<NeighbourList::Index> rank(n);
    for (std::size_t k = 0; k < n; ++k) rank[order[k]] = NeighbourList::Index(k);
    for (std::size_t k = 0; k < n; ++k) {
        std::vector<NeighbourList::Index> renumbered;
        for (auto j : list[order[k]]) renumbered.push_back(rank[j]);
        std::sort(renumbered.begin(), renumbered.end());
        ASSERT_EQ(std::vector<NeighbourList::Index>(reordered[k].begin(), reordered[k].end()), renumbered);
    }
    // On cell-ordered particles the rows come out in index order without sorting.
    NeighbourSearchOptions unsortedRows;
    unsortedRows.sortRows = false;
    NeighbourSearch<Dim> cellOrder({}, unsortedRows);
    EXPECT_EQ(cellOrder.build(xs, rs), reordered);
}

TYPED_TEST(NeighbourSearchDim, ListsAreBitIdenticalForAnyThreadCount) {
    constexpr int Dim = TypeParam::value;
    const std::size_t n = 20000;
    const auto x = randomCloud<Dim>(n, 25, -0.2, 1.2);
    const auto r = variableRadii(n, radiusFor<Dim>(n, 40), 26);
    std::array<bool, Dim> periodic{};
    periodic[0] = true;
    const NeighbourDomain<Dim> domains[] = {{}, {Vector<Dim>::Zero(), Vector<Dim>::Ones(), periodic}};
    const int threadsBefore = omp_get_max_threads();
    for (const auto& domain : domains)
        for (PairCriterion criterion : allCriteria)
            for (bool sortRows : {true, false}) {
                NeighbourSearchOptions options;
                options.criterion = criterion;
                options.sortRows = sortRows;
                std::vector<NeighbourList> lists;
                std::vector<std::vector<NeighbourList::Index>> orders;
                for (int threads : {1, 2, 3}) {
                    omp_set_num_threads(threads);
                    NeighbourSearch<Dim> search(domain, options);
                    lists.push_back(search.build(x, r));
                    orders.push_back(search.order());
                }
                EXPECT_EQ(lists[0], lists[1]);
                EXPECT_EQ(lists[0], lists[2]);
                EXPECT_EQ(orders[0], orders[1]);
                EXPECT_EQ(orders[0], orders[2]);
                EXPECT_GT(lists[0].pairCount(), 5 * n);
            }
    omp_set_num_threads(threadsBefore);
}

// The half stencil (each pair tested from its lower place, rows assembled from the forward
// halves) gives the full stencil's list entry for entry, in the same order: the solvers' sums
// run over the rows in that order, so a different one would change their last bits.
TYPED_TEST(NeighbourSearchDim, HalfStencilEqualsTheFullStencilInOrder) {
    constexpr int Dim = TypeParam::value;
    const std::size_t n = 1500;
    struct Cloud {
        std::vector<Vector<Dim>> x;
        NeighbourDomain<Dim> domain;
        double radius;
    };
    const std::vector<Cloud> clouds = {{randomCloud<Dim>(n, 41), {}, radiusFor<Dim>(n, 25)},
                                       {clusteredCloud<Dim>(n, 42), {}, 0.01},
                                       {randomCloud<Dim>(n, 43, -0.3, 1.3),
                                        {Vector<Dim>::Zero(), Vector<Dim>::Ones()},
                                        radiusFor<Dim>(n, 20)},
                                       {latticeCloud<Dim>(Dim == 1   ? 1500
                                                          : Dim == 2 ? 40
                                                                     : 12,
                                                          0.1),
                                        {},
                                        0.23}};
    int halfBuilds = 0;
    for (const Cloud& cloud : clouds) {
        const auto r = variableRadii(cloud.x.size(), cloud.radius, 44);
        for (PairCriterion criterion : allCriteria)
            for (bool self : {false, true})
                for (int cellsPerRadius : {1, 2, 3})
                    for (bool constant : {false, true}) {
                        SCOPED_TRACE(std::string(name(criterion)) + (self ? " with self" : "") +
                                     " cellsPerRadius " + std::to_string(cellsPerRadius) +
                                     (constant ? " constant" : " variable"));
                        NeighbourSearchOptions options;
                        options.criterion = criterion;
                        options.includeSelf = self;
                        options.cellsPerRadius = cellsPerRadius;
                        NeighbourSearchOptions full = options;
                        full.halfStencil = false;
                        NeighbourSearch<Dim> a(cloud.domain, options), b(cloud.domain, full);
                        const NeighbourList half =
                            constant ? a.build(cloud.x, cloud.radius) : a.build(cloud.x, r);
                        const NeighbourList whole =
                            constant ? b.build(cloud.x, cloud.radius) : b.build(cloud.x, r);
                        ASSERT_EQ(half, whole);
                        halfBuilds += constant || criterion != PairCriterion::gather;
                        EXPECT_GT(half.pairCount(), cloud.x.size());
                    }
    }
    EXPECT_EQ(halfBuilds, 4 * 3 * 2 * 3 * 2 - 4 * 2 * 3);  // every build but variable-radius gather
}

// A list refilled into a previous list's memory is the list built afresh, whether that memory was
// larger or smaller than needed.
TYPED_TEST(NeighbourSearchDim, ListIntoPreviousStorageEqualsAFreshList) {
    constexpr int Dim = TypeParam::value;
    const std::size_t n = 1500;
    const auto x = randomCloud<Dim>(n, 45);
    NeighbourSearch<Dim> search;
    const NeighbourList small = search.build(x, radiusFor<Dim>(n, 10));
    const NeighbourList large = search.build(x, radiusFor<Dim>(n, 40));
    NeighbourList previous = large;
    search.bin(x, radiusFor<Dim>(n, 10));
    previous = search.list(std::move(previous));
    EXPECT_EQ(previous, small);
    search.bin(x, radiusFor<Dim>(n, 40));
    EXPECT_EQ(search.list(std::move(previous)), large);
}

TYPED_TEST(NeighbourSearchDim, EmptyAndSingleParticle) {
    constexpr int Dim = TypeParam::value;
    NeighbourSearch<Dim> search;
    EXPECT_EQ(search.build({}, 1.0).size(), 0u);
    const std::vector<Vector<Dim>> one(1, Vector<Dim>::Constant(3.0));
    EXPECT_EQ(search.build(one, 1.0).pairCount(), 0u);
    NeighbourSearchOptions withSelf;
    withSelf.includeSelf = true;
    NeighbourSearch<Dim> selfSearch({}, withSelf);
    const NeighbourList list = selfSearch.build(one, 0.0);
    ASSERT_EQ(list.pairCount(), 1u);
    EXPECT_EQ(list[0][0], 0u);
}

TYPED_TEST(NeighbourSearchDim, RejectsBadInput) {
    constexpr int Dim = TypeParam::value;
    auto x = randomCloud<Dim>(10, 27);
    NeighbourSearch<Dim> search;
    EXPECT_THROW(search.bin(x, std::vector<double>(9, 0.1)), Error);
    EXPECT_THROW(search.bin(x, -0.1), Error);
    EXPECT_THROW(search.bin(x, std::nan("")), Error);
    std::vector<double> r(10, 0.1);
    r[3] = -1;
    EXPECT_THROW(search.bin(x, r), Error);
    x[5][0] = std::nan("");
    EXPECT_THROW(search.bin(x, 0.1), Error);

    std::array<bool, Dim> all;
    all.fill(true);
    NeighbourSearch<Dim> torus(NeighbourDomain<Dim>(Vector<Dim>::Zero(), Vector<Dim>::Ones(), all));
    EXPECT_THROW(torus.bin(randomCloud<Dim>(10, 28), 0.51), Error);
    EXPECT_NO_THROW(torus.bin(randomCloud<Dim>(10, 28), 0.5));
    EXPECT_THROW(NeighbourDomain<Dim>(Vector<Dim>::Ones(), Vector<Dim>::Zero()), Error);
    NeighbourSearchOptions badCells;
    badCells.cellsPerRadius = 0;
    EXPECT_THROW(NeighbourSearch<Dim>({}, badCells), Error);
}

TEST(NeighbourDomain, SeparationIsTheMinimumImageAndAntisymmetric) {
    const NeighbourDomain<3> domain(Vector<3>(0, 0, 0), Vector<3>(1, 2, 4), {true, false, true});
    const Vector<3> a(0.05, 0.1, 3.9), b(0.95, 1.9, 0.2);
    const Vector<3> d = domain.separation(a, b);
    EXPECT_NEAR(d[0], 0.1, 1e-15);
    EXPECT_NEAR(d[1], -1.8, 1e-15);
    EXPECT_NEAR(d[2], -0.3, 1e-15);
    EXPECT_EQ(domain.separation(b, a), Vector<3>(-d));
    const Vector<3> w = domain.wrap(Vector<3>(-0.25, 7.0, 9.0));
    EXPECT_NEAR(w[0], 0.75, 1e-15);
    EXPECT_EQ(w[1], 7.0);
    EXPECT_NEAR(w[2], 1.0, 1e-15);
}

TEST(NeighbourList, RejectsInconsistentOffsets) {
    EXPECT_THROW(NeighbourList({0, 2}, {1}), Error);
    EXPECT_THROW(NeighbourList({1, 1}, {1}), Error);
    EXPECT_NO_THROW(NeighbourList({0, 1, 1}, {1}));
    const NeighbourList asymmetric({0, 1, 1}, {1});
    EXPECT_FALSE(asymmetric.symmetric());
    EXPECT_EQ(asymmetric.maxRowSize(), 1u);
}

}  // namespace
}  // namespace mfdyn::test
