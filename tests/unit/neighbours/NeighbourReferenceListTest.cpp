// NeighbourReferenceList: the list of the reference configuration, kept while particles move.
#include "NeighbourTestClouds.hpp"
#include "particles/NeighbourReferenceList.hpp"

#include <gtest/gtest.h>

namespace mfdyn::test {
namespace {

TEST(NeighbourReferenceList, KeepsTheReferencePairsAndSeparations) {
    const std::size_t n = 1000;
    const auto x = randomCloud<2>(n, 41);
    const auto r = variableRadii(n, 0.06, 42);
    const NeighbourDomain<2> domain(Vector<2>::Zero(), Vector<2>::Ones(), {true, false});
    const NeighbourReferenceList<2> reference(x, r, domain);
    EXPECT_EQ(sortedRows(reference.list()), bruteForce(domain, x, r, PairCriterion::either, false));

    EXPECT_EQ(reference.size(), n);
    EXPECT_EQ(reference.referencePositions(), x);
    for (std::size_t i = 0; i < n; i += 50)
        for (auto j : reference.list()[i])
            ASSERT_EQ(reference.referenceSeparation(i, j), domain.separation(x[i], x[j]));
}

TEST(NeighbourReferenceList, ConstantRadiusAndCriterion) {
    const auto x = latticeCloud<3>(8, 1.0);
    NeighbourSearchOptions options;
    options.criterion = PairCriterion::gather;
    options.includeSelf = true;
    const NeighbourReferenceList<3> reference(x, 1.01, {}, options);
    // Self and the face neighbours: 7 inside the lattice, 4 at a corner.
    EXPECT_EQ(reference.list().maxRowSize(), 7u);
    EXPECT_EQ(reference.list().rowSize(0), 4u);
}

}  // namespace
}  // namespace mfdyn::test
