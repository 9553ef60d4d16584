// Selections by region name, by shape, both, and all; refreshed after reordering (by globalId)
// and re-evaluated with `reselect yes`.
#include "BoundaryConditionTestTools.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <numeric>

using namespace mfdyn;
using mfdyn::test::condition;
using mfdyn::test::inputErrorOf;
using mfdyn::test::lattice;

TEST(Selection, ByRegionNameIsExactlyThatRegion) {
    const auto p = lattice<2>();
    const auto bc = condition<2>("type fixed; regions (wall);", p);
    const auto& idx = bc->selection().indices();
    EXPECT_EQ(idx.size(), 22u);  // two rows of 11 with y < 0.15
    EXPECT_TRUE(std::is_sorted(idx.begin(), idx.end()));
    std::size_t inWall = 0;
    for (std::size_t i = 0; i < p.size(); ++i) inWall += p.region()[i] == 1;
    EXPECT_EQ(inWall, idx.size());
    for (auto i : idx) EXPECT_EQ(p.region()[i], 1);
}

TEST(Selection, SeveralRegionsAreTheirUnion) {
    const auto p = lattice<2>();
    EXPECT_EQ(condition<2>("type fixed; regions (wall fluid);", p)->selection().size(), p.size());
}

TEST(Selection, ByShapeIsThePointsInside) {
    const auto p = lattice<3>(6, 0.1, 0.5);  // x = 0.05 ... 0.55 per axis
    const auto bc = condition<3>("type fixed; shape { type box; min (0 0 0); max (0.2 0.3 1); }", p);
    // Inside: two values of x (0.05, 0.15), three of y (0.05 ... 0.25), all six of z.
    EXPECT_EQ(bc->selection().size(), 2u * 3u * 6u);
    for (auto i : bc->selection().indices()) {
        EXPECT_LT(p.position()[i][0], 0.2);
        EXPECT_LT(p.position()[i][1], 0.3);
    }
}

TEST(Selection, RegionsAndShapeTogetherAreTheIntersection) {
    const auto p = lattice<2>();
    const auto bc =
        condition<2>("type fixed; regions (wall); shape { type box; min (-1 -1); max (0.45 1); }", p);
    EXPECT_EQ(bc->selection().size(), 2u * 5u);  // wall rows y = 0, 0.1; x = 0 ... 0.4
    for (auto i : bc->selection().indices()) {
        EXPECT_EQ(p.region()[i], 1);
        EXPECT_LT(p.position()[i][0], 0.45);
    }
}

TEST(Selection, AllAndPlaneDefaults) {
    const auto p = lattice<2>();
    EXPECT_EQ(condition<2>("type fixed; all yes;", p)->selection().size(), p.size());
    EXPECT_TRUE(condition<2>("type symmetryPlane; point (0 0); normal (1 0);", p)->selection().selectsAll());
}

// A fixed condition with no selection would freeze the whole body: an input error, not a default.
TEST(Selection, FixedWithoutSelectionIsAnInputError) {
    const auto p = lattice<2>();
    const std::string message = inputErrorOf([&] { condition<2>("type fixed;", p); });
    EXPECT_NE(message.find("regions"), std::string::npos) << message;
    EXPECT_THROW(condition<2>("type fixed; all yes; regions (wall);", p), InputError);
}

TEST(Selection, UnknownRegionListsTheRegions) {
    const auto p = lattice<2>();
    const std::string message = inputErrorOf([&] { condition<2>("type fixed; regions (wal);", p); });
    ASSERT_FALSE(message.empty());
    EXPECT_NE(message.find("'wal'"), std::string::npos) << message;
    EXPECT_NE(message.find("did you mean 'wall'"), std::string::npos) << message;
    EXPECT_NE(message.find("fluid, wall"), std::string::npos) << message;
    EXPECT_NE(message.find("boundaryConditions/test"), std::string::npos) << message;
}

TEST(Selection, UnknownShapeTypeIsAnInputError) {
    const auto p = lattice<2>();
    EXPECT_THROW(condition<2>("type fixed; shape { type boxx; min (0 0); max (1 1); }", p), InputError);
}

// After the solver reorders particles (cell sorting) the same particles are found again by
// globalId.
TEST(Selection, UpdateAfterReorderKeepsTheSameParticles) {
    auto p = lattice<2>();
    auto bc = condition<2>("type fixed; shape { type box; min (0.25 0.25); max (0.55 0.75); }", p);
    std::vector<std::int64_t> before;
    for (auto i : bc->selection().indices()) before.push_back(p.globalId()[i]);
    std::vector<std::size_t> order(p.size());
    std::iota(order.rbegin(), order.rend(), std::size_t(0));
    p.reorder(order);
    // Moving the particles must not change who is selected without `reselect`.
    for (auto& x : p.position()) x[0] += 10.0;
    bc->updateSelection(p);
    std::vector<std::int64_t> after;
    for (auto i : bc->selection().indices()) after.push_back(p.globalId()[i]);
    std::sort(before.begin(), before.end());
    std::sort(after.begin(), after.end());
    EXPECT_EQ(before, after);
    EXPECT_EQ(after.size(), 3u * 5u);
}

TEST(Selection, ReselectEvaluatesTheShapeAgain) {
    auto p = lattice<2>();
    auto bc = condition<2>("type fixed; reselect yes; shape { type box; min (-1 -1); max (0.05 2); }", p);
    EXPECT_EQ(bc->selection().size(), 11u);    // the column x = 0
    for (auto& x : p.position()) x[0] -= 0.1;  // now x = -0.1 and 0 are in
    bc->updateSelection(p);
    EXPECT_EQ(bc->selection().size(), 22u);
}
