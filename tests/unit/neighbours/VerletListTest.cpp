// VerletList: when it rebuilds, and that its candidates always contain the true neighbours.
#include "NeighbourTestClouds.hpp"
#include "particles/VerletList.hpp"

#include <gtest/gtest.h>

#include <random>

namespace mfdyn::test {
namespace {

// Every true neighbour (brute force, radius r) is among the candidates of its row.
template <int Dim>
void expectCandidatesContainNeighbours(const VerletList<Dim>& verlet, const NeighbourDomain<Dim>& domain,
                                       const std::vector<Vector<Dim>>& x, const std::vector<double>& r,
                                       PairCriterion criterion) {
    const Rows truth = bruteForce(domain, x, r, criterion, false);
    const Rows candidates = sortedRows(verlet.candidates());
    ASSERT_EQ(candidates.size(), truth.size());
    for (std::size_t i = 0; i < truth.size(); ++i)
        ASSERT_TRUE(
            std::includes(candidates[i].begin(), candidates[i].end(), truth[i].begin(), truth[i].end()))
            << "row " << i;
}

TEST(VerletList, NoRebuildUnderHalfTheSkinAndRebuildPastIt) {
    const std::size_t n = 500;
    auto x = randomCloud<3>(n, 31);
    const double radius = 0.15, skin = 0.04;
    VerletList<3> verlet(skin);
    EXPECT_TRUE(verlet.update(x, radius));
    EXPECT_EQ(verlet.rebuildCount(), 1u);
    const NeighbourList first = verlet.candidates();

    // Every particle moves by just under half the skin: the list stands.
    std::mt19937_64 rng(32);
    std::normal_distribution<double> g(0.0, 1.0);
    auto moved = x;
    for (auto& p : moved) {
        Vector<3> dir(g(rng), g(rng), g(rng));
        p += 0.499 * skin * dir.normalized();
    }
    EXPECT_FALSE(verlet.update(moved, radius));
    EXPECT_EQ(verlet.rebuildCount(), 1u);
    EXPECT_EQ(verlet.candidates(), first);
    EXPECT_NEAR(verlet.maxDisplacement(moved), 0.499 * skin, 1e-12);

    // One particle past half the skin: rebuilt.
    moved[123] = x[123] + Vector<3>(0, 0.51 * skin, 0);
    EXPECT_TRUE(verlet.update(moved, radius));
    EXPECT_EQ(verlet.rebuildCount(), 2u);
    EXPECT_EQ(verlet.maxDisplacement(moved), 0.0);
    EXPECT_FALSE(verlet.update(moved, radius));

    // A changed particle count or an explicit invalidation rebuilds.
    moved.pop_back();
    EXPECT_TRUE(verlet.update(moved, radius));
    verlet.invalidate();
    EXPECT_TRUE(verlet.update(moved, radius));
    EXPECT_EQ(verlet.rebuildCount(), 4u);
}

TEST(VerletList, GrowingRadiiUseUpTheSkin) {
    const std::size_t n = 400;
    const auto x = randomCloud<2>(n, 33);
    auto r = variableRadii(n, 0.05, 34);
    VerletList<2> verlet(0.02);
    EXPECT_TRUE(verlet.update(x, r));
    r[7] += 0.019;
    EXPECT_FALSE(verlet.update(x, r));
    r[7] += 0.002;
    EXPECT_TRUE(verlet.update(x, r));
}

TEST(VerletList, CandidatesContainTheNeighboursThroughAMotion) {
    for (PairCriterion criterion : {PairCriterion::either, PairCriterion::both, PairCriterion::gather})
        for (bool periodic : {false, true}) {
            SCOPED_TRACE(std::string(periodic ? "periodic " : "open ") + std::to_string(int(criterion)));
            const std::size_t n = 800;
            auto x = randomCloud<3>(n, 35);
            auto r = variableRadii(n, 0.1, 36);
            const NeighbourDomain<3> domain =
                periodic ? NeighbourDomain<3>(Vector<3>::Zero(), Vector<3>::Ones(), {true, true, true})
                         : NeighbourDomain<3>();
            NeighbourSearchOptions options;
            options.criterion = criterion;
            const double skin = 0.03;
            VerletList<3> verlet(skin, domain, options);

            // A shear flow with noise and slowly breathing radii; periodic particles are wrapped
            // into the box, so some jump by a period between steps.
            std::mt19937_64 rng(37);
            std::normal_distribution<double> g(0.0, 1.0);
            int rebuilds = 0;
            for (int step = 0; step < 60; ++step) {
                rebuilds += verlet.update(x, r);
                expectCandidatesContainNeighbours(verlet, domain, x, r, criterion);
                for (std::size_t i = 0; i < n; ++i) {
                    x[i] += Vector<3>(0.002 * std::sin(6.0 * x[i][1]), 0.001 * g(rng), 0.001 * g(rng));
                    if (periodic) x[i] = domain.wrap(x[i]);
                    r[i] *= 1.0 + 0.002 * std::sin(0.1 * step + double(i));
                }
            }
            EXPECT_GT(rebuilds, 2);
            EXPECT_LT(rebuilds, 40);
        }
}

TEST(VerletList, PeriodicWrapIsNotADisplacement) {
    const NeighbourDomain<1> domain(Vector<1>(0.0), Vector<1>(1.0), {true});
    std::vector<Vector<1>> x = {Vector<1>(0.999), Vector<1>(0.5)};
    VerletList<1> verlet(0.01, domain);
    EXPECT_TRUE(verlet.update(x, 0.1));
    x[0] = Vector<1>(0.001);
    EXPECT_NEAR(verlet.maxDisplacement(x), 0.002, 1e-12);
    EXPECT_FALSE(verlet.update(x, 0.1));
}

TEST(VerletList, RejectsBadSkin) {
    EXPECT_THROW(VerletList<2>(-1.0), Error);
    EXPECT_THROW(VerletList<2>(std::nan("")), Error);
}

}  // namespace
}  // namespace mfdyn::test
