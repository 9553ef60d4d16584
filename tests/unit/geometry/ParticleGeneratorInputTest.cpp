// particleGen's refusals (issue 14): non-finite or overflowing values, particle masses that
// underflow, particle counts beyond memory (refused before allocating), regions left empty,
// misspelt field names. Each case was accepted, or crashed, before: the comments say how.
#include "GeometryTestUtils.hpp"
#include "geometry/ParticleGenerator.hpp"
#include "particles/ParticleSet.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <new>
#include <string>

using namespace mfdyn;

namespace {

// One region `a` of the given shape, lattice and extra entries, in `dim` dimensions.
std::string oneRegion(int dim, const std::string& shape, const std::string& lattice,
                      const std::string& extra = "") {
    return "dimension " + std::to_string(dim) + "; regions { a { shape { " + shape + " } lattice { " +
           lattice + " } density 1000; " + extra + " } }";
}

const std::string plate2D = "type box; min (0 0); max (0.1 0.1);";

// The message of the InputError that generating from `text` throws ("" and a test failure when
// it throws nothing or something else).
std::string refusal(const std::string& text) {
    try {
        const Dictionary dict = Dictionary::parse(text, "system/particleGenDict");
        ParticleGenerator gen(dict);
        gen.generate();
    } catch (const InputError& e) {
        return e.what();
    } catch (const std::exception& e) {
        ADD_FAILURE() << "not an InputError: " << e.what();
        return "";
    }
    ADD_FAILURE() << "accepted: " << text;
    return "";
}

void expectContains(const std::string& message, const std::string& part) {
    EXPECT_NE(message.find(part), std::string::npos) << "'" << part << "' not in: " << message;
}

}  // namespace

namespace mfdyn {
namespace {

// A shape whose inside test runs out of memory, as a huge region can after the count check
// passed (memory taken by another process meanwhile).
class OutOfMemoryShape final : public Shape {
public:
    OutOfMemoryShape(const Dictionary& dict, int dimension) : Shape(dict, dimension) {}
    bool inside(const double*) const override { throw std::bad_alloc(); }
    BoundingBox bounds() const override {
        BoundingBox b;
        b.max = {1, 1, 1};
        return b;
    }
};
MFDYN_REGISTER(Shape, OutOfMemoryShape, "testOutOfMemory", "geometryTests only: inside() throws bad_alloc");

}  // namespace
}  // namespace mfdyn

// The parser may refuse 1e400 itself; here inf and NaN are put into the parsed token, as a value
// from elsewhere could be. Whether the dictionary's typed read or particleGen's own check refuses
// it, the error is at the entry (file:line, scope regions/a/fields, keyword). Before, it was written.
TEST(ParticleGeneratorInput, NonFiniteFieldValuesNameTheRegionAndField) {
    for (const double bad :
         {std::numeric_limits<double>::infinity(), std::numeric_limits<double>::quiet_NaN()}) {
        Dictionary dict = Dictionary::parse(
            oneRegion(2, plate2D, "type cubic; spacing 0.01;", "fields { velocity (1 0); pressure 0; }"),
            "system/particleGenDict");
        const_cast<Entry*>(dict.findScoped("regions/a/fields/velocity"))->tokens[0].list[0].real = bad;
        const_cast<Entry*>(dict.findScoped("regions/a/fields/velocity"))->tokens[0].list[0].kind =
            Token::Kind::real;
        ParticleGenerator gen(dict);
        try {
            gen.generate();
            ADD_FAILURE() << "velocity " << bad << " accepted";
        } catch (const InputError& e) {
            const std::string m = e.what();
            expectContains(m, "system/particleGenDict:1:");
            expectContains(m, "in 'regions/a/fields': keyword 'velocity'");
            EXPECT_TRUE(m.find("must be finite") != std::string::npos ||
                        m.find("non-finite") != std::string::npos)
                << m;
        }
    }
}

// Finite components whose square overflows: v·v (kinetic energy) would be inf from the start.
TEST(ParticleGeneratorInput, VelocityWhoseSquareOverflowsIsRefused) {
    const auto m =
        refusal(oneRegion(2, plate2D, "type cubic; spacing 0.01;", "fields { velocity (1e200 0); }"));
    expectContains(m, "field 'velocity' is so large that its square overflows");
}

// A rotation of 1e200 rad/s gives ω × r ~ 1e198 m/s, whose square overflows; it was written.
TEST(ParticleGeneratorInput, RotationThatOverflowsIsRefused) {
    const auto m = refusal(oneRegion(2, "type sphere; centre (0 0); radius 0.1;", "type cubic; spacing 0.01;",
                                     "angularVelocity { omega 1e200; }"));
    expectContains(m, "keyword 'angularVelocity'");
    expectContains(m, "overflows");
}

