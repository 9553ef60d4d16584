// planeCrossing (issue 18 item 5: the first time a particle crosses a plane, the thesis's dam exit
// time) on hand-made particle sets, built through FunctionObject::New from a dictionary as
// controlDict gives it: the leading particle and its signed distance, the crossing's time, particle,
// position and linear estimate, a region's particles alone, the stop request, the reference value,
// and the refused input (zero normal, unknown region, wrong component count). The positions are
// binary-exact (halves and quarters), so distances are exact; the normal (0 2) normalises to (0 1)
// exactly.
#include "FunctionObjectTestCase.hpp"
#include "core/Dictionary.hpp"
#include "core/Error.hpp"
#include "functionObjects/FunctionObject.hpp"
#include "particles/ParticleSet.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

using namespace mfdyn;
namespace fs = std::filesystem;

namespace {

using Context = functionObjectTest::TestContext<2>;
fs::path freshCase(const std::string& tag) {
    return functionObjectTest::freshCase("PlaneCrossing", tag);
}
const auto& rows = functionObjectTest::csvRows;

std::unique_ptr<FunctionObject> make(const std::string& text, const std::string& name, const RunContext& c) {
    return FunctionObject::New(Dictionary::parse(text, "controlDict"), name, c);
}

std::string errorOf(const std::string& text, const RunContext& c) {
    try {
        make(text, "exit", c);
    } catch (const InputError& e) {
        return e.what();
    }
    return "no error";
}

// Region water: ids 0, 1 at y = 0 and 1; region wall: id 2 at y = 1.5 (the leading particle).
void threeParticles(ParticleSet<2>& p) {
    p.resize(3);
    p.regionNames = {"water", "wall"};
    const double y[3] = {0, 1, 1.5};
    const std::int64_t r[3] = {0, 0, 1};
    auto& mass = p.scalarField("mass");
    for (std::size_t i = 0; i < 3; ++i) {
        mass[i] = 1;
        p.position()[i] = Vector<2>(0.25 * double(i), y[i]);
        p.region()[i] = r[i];
        p.globalId()[i] = std::int64_t(i);
    }
}

}  // namespace

// The plane y = 2 (normal (0 2), normalised): at t = 0 the leader is id 2, 0.5 before it; at
// t = 0.5 id 1 has moved to y = 2.5, 0.5 beyond: the crossing at t = 0.5 after t = 0, the linear
// estimate 0 + 0.5 (-0.5) / (-0.5 - 0.5) = 0.25. A later write keeps the first crossing.
TEST(PlaneCrossing, FirstCrossingAndLeader) {
    const fs::path root = freshCase("first");
    Context c(root);
    threeParticles(c.particles);
    {
        auto exit = make("type planeCrossing; point (0 2); normal (0 2); reference 0.4;", "exit", c);
        exit->write();
        EXPECT_FALSE(exit->stopRequested());  // no stopAtCrossing, and nothing crossed
        EXPECT_TRUE(exit->referenceValues().empty());
        ASSERT_EQ(exit->summary().size(), 1u);
        EXPECT_NE(exit->summary()[0].find("no particle crossed by t = 0"), std::string::npos)
            << exit->summary()[0];
        c.at(0.5);
        c.particles.position()[1] = Vector<2>(0.25, 2.5);
        exit->write();
        EXPECT_FALSE(exit->stopRequested());  // crossed, but stopAtCrossing is off
        c.at(0.75);
        c.particles.position()[0] = Vector<2>(0, 3);
        exit->write();
        const auto refs = exit->referenceValues();
        ASSERT_EQ(refs.size(), 1u);
        EXPECT_EQ(refs[0].name, "crossingTime");
        EXPECT_EQ(refs[0].value, 0.5);
        EXPECT_EQ(refs[0].exact, 0.4);
        const std::string s = exit->summary()[0];
        EXPECT_NE(
            s.find(
                "first crossing at t = 0.5 (after t = 0; linear estimate 0.25) by particle 1 at (0.25 2.5)"),
            std::string::npos)
            << s;
    }
    const auto leading = rows(root / "postProcessing" / "exit" / "0" / "leading.csv");
    ASSERT_EQ(leading.size(), 3u);
    const std::vector<std::vector<double>> expected{
        {0, -0.5, 2, 0.5, 1.5}, {0.5, 0.5, 1, 0.25, 2.5}, {0.75, 1, 0, 0, 3}};
    for (std::size_t k = 0; k < 3; ++k) EXPECT_EQ(leading[k], expected[k]) << "row " << k;
    const auto crossing = rows(root / "postProcessing" / "exit" / "0" / "crossing.csv");
    ASSERT_EQ(crossing.size(), 1u);
    EXPECT_EQ(crossing[0], (std::vector<double>{0.5, 0, 0.25, 0.5, 1, 0.25, 2.5}));
    fs::remove_all(root);
}

