#include "particles/PvdIndex.hpp"

#include "TestFiles.hpp"
#include "core/Error.hpp"
#include "particles/XmlElement.hpp"

#include <gtest/gtest.h>

using namespace mfdyn;
using mfdyn::test::readFile;
using mfdyn::test::ScratchDir;
using mfdyn::test::writeFile;

TEST(PvdIndex, WritesReadsAndTruncatesOnRestart) {
    ScratchDir caseDir("pvd");
    const auto file = caseDir.path() / "particles.pvd";
    PvdIndex index = PvdIndex::read(file);
    EXPECT_TRUE(index.entries().empty()) << "a missing index is an empty one";
    const double t1 = 0.1, t2 = 0.2, t3 = 0.1 + 0.2;  // 0.30000000000000004: needs 17 digits
    for (double t : {0.0, t1, t2, t3}) {
        index.add(t, "t/particles.vtp");
        index.write();
    }
    index.add(t1, "0.1/particles.vtp");  // a rewrite of a time replaces its entry
    index.write();

    PvdIndex back = PvdIndex::read(file);
    ASSERT_EQ(back.entries().size(), 4u);
    EXPECT_EQ(back.entries()[1].file, "0.1/particles.vtp");
    EXPECT_EQ(back.entries()[3].time, t3) << "times survive the text round trip exactly";

    // Restart from 0.2: later entries go, and the next write continues from there.
    back.truncateAfter(t2);
    back.add(0.25, "0.25/particles.vtp");
    back.write();
    const PvdIndex again = PvdIndex::read(file);
    ASSERT_EQ(again.entries().size(), 4u);
    EXPECT_EQ(again.entries()[2].time, t2);
    EXPECT_EQ(again.entries()[3].time, 0.25);
    EXPECT_FALSE(std::filesystem::exists(file.string() + ".tmp-" + std::to_string(::getpid())));

    const std::string text = readFile(file);
    EXPECT_NO_THROW(XmlElement::parse(text, "particles.pvd"));
#ifdef MFDYN_XMLLINT
    const std::string command = std::string(MFDYN_XMLLINT) + " --noout " + file.string();
    EXPECT_EQ(std::system(command.c_str()), 0) << text;
#endif
}

TEST(PvdIndex, UnreadableIndexIsAnErrorNamingTheFile) {
    ScratchDir caseDir("pvdBad");
    const auto file = caseDir.path() / "particles.pvd";
    writeFile(file, "<VTKFile><Collection><DataSet timestep=\"x\" file=\"a\"/></Collection></VTKFile>");
    try {
        PvdIndex::read(file);
        ADD_FAILURE() << "no error for a non-numeric timestep";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("particles.pvd"), std::string::npos) << e.what();
    }
    writeFile(file, "<VTKFile><Collection>");
    EXPECT_THROW(PvdIndex::read(file), InputError);
}
