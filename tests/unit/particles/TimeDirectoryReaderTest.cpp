// Reading a time directory however many ranks wrote it (particles/TimeDirectoryReader.hpp): a
// one-process run restarts from the pieces of a run on three ranks. The pieces are written here
// with the functions the distributed writeTimeDirectory uses (writeVtp with the run's next id,
// writePvtp); tests/unit/mpi writes them through writeTimeDirectory under mpirun.
#include "particles/TimeDirectoryReader.hpp"

#include "PieceTestTools.hpp"
#include "TestFiles.hpp"
#include "core/Case.hpp"
#include "particles/ParticleSet.hpp"
#include "particles/TimeDirectory.hpp"
#include "particles/VtpWriter.hpp"

#include <gtest/gtest.h>

using namespace mfdyn;
using mfdyn::test::expectAllPiecesInIdOrder;
using mfdyn::test::pieceOfRank;
using mfdyn::test::readFile;
using mfdyn::test::ScratchDir;
using mfdyn::test::writeFile;
namespace fs = std::filesystem;

namespace {

constexpr int ranks = 3;
constexpr std::int64_t total = 11;  // 4, 4 and 3 particles

// <dir>/particles_<r>.vtp for r < ranks and the index of them, as a run on `ranks` ranks writes
// them (nextGlobalId: the run's, the largest of the ranks').
void writeThreePieces(const fs::path& dir, double time, std::int64_t nextGlobalId = 0) {
    fs::create_directories(dir);
    std::vector<std::string> names;
    for (int r = 0; r < ranks; ++r) {
        names.push_back(particlePieceFileName(r));
        writeVtp(dir / names.back(), pieceOfRank(r, ranks, total), time, nextGlobalId);
    }
    writePvtp(dir / particleIndexFileName, pieceOfRank(0, ranks, total), names);
}

std::string inputErrorOf(const fs::path& timeDir) {
    try {
        readTimeParticles(timeDir);
    } catch (const InputError& e) {
        return e.what();
    }
    return "no InputError";
}

}  // namespace

TEST(TimeDirectoryReader, ThreePiecesReadAsOneSetInGlobalIdOrder) {
    ScratchDir caseDir("pieces");
    const fs::path dir = caseDir.path() / "0.25";
    writeThreePieces(dir, 0.25);
    EXPECT_EQ(timeParticleFile(dir), dir / "particles.pvtp");
    const ParticleFile back = readTimeParticles(dir);
    EXPECT_TRUE(back.hasTime);
    EXPECT_EQ(back.time, 0.25);
    expectAllPiecesInIdOrder(*back.particles, total);
    EXPECT_EQ(back.particles->nextGlobalId(), total);
    EXPECT_EQ(back.particles->source(), (dir / "particles.pvtp").string())
        << "a field asked for with another type is then the index's fault";
}

TEST(TimeDirectoryReader, TheIndexListsThePiecesAndTheirArrays) {
    ScratchDir caseDir("index");
    writeThreePieces(caseDir.path(), 0.0);
    const std::string index = readFile(caseDir.path() / particleIndexFileName);
    EXPECT_EQ(
        index,
        "<?xml version=\"1.0\"?>\n"
        "<VTKFile type=\"PPolyData\" version=\"1.0\" byte_order=\"LittleEndian\" header_type=\"UInt64\">\n"
        "  <PPolyData GhostLevel=\"0\">\n"
        "    <PPointData>\n"
        "      <PDataArray type=\"Int64\" Name=\"globalId\" NumberOfComponents=\"1\"/>\n"
        "      <PDataArray type=\"Int64\" Name=\"region\" NumberOfComponents=\"1\"/>\n"
        "      <PDataArray type=\"Float64\" Name=\"density\" NumberOfComponents=\"1\"/>\n"
        "      <PDataArray type=\"Float64\" Name=\"velocity\" NumberOfComponents=\"3\"/>\n"
        "    </PPointData>\n"
        "    <PPoints>\n"
        "      <PDataArray type=\"Float64\" Name=\"position\" NumberOfComponents=\"3\"/>\n"
        "    </PPoints>\n"
        "    <Piece Source=\"particles_0.vtp\"/>\n"
        "    <Piece Source=\"particles_1.vtp\"/>\n"
        "    <Piece Source=\"particles_2.vtp\"/>\n"
        "  </PPolyData>\n"
        "</VTKFile>\n");
#ifdef MFDYN_XMLLINT
    const std::string command =
        std::string(MFDYN_XMLLINT) + " --noout " + (caseDir.path() / particleIndexFileName).string();
    EXPECT_EQ(std::system(command.c_str()), 0);
#endif
}

