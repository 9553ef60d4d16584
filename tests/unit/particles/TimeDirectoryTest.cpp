#include "particles/TimeDirectory.hpp"

#include "TestFiles.hpp"
#include "particles/ParticleSet.hpp"
#include "particles/VtpReader.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

using namespace mfdyn;
using mfdyn::test::readFile;
using mfdyn::test::ScratchDir;
using mfdyn::test::writeFile;
namespace fs = std::filesystem;

namespace {

// Entries of `dir` whose names contain ".tmp-" or ".old": leftovers of an atomic write.
std::vector<std::string> leftovers(const fs::path& dir) {
    std::vector<std::string> found;
    for (const auto& e : fs::directory_iterator(dir)) {
        const std::string name = e.path().filename().string();
        if (name.find(".tmp-") != std::string::npos || name.find(".old") != std::string::npos)
            found.push_back(name);
    }
    return found;
}

}  // namespace

TEST(TimeDirectory, WritesParticlesAndExtraFiles) {
    ScratchDir caseDir("timeDir");
    ParticleSet<2> p(4);
    p.scalarField("rho")[2] = 2700.0;
    const fs::path dir = writeTimeDirectory(caseDir.path(), "0.001", p, {{"state", "step 12;\n"}});
    EXPECT_EQ(dir, caseDir.path() / "0.001");
    EXPECT_EQ(readFile(dir / "state"), "step 12;\n");
    ParticleFile back = readVtp(dir / particleFileName);
    EXPECT_EQ(back.time, 0.001) << "time taken from the directory name";
    EXPECT_EQ(back.particles->requireField<double>("rho")[2], 2700.0);
    EXPECT_TRUE(leftovers(caseDir.path()).empty());
}

TEST(TimeDirectory, ReplacesAnExistingTimeWhole) {
    ScratchDir caseDir("replace");
    ParticleSet<1> p(2);
    writeTimeDirectory(caseDir.path(), "1", p, {{"state", "old"}, {"stale", "x"}});
    p.resize(3);
    writeTimeDirectory(caseDir.path(), "1", p, {{"state", "new"}}, 1.0);
    EXPECT_EQ(readFile(caseDir.path() / "1" / "state"), "new");
    EXPECT_FALSE(fs::exists(caseDir.path() / "1" / "stale")) << "the old directory is replaced, not merged";
    EXPECT_EQ(readVtp(caseDir.path() / "1" / particleFileName).particles->size(), 3u);
    EXPECT_TRUE(leftovers(caseDir.path()).empty());
}

TEST(TimeDirectory, WriterFailingMidwayLeavesNoPartialDirectory) {
    ScratchDir caseDir("fail");
    ParticleSet<3> p(10);
    // A write that throws after part of the files exist, with and without an earlier state.
    auto failing = [&](const fs::path& tmp) {
        writeFile(tmp / particleFileName, "half a file");
        throw Error("simulated failure");
    };
    EXPECT_THROW(writeDirectoryAtomically(caseDir.path() / "0.5", failing), Error);
    EXPECT_FALSE(fs::exists(caseDir.path() / "0.5"));
    EXPECT_TRUE(leftovers(caseDir.path()).empty());

    writeTimeDirectory(caseDir.path(), "0.5", p, {{"state", "good"}});
    EXPECT_THROW(writeDirectoryAtomically(caseDir.path() / "0.5", failing), Error);
    EXPECT_EQ(readFile(caseDir.path() / "0.5" / "state"), "good") << "a failed rewrite keeps the old state";
    EXPECT_EQ(readVtp(caseDir.path() / "0.5" / particleFileName).particles->size(), 10u);
    EXPECT_TRUE(leftovers(caseDir.path()).empty());

    // The real writer failing after particles.vtp: an extra file name longer than NAME_MAX.
    EXPECT_THROW(writeTimeDirectory(caseDir.path(), "0.7", p, {{std::string(300, 'x'), ""}}), Error);
    EXPECT_FALSE(fs::exists(caseDir.path() / "0.7"));
    EXPECT_TRUE(leftovers(caseDir.path()).empty());
    EXPECT_THROW(writeTimeDirectory(caseDir.path(), "0.8", p, {{"../escape", ""}}), Error);
}

TEST(TimeDirectory, ListsNumericDirectoriesByValue) {
    ScratchDir caseDir("list");
    for (const char* d :
         {"0", "0.5", "1e-3", "10", "2", "0.1.tmp-123", "0.1.old.tmp-4", "constant", "system", "1x"})
        fs::create_directories(caseDir.path() / d);
    writeFile(caseDir.path() / "5", "a file, not a time");
    const auto times = listTimeDirectories(caseDir.path());
    const std::vector<std::pair<double, std::string>> expected{
        {0.0, "0"}, {1e-3, "1e-3"}, {0.5, "0.5"}, {2.0, "2"}, {10.0, "10"}};
    EXPECT_EQ(times, expected);
    EXPECT_THROW(listTimeDirectories(caseDir.path() / "absent"), Error);
}

