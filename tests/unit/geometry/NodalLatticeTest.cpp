// The nodal lattice (doc/methods/tl-jst-sph.md 2.1): nodes on the faces, Δx = L/(n − 1), tributary volumes.
// Volumes are products and halvings of Δx (exact in binary) summed over up to 10^4 nodes, so Σ V
// matches |box| to round-off of the sum: 1e-12 relative. Coordinates on faces are exact by
// construction (the last node is placed at max itself), so they are compared with ==.
#include "GeometryTestUtils.hpp"
#include "geometry/NodalLattice.hpp"
#include "geometry/ParticleGenerator.hpp"
#include "particles/ParticleSet.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numeric>

using namespace mfdyn;
using mfdyn::test::lattice;
using mfdyn::test::shape;

namespace {

struct NodalFill {
    std::vector<double> points;
    std::vector<double> volumes;
    std::size_t inside = 0;
    double volume = 0;
};

// The nodes of `latticeText` over the box `boxText` as particleGen takes them: all points, their
// volumes, and how many of them the box's inside test keeps (with the sum of their volumes).
NodalFill nodal(const std::string& boxText, const std::string& latticeText, int dim) {
    const auto s = shape(boxText, dim);
    const auto l = lattice(latticeText, dim);
    NodalFill f;
    f.points = l->points(s->bounds());
    f.volumes = l->pointVolumes(s->bounds(), f.points);
    EXPECT_EQ(f.volumes.size() * std::size_t(dim), f.points.size());
    for (std::size_t p = 0; p < f.volumes.size(); ++p)
        if (s->inside(&f.points[p * std::size_t(dim)])) {
            ++f.inside;
            f.volume += f.volumes[p];
        }
    return f;
}

}  // namespace

TEST(NodalLattice, VolumesSumToTheBoxIn1D2D3D) {
    const auto f1 = nodal("type box; min (-0.3); max (0.7);", "type nodal; spacing 0.01;", 1);
    EXPECT_EQ(f1.inside, 101u);
    EXPECT_NEAR(f1.volume / 1.0, 1.0, 1e-12);
    const auto f2 = nodal("type box; min (0.1 -2); max (1.4 -1.3);", "type nodal; spacing 0.01;", 2);
    EXPECT_EQ(f2.inside, 131u * 71u);
    EXPECT_NEAR(f2.volume / (1.3 * 0.7), 1.0, 1e-12);
    const auto f3 = nodal("type box; min (0 0 0); max (0.03 0.01 0.005);", "type nodal; spacing 1e-3;", 3);
    EXPECT_NEAR(f3.volume / (0.03 * 0.01 * 0.005), 1.0, 1e-12);
}

TEST(NodalLattice, CountsOfThePapersExamples) {
    // Lee et al. 2016: 31×11×6 on 0.03×0.01×0.005 (Δx = 1 mm), 21×11×3 on 1×0.5×0.1 (Δx = 0.05).
    const auto a = nodal("type box; min (0 0 0); max (0.03 0.01 0.005);", "type nodal; spacing 1e-3;", 3);
    EXPECT_EQ(a.volumes.size(), 31u * 11u * 6u);
    EXPECT_EQ(a.inside, 31u * 11u * 6u);
    const auto b = nodal("type box; min (0 0 0); max (1 0.5 0.1);", "type nodal; spacing 0.05;", 3);
    EXPECT_EQ(b.inside, 21u * 11u * 3u);
    EXPECT_NEAR(b.volume / 0.05, 1.0, 1e-12);
    // The same lattice by node counts.
    const auto c = nodal("type box; min (0 0 0); max (1 0.5 0.1);", "type nodal; points (21 11 3);", 3);
    EXPECT_EQ(c.points, b.points);
    EXPECT_EQ(c.volumes, b.volumes);
    // Node counts per direction: spacings L/(n − 1), here 0.1, 0.05, 0.025.
    const auto l = NodalLattice(Dictionary::parse("type nodal; points (11 11 5);", "test"), 3);
    BoundingBox box;
    box.max = {1, 0.5, 0.1};
    EXPECT_EQ(l.counts(box), (std::array<long, 3>{11, 11, 5}));
    const auto dx = l.spacings(box);
    EXPECT_DOUBLE_EQ(dx[0], 0.1);
    EXPECT_DOUBLE_EQ(dx[1], 0.05);
    EXPECT_DOUBLE_EQ(dx[2], 0.025);
}

TEST(NodalLattice, SpacingIsAdjustedToFitTheBox) {
    // 1/0.3 = 3.33 -> 3 intervals -> 4 nodes, Δx = 1/3.
    const auto l = NodalLattice(Dictionary::parse("type nodal; spacing 0.3;", "test"), 2);
    BoundingBox box;
    box.max = {1, 0.1, 0};
    EXPECT_EQ(l.counts(box)[0], 4);
    EXPECT_DOUBLE_EQ(l.spacings(box)[0], 1.0 / 3);
    EXPECT_EQ(l.counts(box)[1], 2);  // never fewer than the two faces
    EXPECT_DOUBLE_EQ(l.spacings(box)[1], 0.1);
}