TEST(TimeDirectoryReader, TheNextGlobalIdIsTheLargestOfThePieces) {
    // Particle 10 (the highest id) was removed before the write: the run's next id, 11, travels in
    // every piece whose own ids imply less, so a restart never issues 10 again.
    ScratchDir caseDir("nextId");
    const fs::path dir = caseDir.path();
    fs::create_directories(dir);
    std::vector<std::string> names;
    for (int r = 0; r < ranks; ++r) {
        names.push_back(particlePieceFileName(r));
        writeVtp(dir / names.back(), pieceOfRank(r, ranks, total - 1), 0.0, total);
    }
    writePvtp(dir / particleIndexFileName, pieceOfRank(0, ranks, total), names);
    ParticleFile back = readTimeParticles(dir);
    expectAllPiecesInIdOrder(*back.particles, total - 1);
    EXPECT_EQ(back.particles->nextGlobalId(), total);
    // Carried by one piece alone, the largest still wins.
    writeVtp(dir / names[0], pieceOfRank(0, ranks, total - 1), 0.0);
    writeVtp(dir / names[1], pieceOfRank(1, ranks, total - 1), 0.0, total + 5);
    back = readTimeParticles(dir);
    EXPECT_EQ(back.particles->nextGlobalId(), total + 5);
}

TEST(TimeDirectoryReader, PiecesMayListTheirFieldsInAnyOrderAndBeEmpty) {
    // Fields are created in the order models ask for them, which may differ between ranks; a rank
    // may own no particle at all.
    ScratchDir caseDir("order");
    const fs::path dir = caseDir.path();
    ParticleSet<2> reversed = pieceOfRank(1, 2, 6);
    ParticleSet<2> other(reversed.size());
    other.vectorField("velocity") = reversed.vectorField("velocity");
    other.scalarField("density") = reversed.scalarField("density");
    other.position() = reversed.position();
    other.globalId() = reversed.globalId();
    other.region() = reversed.region();
    other.regionNames = reversed.regionNames;
    ParticleSet<2> empty(0);
    empty.scalarField("density");
    empty.vectorField("velocity");
    writeVtp(dir / "a.vtp", pieceOfRank(0, 2, 6), 0.0);
    writeVtp(dir / "b.vtp", other, 0.0);
    writeVtp(dir / "c.vtp", empty, 0.0);
    writePvtp(dir / particleIndexFileName, pieceOfRank(0, 2, 6), {"a.vtp", "c.vtp", "b.vtp"});
    const ParticleFile back = readTimeParticles(dir);
    expectAllPiecesInIdOrder(*back.particles, 6);
}

TEST(TimeDirectoryReader, ParticlesVtpComesFirstAndLatestTimeSeesAnIndexAlone) {
    ScratchDir caseDir("which");
    const fs::path one = caseDir.path() / "0.5", pieces = caseDir.path() / "1";
    writeTimeDirectory(caseDir.path(), "0.5", pieceOfRank(0, 1, 4));
    writeThreePieces(pieces, 1.0);
    EXPECT_EQ(timeParticleFile(one), one / particleFileName);
    EXPECT_EQ(timeParticleFile(caseDir.path() / "2"), caseDir.path() / "2" / particleFileName)
        << "nothing there: the name a 'cannot find' gives";
    EXPECT_FALSE(fs::exists(one / particleIndexFileName)) << "one process writes particles.vtp alone";
    EXPECT_STREQ(writtenParticleFileName(), particleFileName);
    const auto latest = Case(caseDir.path()).latestTime();
    ASSERT_TRUE(latest);
    EXPECT_EQ(latest->name, "1");
    ASSERT_TRUE(Case(caseDir.path()).findTime(1.0));
    expectAllPiecesInIdOrder(*readTimeParticles(pieces).particles, total);
    EXPECT_EQ(readTimeParticles(one).particles->size(), 4u);
    const std::string missing = inputErrorOf(caseDir.path() / "2");
    EXPECT_NE(missing.find("particles.vtp nor particles.pvtp"), std::string::npos) << missing;
}

TEST(TimeDirectoryReader, AMissingOrDamagedPieceIsAnInputErrorNamingIt) {
    ScratchDir caseDir("missing");
    const fs::path dir = caseDir.path();
    writeThreePieces(dir, 0.0);
    fs::remove(dir / "particles_1.vtp");
    std::string message = inputErrorOf(dir);
    EXPECT_NE(message.find("particle index '" + (dir / "particles.pvtp").string() + "'"), std::string::npos)
        << message;
    EXPECT_NE(message.find("piece 'particles_1.vtp' (line 14) cannot be read"), std::string::npos) << message;

    writeFile(dir / "particles_1.vtp", readFile(dir / "particles_2.vtp").substr(0, 300));
    message = inputErrorOf(dir);
    EXPECT_NE(message.find("piece 'particles_1.vtp' (line 14) cannot be read: "), std::string::npos)
        << message;
}