TEST(TimeDirectory, RemoveTimeDirectoryAndStaleTemporaries) {
    ScratchDir caseDir("remove");
    ParticleSet<1> p(1);
    writeTimeDirectory(caseDir.path(), "0.25", p);
    EXPECT_TRUE(removeTimeDirectory(caseDir.path(), "0.25"));
    EXPECT_FALSE(fs::exists(caseDir.path() / "0.25"));
    EXPECT_FALSE(removeTimeDirectory(caseDir.path(), "0.25"));
    EXPECT_TRUE(leftovers(caseDir.path()).empty());

    // 999999999 is above any pid_max (at most 2^22), so no process has it.
    fs::create_directories(caseDir.path() / "3.tmp-999999999" / "inner");
    writeFile(caseDir.path() / "particles.pvd.tmp-999999999", "");
    EXPECT_EQ(removeStaleTemporaries(caseDir.path()), 2u);
    EXPECT_TRUE(leftovers(caseDir.path()).empty());
}

// The sweep used to remove anything with ".tmp-" in its name: a user's notes.tmp-1 or a running
// writer's temporary went with the leftovers.
TEST(TimeDirectory, StaleTemporarySweepTakesOnlyOurShapesOfDeadWriters) {
    ScratchDir caseDir("sweep");
    const fs::path c = caseDir.path();
    const std::string dead = "999999999";
    const std::string live = std::to_string(::getppid());  // the test's parent: alive, not us
    const std::string self = std::to_string(::getpid());
    // Ours, writer gone: removed.
    for (const std::string name :
         {"0.5.tmp-" + dead, "0.5.old.tmp-" + dead, "1e-3.tmp-" + dead, "0.75.tmp-" + self})
        fs::create_directories(c / name / "inner");
    writeFile(c / ("particles.pvd.tmp-" + dead), "<half a pvd");
    // The user's, or a live writer's: kept.
    const std::vector<std::string> kept{
        "notes.tmp-1", "draft.tmp-backup", "0.5.tmp-abc", "0.25.tmp-" + live, "results.csv.tmp-" + dead,
        "0.5.tmp-",    ".tmp-" + dead,     "0.5.tmp-12x"};
    for (const auto& name : kept) writeFile(c / name, "user data");
    fs::create_directories(c / ("0.3.old.tmp-" + live));
    EXPECT_EQ(removeStaleTemporaries(c), 5u);
    for (const auto& name : kept) {
        ASSERT_TRUE(fs::exists(c / name)) << name << " is not a temporary of ours, or its writer lives";
        EXPECT_EQ(readFile(c / name), "user data");
    }
    EXPECT_TRUE(fs::exists(c / ("0.3.old.tmp-" + live))) << "a live process's temporary";
    for (const std::string name : {"0.5.tmp-" + dead, "0.5.old.tmp-" + dead, "1e-3.tmp-" + dead,
                                   "0.75.tmp-" + self, "particles.pvd.tmp-" + dead})
        EXPECT_FALSE(fs::exists(c / name)) << name << " is a dead writer's temporary";
}

// Killed between writeDirectoryAtomically's two renames: the new directory is complete, the old
// one aside, and no <time>. The sweep puts the new one in place rather than losing the time.
TEST(TimeDirectory, StaleTemporarySweepCompletesAnInterruptedReplace) {
    ScratchDir caseDir("interrupted");
    const fs::path c = caseDir.path();
    fs::create_directories(c / "2.tmp-999999999");
    fs::create_directories(c / "2.old.tmp-999999999");
    writeFile(c / "2.tmp-999999999" / "state", "new");
    writeFile(c / "2.old.tmp-999999999" / "state", "old");
    EXPECT_EQ(removeStaleTemporaries(c), 2u);
    EXPECT_EQ(readFile(c / "2" / "state"), "new");
    EXPECT_TRUE(leftovers(c).empty());
    // A lone <time>.tmp-<pid> may be half-filled: removed, never promoted.
    fs::create_directories(c / "3.tmp-999999999");
    EXPECT_EQ(removeStaleTemporaries(c), 1u);
    EXPECT_FALSE(fs::exists(c / "3"));
}

TEST(TimeDirectory, MovesTimesAsideWhereListingsIgnoreThem) {
    ScratchDir caseDir("aside");
    const fs::path c = caseDir.path();
    ParticleSet<1> p(3);
    for (const char* t : {"0", "0.5", "1"}) writeTimeDirectory(c, t, p, {{"state", t}});
    EXPECT_EQ(moveAsideTimeDirectories(c, {"0.5", "1"}), c / "abandoned.1");
    EXPECT_EQ(readFile(c / "abandoned.1" / "1" / "state"), "1") << "moved, not rewritten";
    const std::vector<std::pair<double, std::string>> onlyZero{{0.0, "0"}};
    EXPECT_EQ(listTimeDirectories(c), onlyZero);
    writeTimeDirectory(c, "0.5", p);
    EXPECT_EQ(moveAsideTimeDirectories(c, {"0.5"}), c / "abandoned.2") << "an earlier abandoned.1 is kept";
    EXPECT_TRUE(fs::exists(c / "abandoned.1" / "0.5"));
    EXPECT_EQ(listTimeDirectories(c), onlyZero);
    EXPECT_THROW(moveAsideTimeDirectories(c, {"7"}), Error) << "a time that does not exist";
}
