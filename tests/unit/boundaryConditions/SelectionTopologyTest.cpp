// Selections told that particles came and went (ParticleSetBase::append/keep, issue 15): a kept
// particle keeps its selection by global id, a removed one drops out, an appended one is judged
// by the criteria, and ghosts are never selected.
#include "BoundaryConditionTestTools.hpp"
#include "boundaryConditions/Selection.hpp"

#include <gtest/gtest.h>

using namespace mfdyn;
using mfdyn::test::lattice;

namespace {

template <int Dim>
Selection<Dim> selection(const std::string& text, const ParticleSet<Dim>& p) {
    return Selection<Dim>(Dictionary::parse(text, "constant/boundaryConditions"), p, false);
}

template <int Dim>
std::vector<std::int64_t> selectedIds(const Selection<Dim>& s, const ParticleSet<Dim>& p) {
    std::vector<std::int64_t> ids;
    for (auto i : s.indices()) ids.push_back(p.globalId()[i]);
    return ids;
}

}  // namespace

TEST(SelectionTopology, KeptParticlesKeepTheirSelectionByGlobalId) {
    auto p = lattice<2>(4, 0.1);  // 16 particles, ids 100..115; wall: the rows y = 0, 0.1
    auto wall = selection<2>("regions (wall);", p);
    ASSERT_EQ(selectedIds(wall, p), (std::vector<std::int64_t>{100, 101, 102, 103, 104, 105, 106, 107}));
    EXPECT_FALSE(wall.refresh(p)) << "nothing changed: nothing to do";

    // Drop every other particle, then move one kept wall particle out of the wall's rows and
    // into region fluid: it stays selected (identity, not criteria, for particles already there).
    std::vector<std::size_t> even;
    for (std::size_t i = 0; i < p.size(); i += 2) even.push_back(i);
    p.keep(even);
    p.region()[0] = 0;
    EXPECT_TRUE(wall.refresh(p));
    EXPECT_EQ(selectedIds(wall, p), (std::vector<std::int64_t>{100, 102, 104, 106}));
    for (auto i : wall.indices()) EXPECT_LT(i, p.size());
}

TEST(SelectionTopology, AppendedParticlesAreJudgedByTheCriteria) {
    auto p = lattice<2>(4, 0.1);
    auto wall = selection<2>("regions (wall);", p);
    auto box = selection<2>("shape { type box; min (-1 -1); max (0.05 1); }", p);  // the column x = 0
    auto all = selection<2>("all yes;", p);
    const std::size_t first = p.append(2);
    p.region()[first] = 1;  // a new wall particle, at the origin (inside the box)
    p.position()[first + 1] = Vector<2>(0.35, 0.35);
    EXPECT_TRUE(wall.refresh(p));
    EXPECT_TRUE(box.refresh(p));
    EXPECT_TRUE(all.refresh(p));
    EXPECT_EQ(wall.size(), 9u);
    EXPECT_EQ(selectedIds(wall, p).back(), 116) << "the new particle of region wall joins";
    EXPECT_EQ(box.size(), 5u) << "four of the column and the new one at the origin";
    EXPECT_EQ(all.size(), 18u);
    // An old particle that moved into the box does not join it (its selection is by id).
    p.position()[3] = Vector<2>(0.01, 0.05);
    p.reorder({17, 16, 15, 14, 13, 12, 11, 10, 9, 8, 7, 6, 5, 4, 3, 2, 1, 0});
    EXPECT_TRUE(box.refresh(p));
    EXPECT_EQ(box.size(), 5u);
}

TEST(SelectionTopology, GhostsAreNeverSelected) {
    auto p = lattice<2>(3, 0.1);
    auto all = selection<2>("all yes;", p);
    auto wall = selection<2>("regions (wall);", p);
    p.addGhosts({0, 1, 2}, std::vector<Tensor<2>>(3, Tensor<2>::Identity()));
    EXPECT_TRUE(all.refresh(p));
    EXPECT_TRUE(wall.refresh(p));
    EXPECT_EQ(all.size(), 9u) << "the owned particles only";
    EXPECT_EQ(wall.size(), 6u) << "the ghosts copy their sources' region and id, and are still no wall";
    all.resolve(p);
    EXPECT_EQ(all.size(), 9u);
}
