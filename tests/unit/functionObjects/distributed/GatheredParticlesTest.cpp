// What function objects see on several ranks (functionObjects/GatheredParticles.hpp), on any
// number of ranks: run serially by ctest, and under mpiexec on three ranks where MPI is built
// (label mpi). Each rank holds the particles whose global id is its rank modulo the rank count,
// in descending id order, so the gathered copy must both join the ranks' shares and sort them:
// it holds every particle once, in id order, with every selected field's values, on every rank.
// The list gathers once per call, only at the calls where an object of scope all writes, and an
// object of scope all (probes) writes what a serial run over all the particles writes, bit for
// bit (the same particles in the same order), while one of scope owned (fieldMinMax) reduces
// globally. A failing expectation never returns early: a rank that left would leave the others
// waiting in the next collective.
#include "DistributedTestCase.hpp"
#include "core/Communicator.hpp"
#include "core/Dictionary.hpp"
#include "functionObjects/FunctionObject.hpp"
#include "functionObjects/GatheredParticles.hpp"
#include "particles/ParticleSet.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>

using namespace mfdyn;
using namespace mfdyn::distributedTest;
namespace fs = std::filesystem;

namespace {

fs::path freshCase(const std::string& tag) {
    return functionObjectTest::freshCase("Gathered", tag);
}

TEST(GatheredParticles, holdsEveryRanksParticlesOnceInIdOrder) {
    SteppedContext run(freshCase("order"));
    place(run.particles, myShare());
    GatheredParticles gathered(run);
    EXPECT_EQ(gathered.copy(), nullptr);
    const ParticleSetBase& all = gathered.particles();
    EXPECT_EQ(gathered.refreshes(), 1u);
    ASSERT_EQ(all.size(), std::size_t(total));
    const auto& set = particleSetCast<2>(all);
    const auto& mass = set.requireField<double>("mass");
    const auto& stress = set.requireField<SymmTensor<2>>("deviatoricStress");
    for (std::int64_t id = 0; id < total; ++id) {
        const auto i = std::size_t(id);
        EXPECT_EQ(set.globalId()[i], id);
        EXPECT_EQ(set.region()[i], id % 2);
        EXPECT_EQ(set.position()[i], Vector<2>(double(id), -2.0 * double(id)));
        EXPECT_EQ(mass[i], 0.5 * double(id));
        EXPECT_EQ(stress[i].c[2], double(id) / 3);
    }
    EXPECT_EQ(all.regionNames, (std::vector<std::string>{"even", "odd"}));
}

TEST(GatheredParticles, gathersOnlyTheSelectedFieldsAgain) {
    SteppedContext run(freshCase("select"));
    place(run.particles, myShare());
    GatheredParticles gathered(run);
    gathered.particles();
    gathered.select(std::set<std::string>{"mass"});
    const ParticleSetBase& all = gathered.particles();
    EXPECT_TRUE(all.hasField("mass"));
    EXPECT_TRUE(all.hasField("globalId"));
    EXPECT_TRUE(all.hasField("region"));
    EXPECT_FALSE(all.hasField("position"));
    EXPECT_FALSE(all.hasField("pressure"));
    EXPECT_FALSE(all.hasField("deviatoricStress"));
    // The run moves on: the copy shows it only after a refresh.
    const auto& share = run.particles.globalId();
    auto& mass = run.particles.scalarField("mass");
    for (std::size_t k = 0; k < mass.size(); ++k) mass[k] = double(share[k] * share[k]);
    EXPECT_EQ(all.requireField<double>("mass")[3], 1.5);
    gathered.refresh();
    EXPECT_EQ(gathered.refreshes(), 2u);
    const auto& gatheredMass = all.requireField<double>("mass");
    ASSERT_EQ(gatheredMass.size(), std::size_t(total));
    for (std::int64_t id = 0; id < total; ++id) EXPECT_EQ(gatheredMass[std::size_t(id)], double(id * id));
}

TEST(GatheredParticles, aContextShowsTheScopeItsObjectStated) {
    SteppedContext run(freshCase("scope"));
    place(run.particles, myShare());
    GatheredParticles gathered(run);
    const FunctionObjectContext context(run, gathered);
    EXPECT_EQ(context.fields().size(), std::size_t(total));
    EXPECT_EQ(context.ownedParticles(), std::size_t(total));
    context.show(ParticleScope::owned);
    EXPECT_EQ(&context.fields(), &run.fields());
    EXPECT_EQ(context.ownedParticles(), myShare().size());
    EXPECT_EQ(&context.time(), &run.time());
    EXPECT_EQ(&context.solverContext(), &run);
}

// The list: probes (scope all, every second step) and fieldMinMax (owned, every step).
const char* listText = R"(
    health off;
    functions
    {
        extremes { type fieldMinMax; fields (mass); }
        probe    { type probes; fields (mass pressure); points ((4.2 -8.4) (11 -22)); h 1.5;
                   writeControl timeStep; writeInterval 2; }
    }
)";

