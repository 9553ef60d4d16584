#include "particles/PvdIndex.hpp"

#include "TestFiles.hpp"
#include "core/Error.hpp"
#include "particles/XmlElement.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <random>

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

namespace {

std::string pvdWith(const std::string& dataSets) {
    return "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"1.0\">\n  <Collection>\n" +
           dataSets + "  </Collection>\n</VTKFile>\n";
}

}  // namespace

TEST(PvdIndex, LargeIndexIsReadInLinearTime) {
    // 200 000 entries, as a long run writing often makes. On a668953 each element's line was
    // counted from the start of the file: 50 000 entries took 7.5 s, so 200 000 would take
    // about 2 minutes; read linearly they take a fraction of a second.
    ScratchDir caseDir("pvdLarge");
    const auto file = caseDir.path() / "particles.pvd";
    const std::size_t n = 200000;
    std::string dataSets;
    dataSets.reserve(n * 64);
    for (std::size_t i = 0; i < n; ++i)
        dataSets += "    <DataSet timestep=\"" + std::to_string(i) + "e-6\" part=\"0\" file=\"" +
                    std::to_string(i) + "/particles.vtp\"/>\n";
    writeFile(file, pvdWith(dataSets));
    const auto start = std::chrono::steady_clock::now();
    const PvdIndex index = PvdIndex::read(file);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::printf("read %zu entries in %.3f s\n", n, seconds);
    EXPECT_LT(seconds, 2.0) << "linear: was 7.5 s for 50 000 entries on a668953";
    ASSERT_EQ(index.entries().size(), n);
    EXPECT_EQ(index.entries().back().file, std::to_string(n - 1) + "/particles.vtp");
    EXPECT_DOUBLE_EQ(index.entries().back().time, double(n - 1) * 1e-6);
}

TEST(PvdIndex, EntriesOutOfOrderAreSortedAndTheLastOfATimeKept) {
    // What add() one at a time gives, also for an index listed backwards (which add() alone
    // would insert quadratically).
    ScratchDir caseDir("pvdOrder");
    const auto file = caseDir.path() / "particles.pvd";
    writeFile(file,
              pvdWith("<DataSet timestep=\"0.3\" file=\"c\"/>\n<DataSet timestep=\"0.1\" file=\"a\"/>\n"
                      "<DataSet timestep=\"0.2\" file=\"b\"/>\n<DataSet timestep=\"0.1\" file=\"a2\"/>\n"));
    const PvdIndex index = PvdIndex::read(file);
    ASSERT_EQ(index.entries().size(), 3u);
    EXPECT_EQ(index.entries()[0].time, 0.1);
    EXPECT_EQ(index.entries()[0].file, "a2") << "a later entry of a time replaces the earlier, as add() does";
    EXPECT_EQ(index.entries()[1].file, "b");
    EXPECT_EQ(index.entries()[2].file, "c");
}

TEST(PvdIndex, NonFiniteTimestepIsAnErrorNamingFileAndLine) {
    // from_chars accepts "nan" and "inf"; a NaN time would break the sorted order that restart
    // truncation relies on.
    ScratchDir caseDir("pvdNan");
    const auto file = caseDir.path() / "particles.pvd";
    for (const char* bad : {"nan", "inf", "-inf", "NaN"}) {
        writeFile(file, pvdWith("<DataSet timestep=\"0\" file=\"a\"/>\n<DataSet timestep=\"" +
                                std::string(bad) + "\" file=\"b\"/>\n"));
        try {
            PvdIndex::read(file);
            ADD_FAILURE() << "timestep " << bad << " accepted";
        } catch (const InputError& e) {
            const std::string what = e.what();
            EXPECT_NE(what.find(file.string()), std::string::npos) << what;
            EXPECT_NE(what.find("line 5"), std::string::npos) << what;
            EXPECT_NE(what.find("not a finite number"), std::string::npos) << what;
        }
    }
}

TEST(PvdIndex, FifoIsRefusedWithoutBlocking) {
    // On a668953 the ifstream open of a FIFO waited for a writer that never came.
    ScratchDir caseDir("pvdFifo");
    const auto file = caseDir.path() / "particles.pvd";
    const auto result = mfdyn::test::readFifo(file, [&] { PvdIndex::read(file); });
    EXPECT_FALSE(result.blocked) << "the read blocked for " << result.seconds << " s";
    EXPECT_NE(result.message.find("'" + file.string() + "' is not a regular file"), std::string::npos)
        << result.message;
    // A directory in its place is refused the same way, not read as an empty index.
    std::filesystem::remove(file);
    std::filesystem::create_directory(file);
    try {
        PvdIndex::read(file);
        ADD_FAILURE() << "a directory read as an index";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("is not a regular file (it is a directory)"), std::string::npos)
            << e.what();
    }
}