// spacing 1e-110 on a box of 1e-109: 1000 points of volume 1e-330, which underflows to 0. Before:
// 1000 particles of mass 0.
TEST(ParticleGeneratorInput, MassThatUnderflowsIsRefused) {
    const auto m = refusal(
        oneRegion(3, "type box; min (0 0 0); max (1e-109 1e-109 1e-109);", "type cubic; spacing 1e-110;"));
    expectContains(m, "keyword 'lattice'");
    expectContains(m, "region 'a': the particle mass density x volume = 1000 x 0 = 0 (spacing 1e-110 m)");
}

// Also through the density: 1e-310 kg/m^3 x 1e-4 m^2 = 1e-314 kg is subnormal (below 2.2e-308),
// whose reciprocal is inf. Before, it was written.
TEST(ParticleGeneratorInput, SubnormalMassIsRefused) {
    auto text = oneRegion(2, plate2D, "type cubic; spacing 0.01;");
    text.replace(text.find("density 1000"), 12, "density 1e-310");
    expectContains(refusal(text), "is not a positive normal number");
}

// spacing 1e-300: the count of points per direction (1e299) overflowed a long, and the lattice
// returned ONE point. Now the count is refused before anything is allocated.
TEST(ParticleGeneratorInput, AbsurdSpacingIsRefusedBeforeAllocating) {
    const auto m = refusal(oneRegion(2, plate2D, "type cubic; spacing 1e-300;"));
    expectContains(m, "system/particleGenDict:1:");
    expectContains(m, "region 'a' would hold about more than 1e308 particles");
    expectContains(m, "spacing 1e-300 m");
    // The lattice on its own refuses too, rather than returning one point.
    const auto lattice = test::lattice("type cubic; spacing 1e-300;", 2);
    BoundingBox box;
    box.max = {0.1, 0.1, 0};
    EXPECT_THROW(lattice->points(box), InputError);
}

// 1e12 particles (200 TB): this was std::bad_alloc, printed as "Error (internal)".
TEST(ParticleGeneratorInput, CountBeyondMemoryNamesRegionCountAndSpacing) {
    const auto m = refusal(oneRegion(3, "type box; min (0 0 0); max (1 1 1);", "type cubic; spacing 1e-4;"));
    expectContains(m, "region 'a' would hold about 1e+12 particles");
    expectContains(m, "cubic lattice of spacing 0.0001 m");
    expectContains(m, "at 200 bytes per particle that needs");
    // A nodal lattice given by node counts: 2^31 per direction passes the per-direction check,
    // the product (1e28) does not fit any memory.
    const auto n = refusal(oneRegion(3, "type box; min (0 0 0); max (1 1 1);",
                                     "type nodal; points (2147483648 2147483648 2147483648);"));
    expectContains(n, "region 'a' would hold about 9.90352e+27 particles");
    // More than 2^31 nodes per direction cannot be converted exactly: refused where given.
    expectContains(
        refusal(oneRegion(3, "type box; min (0 0 0); max (1 1 1);", "type nodal; points (1e300 2 2);")),
        "keyword 'points'");
}

// A sphere of radius 1e200: its bounding box's point count was std::bad_alloc.
TEST(ParticleGeneratorInput, HugeShapesAreRefusedWhereGiven) {
    expectContains(
        refusal(oneRegion(2, "type sphere; centre (0 0); radius 1e200;", "type cubic; spacing 0.01;")),
        "keyword 'radius': radius must be positive and at most 1e150 m, found 1e+200");
    expectContains(refusal(oneRegion(2, "type box; min (0 0); max (1e200 1);", "type cubic; spacing 1e190;")),
                   "keyword 'max': component 1 is 1e+200: coordinates must be finite and within +-1e150 m");
    expectContains(refusal(oneRegion(3, "type cylinder; point1 (0 0 0); point2 (0 0 1); radius -1;",
                                     "type cubic; spacing 0.01;")),
                   "keyword 'radius'");
}

// A region whose particles a later region (override yes) takes completely was silently kept with
// none: a region of no mass in the particle file.
TEST(ParticleGeneratorInput, RegionLeftWithoutParticlesIsRefused) {
    const auto m = refusal(
        "dimension 2; regions { a { shape { type box; min (0 0); max (0.1 0.1); } lattice { type cubic; "
        "spacing 0.01; }"
        " density 1000; } b { shape { type box; min (-1 -1); max (1 1); } lattice { type cubic; spacing "
        "0.05; }"
        " density 1000; } }");
    expectContains(m, "system/particleGenDict:1:24: in 'regions': keyword 'a'");
    expectContains(m, "region 'a' has no particles left: the later region 'b' took them all");
}