std::vector<double> lastRow(const fs::path& file) {
    const auto rows = functionObjectTest::csvRows(file);
    return rows.empty() ? std::vector<double>{} : rows.back();
}

TEST(GatheredParticles, theListGathersOnlyWhenAnObjectOfScopeAllWrites) {
    const fs::path root = freshCase("list");
    SteppedContext run(root);
    place(run.particles, myShare());
    FunctionObjectList list(Dictionary::parse(listText, "controlDict"), run);
    const GatheredParticles* gathered = list.gathered();
    EXPECT_EQ(gathered != nullptr, Communicator::distributed());
    const auto refreshes = [&] { return gathered ? gathered->refreshes() : 0u; };
    // Once for the probes' construction, then once per call at which they write.
    const std::uint64_t built = Communicator::distributed() ? 1 : 0;
    EXPECT_EQ(refreshes(), built);
    if (gathered) EXPECT_NE(gathered->copy(), nullptr);
    if (gathered && gathered->copy()) {
        const auto fields = gathered->copy()->fieldNames();
        // What probes read (mass, pressure, position; mass and density for the volumes), no more.
        EXPECT_EQ(std::count(fields.begin(), fields.end(), "deviatoricStress"), 0);
        EXPECT_EQ(std::count(fields.begin(), fields.end(), "pressure"), 1);
    }
    list.execute(false);  // step 0: both write
    EXPECT_EQ(refreshes(), built + (gathered ? 1 : 0));
    run.step();
    list.execute(false);  // step 1: fieldMinMax alone
    EXPECT_EQ(refreshes(), built + (gathered ? 1 : 0));
    run.step();
    list.execute(false);  // step 2: both
    EXPECT_EQ(refreshes(), built + (gathered ? 2 : 0));

    // What one process holding every particle writes, against what the list wrote (on rank 0,
    // which writes the files).
    const fs::path serialRoot = freshCase("serial");
    SteppedContext serial(serialRoot);
    place(serial.particles, everyId());
    serial.step(), serial.step();
    const auto probe = FunctionObject::New(
        Dictionary::parse(listText, "controlDict").subDict("functions").subDict("probe"), "probe", serial);
    probe->write();
    if (Communicator::rank() == 0) {
        const auto expected = lastRow(serialRoot / "postProcessing" / "probe" / "0" / "probes.csv");
        const auto written = lastRow(root / "postProcessing" / "probe" / "0" / "probes.csv");
        ASSERT_EQ(expected.size(), 5u);
        EXPECT_EQ(written, expected);
        EXPECT_FALSE(std::isnan(expected[1]));
        // mass from 0 (id 0) to 11 (id 22).
        EXPECT_EQ(lastRow(root / "postProcessing" / "extremes" / "0" / "fieldMinMax.csv"),
                  (std::vector<double>{2e-3, 0, 0, 11, 22}));
    }
}

}  // namespace

// MPI is started only under mpiexec (core/Communicator.hpp); serially this is gtest's own main.
int main(int argc, char** argv) {
    Communicator::initialise(argc, argv);
    ::testing::InitGoogleTest(&argc, argv);
    const int status = RUN_ALL_TESTS();
    Communicator::finalise();
    return status;
}
