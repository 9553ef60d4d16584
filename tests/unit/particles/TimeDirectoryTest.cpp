#include "particles/TimeDirectory.hpp"

#include "TestFiles.hpp"
#include "particles/ParticleSet.hpp"
#include "particles/VtpReader.hpp"

#include <gtest/gtest.h>

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

    fs::create_directories(caseDir.path() / "3.tmp-999" / "inner");
    writeFile(caseDir.path() / "particles.pvd.tmp-999", "");
    EXPECT_EQ(removeStaleTemporaries(caseDir.path()), 2u);
    EXPECT_TRUE(leftovers(caseDir.path()).empty());
}