TEST(PvdIndex, MutatedIndexIsReadOrRefusedCleanly) {
    // A fixed-seed mutation loop over a written index: every result is an index or an
    // InputError, never a crash, a hang or another exception.
    ScratchDir caseDir("pvdMutate");
    const auto file = caseDir.path() / "particles.pvd";
    PvdIndex index(file);
    for (int i = 0; i < 20; ++i) index.add(0.001 * i, std::to_string(0.001 * i) + "/particles.vtp");
    index.write();
    const std::string whole = readFile(file);
    std::mt19937 rng(14);
    const char* hostile[] = {"<", ">", "\"", "&", "&#0;", "nan", "-1e400", "<a>", "</Collection>", "\n", ""};
    std::size_t refused = 0;
    for (int m = 0; m < 300; ++m) {
        std::string text = whole;
        const std::size_t at = rng() % text.size();
        switch (m % 4) {
            case 0:
                text[at] = char(rng());
                break;
            case 1:
                text.insert(at, hostile[rng() % std::size(hostile)]);
                break;
            case 2:
                text.erase(at, rng() % 40);
                break;
            case 3:
                text.resize(at);
                break;
        }
        writeFile(file, text);
        try {
            const PvdIndex back = PvdIndex::read(file);
            for (const auto& e : back.entries()) EXPECT_TRUE(std::isfinite(e.time)) << m;
        } catch (const InputError&) {
            ++refused;
        } catch (const std::exception& e) {
            ADD_FAILURE() << "mutation " << m << ": not an InputError: " << e.what();
        }
    }
    EXPECT_GT(refused, 50u) << "most mutations break the XML";
}

TEST(PvdIndex, PartsOfATimeAreKeptApartAndTruncatedTogether) {
    // A grid method writes grid.vti beside particles.vtp: part 1 of the same time, so that
    // ParaView opens both (grid/VtiWriter.hpp). Before parts, add() at the same time replaced
    // the particles' entry with the grid's.
    ScratchDir caseDir("pvdParts");
    const auto file = caseDir.path() / "particles.pvd";
    PvdIndex index(file);
    for (double t : {0.1, 0.2}) {
        const std::string dir = t == 0.1 ? "0.1" : "0.2";
        index.add(t, dir + "/particles.vtp");
        index.add(t, dir + "/grid.vti", 1);
    }
    index.add(0.1, "0.1/grid2.vti", 1);  // the same time and part: replaced
    index.write();
    const std::string text = readFile(file);
    EXPECT_NE(text.find("<DataSet timestep=\"0.10000000000000001\" part=\"1\" file=\"0.1/grid2.vti\"/>"),
              std::string::npos)
        << text;
    PvdIndex back = PvdIndex::read(file);
    ASSERT_EQ(back.entries().size(), 4u);
    EXPECT_EQ(back.entries()[0].file, "0.1/particles.vtp");
    EXPECT_EQ(back.entries()[1].part, 1);
    EXPECT_EQ(back.entries()[3].file, "0.2/grid.vti");
    back.truncateAfter(0.1);
    ASSERT_EQ(back.entries().size(), 2u);
    EXPECT_EQ(back.entries()[0].part, 0);
    EXPECT_EQ(back.entries()[1].part, 1);

    // Read: listed grid first, particles second, a part repeated (the last kept); no part
    // attribute is part 0; a part that is not a non-negative integer is an error at its line.
    writeFile(file,
              "<VTKFile type=\"Collection\"><Collection>\n"
              "<DataSet timestep=\"1\" part=\"1\" file=\"1/old.vti\"/>\n"
              "<DataSet timestep=\"1\" part=\"1\" file=\"1/grid.vti\"/>\n"
              "<DataSet timestep=\"1\" file=\"1/particles.vtp\"/>\n"
              "</Collection></VTKFile>\n");
    const PvdIndex sorted = PvdIndex::read(file);
    ASSERT_EQ(sorted.entries().size(), 2u);
    EXPECT_EQ(sorted.entries()[0].file, "1/particles.vtp");
    EXPECT_EQ(sorted.entries()[1].file, "1/grid.vti");
    writeFile(file,
              "<VTKFile type=\"Collection\"><Collection>\n"
              "<DataSet timestep=\"1\" part=\"-1\" file=\"1/particles.vtp\"/>\n"
              "</Collection></VTKFile>\n");
    try {
        PvdIndex::read(file);
        FAIL() << "a negative part must be refused";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("line 2: part \"-1\" is not a non-negative integer"),
                  std::string::npos)
            << e.what();
    }
}