// std::bad_alloc reached the user as "Error (internal): std::bad_alloc".
TEST(ParticleGeneratorInput, OutOfMemoryIsAnErrorNamingTheRegion) {
    const Dictionary dict =
        Dictionary::parse(oneRegion(2, "type testOutOfMemory;", "type cubic; spacing 0.1;"), "test");
    ParticleGenerator gen(dict);
    try {
        gen.generate();
        ADD_FAILURE() << "no error";
    } catch (const InputError& e) {
        ADD_FAILURE() << "an input error: " << e.what();
    } catch (const Error& e) {
        expectContains(e.what(), "out of memory while generating particles in region 'a'");
    }
}

// `velocty` was written as a new field, leaving the block at rest.
TEST(ParticleGeneratorInput, MisspeltFieldHasADidYouMean) {
    const auto m = refusal(oneRegion(2, plate2D, "type cubic; spacing 0.01;", "fields { velocty (1 0); }"));
    expectContains(m, "system/particleGenDict:1:");
    expectContains(m,
                   "unknown field 'velocty' (did you mean 'velocity'?); known fields: velocity pressure "
                   "specificInternalEnergy temperature smoothingLength plasticStrain");
    expectContains(m, "userFields (velocty);");
    // Not a typo by edit distance, but the one known name that contains it.
    expectContains(
        refusal(oneRegion(2, plate2D, "type cubic; spacing 0.01;", "fields { internalEnergy 1; }")),
        "(did you mean 'specificInternalEnergy'?)");
    // Fixed names the solvers compute themselves are no initial values.
    expectContains(
        refusal(oneRegion(2, plate2D, "type cubic; spacing 0.01;", "fields { acceleration (0 1); }")),
        "the solvers compute it themselves");
}

// A density in `fields` overwrote the density field after the mass was computed from the
// region's `density`: m/rho was no longer the particle's volume.
TEST(ParticleGeneratorInput, FieldsCannotContradictWhatParticleGenSets) {
    expectContains(refusal(oneRegion(2, plate2D, "type cubic; spacing 0.01;", "fields { density 5; }")),
                   "'density' is set by particleGen itself from the region's `density` entry");
    // Scalar where the models read a vector, and the reverse (in 1D both have one component, but
    // `velocity 1;` made a scalar field that the solvers' vector `velocity` clashed with).
    expectContains(refusal(oneRegion(1, "type box; min (0); max (1);", "type cubic; spacing 0.1;",
                                     "fields { velocity 1; }")),
                   "'velocity' is a vector field: expected a list of 1 components");
    expectContains(refusal(oneRegion(2, plate2D, "type cubic; spacing 0.01;", "fields { pressure (1 0); }")),
                   "'pressure' is a scalar field: expected a number");
}

TEST(ParticleGeneratorInput, UserFieldsAreAccepted) {
    const Dictionary dict =
        Dictionary::parse("userFields (charge spin);" + oneRegion(2, plate2D, "type cubic; spacing 0.01;",
                                                                  "fields { charge 3; spin (0 2); }"),
                          "system/particleGenDict");
    ParticleGenerator gen(dict);
    auto set = gen.generate();
    auto& p = particleSetCast<2>(*set);
    ASSERT_EQ(p.size(), 100u);
    EXPECT_EQ(p.scalarField("charge")[0], 3);
    EXPECT_EQ(p.vectorField("spin")[99][1], 2);
    expectContains(refusal("userFields (mass);" + oneRegion(2, plate2D, "type cubic; spacing 0.01;")),
                   "'mass' is set by particleGen itself");
}

// pointCount is what the refusal above relies on: it must equal the points actually generated.
TEST(ParticleGeneratorInput, PointCountMatchesThePointsOfEveryLattice) {
    BoundingBox box;
    box.min = {0, -0.2, 0.1};
    box.max = {1, 0.3, 0.35};
    const struct {
        const char* text;
        int dim;
    } cases[] = {{"type cubic; spacing 0.07;", 1},     {"type cubic; spacing 0.07;", 3},
                 {"type hexagonal; spacing 0.07;", 2}, {"type hcp; spacing 0.07;", 3},
                 {"type nodal; spacing 0.07;", 3},     {"type nodal; points (5 4 3);", 3}};
    for (const auto& c : cases) {
        const auto l = test::lattice(c.text, c.dim);
        EXPECT_EQ(l->pointCount(box), double(l->points(box).size() / std::size_t(c.dim))) << c.text;
    }
}

// Found by mutating the tutorials' dictionaries: `fields velocity;` (not a dictionary) was skipped
// without a word, and `mass equalMass` with a nodal lattice of `points` was refused with no
// file:line.
TEST(ParticleGeneratorInput, MalformedEntriesAreRefusedWhereWritten) {
    expectContains(refusal(oneRegion(2, plate2D, "type cubic; spacing 0.01;", "fields velocity;")),
                   "in 'regions/a': keyword 'fields': expected a dictionary");
    expectContains(refusal(oneRegion(3, "type box; min (0 0 0); max (1 1 1);", "type nodal; points (3 3 3);",
                                     "mass equalMass;")),
                   "system/particleGenDict:1:");
}