// A region's particles alone: the wall's id 2 crossing does not count for region water; with
// stopAtCrossing the request comes at water's own crossing, and names the particle.
TEST(PlaneCrossing, RegionAndStopRequest) {
    const fs::path root = freshCase("region");
    Context c(root);
    threeParticles(c.particles);
    auto exit = make("type planeCrossing; region water; point (0 1.25); normal (0 1); stopAtCrossing yes;",
                     "exit", c);
    exit->write();  // the wall's particle is beyond already: not water
    EXPECT_FALSE(exit->stopRequested());
    c.at(0.25);
    c.particles.position()[0] = Vector<2>(0, 1.5);
    exit->write();
    EXPECT_TRUE(exit->stopRequested());
    EXPECT_NE(exit->stopReason().find("particle 0 crossed the plane at t = 0.25"), std::string::npos)
        << exit->stopReason();
    // The estimate: water's leader was id 1, 0.25 before; now id 0, 0.25 beyond: t* = 0.125.
    EXPECT_NE(exit->summary()[0].find("linear estimate 0.125"), std::string::npos) << exit->summary()[0];
    exit.reset();
    fs::remove_all(root);
}

// A particle beyond the plane at the first write: a crossing at the start, said so.
TEST(PlaneCrossing, BeyondAtStart) {
    const fs::path root = freshCase("start");
    Context c(root);
    threeParticles(c.particles);
    auto exit = make("type planeCrossing; point (0 1); normal (0 1);", "exit", c);
    exit->write();
    EXPECT_NE(exit->summary()[0].find("particle 2 already beyond the plane (by 0.5) at the first write"),
              std::string::npos)
        << exit->summary()[0];
    exit.reset();
    fs::remove_all(root);
}

TEST(PlaneCrossing, RefusedInput) {
    const fs::path root = freshCase("errors");
    Context c(root);
    threeParticles(c.particles);
    const std::string zero = errorOf("type planeCrossing; point (0 8); normal (0 0);", c);
    EXPECT_NE(zero.find("normal"), std::string::npos) << zero;
    EXPECT_NE(zero.find("non-zero"), std::string::npos) << zero;
    EXPECT_NE(zero.find("controlDict"), std::string::npos) << zero;  // the file (and line)
    const std::string region = errorOf("type planeCrossing; region watr; point (0 8); normal (0 1);", c);
    EXPECT_NE(region.find("watr"), std::string::npos) << region;
    EXPECT_NE(region.find("water"), std::string::npos) << region;  // the regions there are
    EXPECT_NE(region.find("wall"), std::string::npos) << region;
    const std::string count = errorOf("type planeCrossing; point (0 8 0); normal (0 1);", c);
    EXPECT_NE(count.find("point"), std::string::npos) << count;
    EXPECT_NE(count.find("expected 2 components"), std::string::npos) << count;
    const std::string missing = errorOf("type planeCrossing; point (0 8);", c);
    EXPECT_NE(missing.find("normal"), std::string::npos) << missing;
    fs::remove_all(root);
}