TEST(TimeDirectoryReader, PiecesThatDisagreeAreAnInputErrorNamingThem) {
    ScratchDir caseDir("disagree");
    const fs::path dir = caseDir.path();
    writeThreePieces(dir, 0.0);
    ParticleSet<2> extra = pieceOfRank(2, ranks, total);
    extra.scalarField("pressure");
    writeVtp(dir / "particles_2.vtp", extra, 0.0);
    std::string message = inputErrorOf(dir);
    EXPECT_NE(message.find("piece 'particles_2.vtp' does not hold the arrays the index lists"),
              std::string::npos)
        << message;
    EXPECT_NE(message.find("not listed pressure"), std::string::npos) << message;

    // Without the index's array list, the pieces are compared with each other.
    writeFile(dir / particleIndexFileName,
              "<VTKFile type=\"PPolyData\"><PPolyData><Piece Source=\"particles_0.vtp\"/>"
              "<Piece Source=\"particles_2.vtp\"/></PPolyData></VTKFile>\n");
    message = inputErrorOf(dir);
    EXPECT_NE(message.find("pieces 'particles_0.vtp' and 'particles_2.vtp' disagree in fields: only in "
                           "'particles_0.vtp': none; only in 'particles_2.vtp': pressure"),
              std::string::npos)
        << message;

    ParticleSet<2> other = pieceOfRank(2, ranks, total);
    other.regionNames = {"left", "middle"};
    writeVtp(dir / "particles_2.vtp", other, 0.0);
    message = inputErrorOf(dir);
    EXPECT_NE(message.find("region names disagree: id 1 is 'right' in piece 'particles_0.vtp' but 'middle'"),
              std::string::npos)
        << message;

    writeVtp(dir / "particles_2.vtp", pieceOfRank(2, ranks, total), 0.5);
    message = inputErrorOf(dir);
    EXPECT_NE(message.find("are of different times"), std::string::npos) << message;

    ParticleSet<3> deeper(2);
    writeVtp(dir / "particles_2.vtp", deeper, 0.0);
    message = inputErrorOf(dir);
    EXPECT_NE(message.find("disagree in dimension (2D and 3D)"), std::string::npos) << message;
}

TEST(TimeDirectoryReader, AParticleInTwoPiecesIsAnInputError) {
    ScratchDir caseDir("twice");
    const fs::path dir = caseDir.path();
    writeThreePieces(dir, 0.0);
    writeFile(dir / particleIndexFileName,
              "<VTKFile type=\"PPolyData\"><PPolyData><Piece Source=\"particles_0.vtp\"/>"
              "<Piece Source=\"./particles_0.vtp\"/></PPolyData></VTKFile>\n");
    std::string message = inputErrorOf(dir);
    EXPECT_NE(message.find("globalId 0 is held by piece 'particles_0.vtp' and by piece './particles_0.vtp'"),
              std::string::npos)
        << message;
    writeFile(dir / particleIndexFileName,
              "<VTKFile type=\"PPolyData\"><PPolyData><Piece Source=\"particles_0.vtp\"/>\n"
              "<Piece Source=\"particles_0.vtp\"/></PPolyData></VTKFile>\n");
    message = inputErrorOf(dir);
    EXPECT_NE(message.find("piece 'particles_0.vtp' is listed twice (lines 1 and 2)"), std::string::npos)
        << message;
}

TEST(TimeDirectoryReader, AnIndexOpensOnlyFilesBesideIt) {
    ScratchDir caseDir("outside");
    const fs::path dir = caseDir.path() / "1";
    writeThreePieces(dir, 0.0);
    for (const std::string& source :
         {std::string("../1/particles_0.vtp"), (dir / "particles_0.vtp").string()}) {
        writeFile(dir / particleIndexFileName, "<VTKFile type=\"PPolyData\"><PPolyData><Piece Source=\"" +
                                                   source + "\"/></PPolyData></VTKFile>\n");
        const std::string message = inputErrorOf(dir);
        EXPECT_NE(message.find("is not a file beside the index"), std::string::npos) << message;
    }
    for (const std::string& text : {std::string("<VTKFile type=\"PPolyData\"><PPolyData/></VTKFile>"),
                                    std::string("<VTKFile type=\"PolyData\"><PPolyData/></VTKFile>"),
                                    std::string("<VTKFile type=\"PPolyData\"><PPolyData><Piece/>"
                                                "</PPolyData></VTKFile>")}) {
        writeFile(dir / particleIndexFileName, text);
        const std::string message = inputErrorOf(dir);
        EXPECT_NE(message.find("particle index '" + (dir / particleIndexFileName).string() + "'"),
                  std::string::npos)
            << text << ": " << message;
    }
}
