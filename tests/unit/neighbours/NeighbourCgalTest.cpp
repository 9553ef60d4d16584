// NeighbourSearch against CGAL's kd-tree (fixed-radius Fuzzy_sphere queries, one per particle
// with its own radius) on open clouds: an independent implementation, at sizes brute force
// would make slow. This is the only translation unit of the tests that includes CGAL.
#include "NeighbourTestClouds.hpp"

#include <gtest/gtest.h>

#ifdef MFDYN_HAVE_CGAL
#include <CGAL/Epick_d.h>
#include <CGAL/Fuzzy_sphere.h>
#include <CGAL/Kd_tree.h>
#include <CGAL/Search_traits_adapter.h>
#include <CGAL/Search_traits_d.h>
#include <CGAL/property_map.h>
#include <boost/iterator/counting_iterator.hpp>
#endif

#include <type_traits>

namespace mfdyn::test {
namespace {

#ifdef MFDYN_HAVE_CGAL

// Row i: every j != i with |x_i - x_j| <= r_i, by CGAL. Its sphere test is <= where ours is <;
// the clouds below have random radii, so no distance equals a radius.
template <int Dim>
Rows cgalGather(const std::vector<Vector<Dim>>& x, const std::vector<double>& r) {
    using Kernel = CGAL::Epick_d<CGAL::Dimension_tag<Dim>>;
    using Point = typename Kernel::Point_d;
    using BaseTraits = CGAL::Search_traits_d<Kernel, CGAL::Dimension_tag<Dim>>;
    using PointMap = typename CGAL::Pointer_property_map<Point>::type;
    using Traits = CGAL::Search_traits_adapter<std::size_t, PointMap, BaseTraits>;
    using Tree = CGAL::Kd_tree<Traits>;
    using Sphere = CGAL::Fuzzy_sphere<Traits>;

    std::vector<Point> points;
    points.reserve(x.size());
    for (const auto& p : x) points.emplace_back(p.data(), p.data() + Dim);
    const PointMap map = CGAL::make_property_map(points);
    Tree tree(boost::counting_iterator<std::size_t>(0), boost::counting_iterator<std::size_t>(x.size()),
              typename Tree::Splitter(), Traits(map));
    tree.build();

    Rows rows(x.size());
    std::vector<std::size_t> found;
    for (std::size_t i = 0; i < x.size(); ++i) {
        found.clear();
        tree.search(std::back_inserter(found), Sphere(points[i], r[i], 0.0, Traits(map)));
        for (std::size_t j : found)
            if (j != i) rows[i].push_back(NeighbourList::Index(j));
        std::sort(rows[i].begin(), rows[i].end());
    }
    return rows;
}

// either = gather rows united with their transpose, both = intersected with it.
Rows combine(const Rows& gather, PairCriterion criterion) {
    if (criterion == PairCriterion::gather) return gather;
    Rows transpose(gather.size());
    for (std::size_t i = 0; i < gather.size(); ++i)
        for (auto j : gather[i]) transpose[j].push_back(NeighbourList::Index(i));
    Rows rows(gather.size());
    for (std::size_t i = 0; i < gather.size(); ++i) {
        if (criterion == PairCriterion::either)
            std::set_union(gather[i].begin(), gather[i].end(), transpose[i].begin(), transpose[i].end(),
                           std::back_inserter(rows[i]));
        else
            std::set_intersection(gather[i].begin(), gather[i].end(), transpose[i].begin(),
                                  transpose[i].end(), std::back_inserter(rows[i]));
    }
    return rows;
}

template <int Dim>
void expectMatchesCgal(const std::vector<Vector<Dim>>& x, const std::vector<double>& r) {
    const Rows gather = cgalGather(x, r);
    for (PairCriterion criterion : {PairCriterion::either, PairCriterion::both, PairCriterion::gather}) {
        SCOPED_TRACE(int(criterion));
        NeighbourSearchOptions options;
        options.criterion = criterion;
        NeighbourSearch<Dim> search({}, options);
        const Rows expected = combine(gather, criterion);
        EXPECT_EQ(sortedRows(search.build(x, r)), expected);
        EXPECT_GT(meanRowSize(expected), 3u);
    }
}

template <class T>
class NeighbourCgal : public ::testing::Test {};
using Dims = ::testing::Types<std::integral_constant<int, 1>, std::integral_constant<int, 2>,
                              std::integral_constant<int, 3>>;
TYPED_TEST_SUITE(NeighbourCgal, Dims);

TYPED_TEST(NeighbourCgal, RandomCloud) {
    constexpr int Dim = TypeParam::value;
    const std::size_t n = 20000;
    const double spacing = std::pow(1.0 / double(n), 1.0 / Dim);
    expectMatchesCgal<Dim>(randomCloud<Dim>(n, 51), variableRadii(n, 2.5 * spacing, 52));
}

TYPED_TEST(NeighbourCgal, Lattice) {
    constexpr int Dim = TypeParam::value;
    const int perSide = Dim == 1 ? 20000 : Dim == 2 ? 140 : 27;
    const auto x = latticeCloud<Dim>(perSide, 0.01);
    expectMatchesCgal<Dim>(x, variableRadii(x.size(), Dim == 1 ? 0.06 : 0.025, 53));
}

TYPED_TEST(NeighbourCgal, ClusteredCloud) {
    constexpr int Dim = TypeParam::value;
    const std::size_t n = 10000;
    expectMatchesCgal<Dim>(clusteredCloud<Dim>(n, 54), variableRadii(n,
                                                                     Dim == 1   ? 1e-4
                                                                     : Dim == 2 ? 0.002
                                                                                : 0.006,
                                                                     55));
}

#else

TEST(NeighbourCgal, NotAvailable) {
    GTEST_SKIP() << "built without CGAL";
}

#endif

}  // namespace
}  // namespace mfdyn::test