TEST(NodalLattice, CornerEdgeFaceAndInteriorVolumes) {
    const double dx = 0.05;
    const auto f = nodal("type box; min (0 0 0); max (1 0.5 0.1);", "type nodal; spacing 0.05;", 3);
    const auto volumeAt = [&](double x, double y, double z) {
        for (std::size_t p = 0; p < f.volumes.size(); ++p)
            if (f.points[3 * p] == x && f.points[3 * p + 1] == y && f.points[3 * p + 2] == z)
                return f.volumes[p];
        ADD_FAILURE() << "no node at (" << x << " " << y << " " << z << ")";
        return 0.0;
    };
    const double cell = std::pow(dx, 3);
    EXPECT_NEAR(volumeAt(0, 0, 0), cell / 8, 1e-15 * cell);
    EXPECT_NEAR(volumeAt(1, 0.5, 0.1), cell / 8, 1e-15 * cell);
    EXPECT_NEAR(volumeAt(1, 0.5, 0.05), cell / 4, 1e-15 * cell);   // edge
    EXPECT_NEAR(volumeAt(1, 0.25, 0.05), cell / 2, 1e-15 * cell);  // face
    EXPECT_NEAR(volumeAt(0.5, 0.25, 0.05), cell, 1e-15 * cell);    // interior
}

TEST(NodalLattice, NodesLieExactlyOnTheFacesAndNeverOutside) {
    const double lo[3] = {-0.1, 0.2, 1e-3}, hi[3] = {0.23, 0.31, 7e-3};  // lengths not multiples of Δx
    const auto f =
        nodal("type box; min (-0.1 0.2 1e-3); max (0.23 0.31 7e-3);", "type nodal; spacing 0.01;", 3);
    EXPECT_EQ(f.inside, f.volumes.size());  // the box's inside test keeps every node, faces included
    for (int d = 0; d < 3; ++d) {
        double least = 1e9, largest = -1e9;
        for (std::size_t p = 0; p < f.volumes.size(); ++p) {
            least = std::min(least, f.points[3 * p + d]);
            largest = std::max(largest, f.points[3 * p + d]);
        }
        EXPECT_EQ(least, lo[d]) << d;
        EXPECT_EQ(largest, hi[d]) << d;
    }
    const auto box = shape("type box; min (0 0); max (1 1);", 2);
    const double corner[2] = {1, 1}, face[2] = {0.5, 1}, beyond[2] = {0.5, std::nextafter(1.0, 2.0)};
    EXPECT_TRUE(box->inside(corner));
    EXPECT_TRUE(box->inside(face));
    EXPECT_FALSE(box->inside(beyond));
}

TEST(NodalLattice, JitterMovesNodesAlongTheirFacesOnly) {
    const std::string boxText = "type box; min (0 0 0); max (1 0.5 0.1);";
    const auto plain = nodal(boxText, "type nodal; spacing 0.05;", 3);
    const auto shaken = nodal(boxText, "type nodal; spacing 0.05; jitter 0.2; seed 7;", 3);
    const auto again = nodal(boxText, "type nodal; spacing 0.05; jitter 0.2; seed 7;", 3);
    EXPECT_EQ(shaken.points, again.points);
    ASSERT_EQ(shaken.points.size(), plain.points.size());
    const double hi[3] = {1, 0.5, 0.1};
    std::size_t moved = 0;
    for (std::size_t c = 0; c < plain.points.size(); ++c) {
        const int d = int(c % 3);
        const double x = plain.points[c];
        if (x == 0 || x == hi[d]) {
            EXPECT_EQ(shaken.points[c], x);
        } else {
            EXPECT_LE(std::abs(shaken.points[c] - x), 0.2 * 0.05 + 1e-15);
            moved += shaken.points[c] != x;
        }
    }
    EXPECT_GT(moved, 100u);
    EXPECT_EQ(shaken.inside, shaken.volumes.size());
    EXPECT_NEAR(shaken.volume / 0.05, 1.0, 1e-12);  // the volumes follow the faces, not the jitter
}

TEST(NodalLattice, InputErrors) {
    EXPECT_THROW(lattice("type nodal;", 3), InputError);
    EXPECT_THROW(lattice("type nodal; spacing 0.1; points (3 3 3);", 3), InputError);
    EXPECT_THROW(lattice("type nodal; spacing -0.1;", 3), InputError);
    EXPECT_THROW(lattice("type nodal; points (3 1 3);", 3), InputError);
    EXPECT_THROW(lattice("type nodal; points (3 2.5 3);", 3), InputError);
    EXPECT_THROW(lattice("type nodal; points (3 3);", 3), InputError);
    EXPECT_THROW(lattice("type nodal; points (3 3 4);", 2), InputError);
    EXPECT_NO_THROW(lattice("type nodal; points (3 3 1);", 2));
    EXPECT_THROW(lattice("type nodal; points (3 3);", 2)->pointVolume(), InputError);
    EXPECT_DOUBLE_EQ(lattice("type nodal; spacing 0.1;", 2)->pointVolume(), 0.01);
}

// particleGen's masses: m = ρ V with the tributary volumes, so Σ m = ρ |box|.
TEST(NodalLattice, ParticleGeneratorGivesTributaryMasses) {
    const auto dict = Dictionary::parse(
        "dimension 3; regions { bar { shape { type box; min (0 0 0); max (1 0.5 0.1); }"
        " lattice { type nodal; points (21 11 3); } density 1100; } }",
        "test");
    ParticleGenerator gen(dict);
    auto set = gen.generate();
    auto& p = particleSetCast<3>(*set);
    ASSERT_EQ(p.size(), 21u * 11u * 3u);
    const auto& mass = p.scalarField("mass");
    const double total = std::accumulate(mass.begin(), mass.end(), 0.0);
    EXPECT_NEAR(total / (1100 * 0.05), 1.0, 1e-12);
    EXPECT_NEAR(gen.report()[0].volume / 0.05, 1.0, 1e-12);
    EXPECT_NEAR(*std::min_element(mass.begin(), mass.end()), 1100 * std::pow(0.05, 3) / 8, 1e-15);
    EXPECT_NEAR(*std::max_element(mass.begin(), mass.end()), 1100 * std::pow(0.05, 3), 1e-12);
}
