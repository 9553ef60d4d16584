// A time directory written in pieces under mpirun (particles/TimeDirectory.hpp) and read back on
// every rank (particles/TimeDirectoryReader.hpp). Every rank runs each test: a check that fails on
// one rank fails the run.
#include "PieceTestTools.hpp"
#include "TestFiles.hpp"
#include "core/Communicator.hpp"
#include "core/Error.hpp"
#include "particles/TimeDirectory.hpp"
#include "particles/TimeDirectoryReader.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>

using namespace mfdyn;
using mfdyn::test::expectAllPiecesInIdOrder;
using mfdyn::test::pieceOfRank;
using mfdyn::test::readFile;
using mfdyn::test::writeFile;
namespace fs = std::filesystem;

namespace {

// One directory for all ranks: rank 0's scratch name, made by rank 0 and removed by it at the end.
class SharedScratch {
public:
    explicit SharedScratch(const std::string& tag) {
        int pid = ::getpid();
        Communicator::broadcast(&pid, sizeof pid, 0);
        path_ = fs::temp_directory_path() / ("mfdynMpi-" + tag + "-" + std::to_string(pid));
        if (Communicator::rank() == 0) {
            fs::remove_all(path_);
            fs::create_directories(path_);
        }
        Communicator::barrier();
    }
    ~SharedScratch() {
        Communicator::barrier();
        std::error_code ec;
        if (Communicator::rank() == 0) fs::remove_all(path_, ec);
    }
    const fs::path& path() const { return path_; }

private:
    fs::path path_;
};

// What xmllint says of `file` (its VTK header closed as XML where raw appended data follows: the
// binary after '_' is outside XML by design, as in VtpReaderTest).
int xmllint(const fs::path& file, const fs::path& scratch) {
#ifdef MFDYN_XMLLINT
    std::string text = readFile(file);
    if (const std::size_t marker = text.find("<AppendedData"); marker != std::string::npos)
        text = text.substr(0, text.find('_', marker)) + "\n  </AppendedData>\n</VTKFile>\n";
    writeFile(scratch, text);
    return std::system((std::string(MFDYN_XMLLINT) + " --noout " + scratch.string()).c_str());
#else
    (void)file, (void)scratch;
    return 0;
#endif
}

}  // namespace

TEST(TimeDirectoryInPieces, EachRankWritesItsPieceAndEveryRankReadsTheWhole) {
    const int rank = Communicator::rank(), ranks = Communicator::size();
    EXPECT_EQ(ranks, 3) << "registered with mpirun -np 3 (tests/unit/mpi/CMakeLists.txt)";
    SharedScratch caseDir("pieces");
    const std::int64_t total = 3 * ranks + 2;  // the first two ranks hold one more
    const ParticleSet<2> mine = pieceOfRank(rank, ranks, total);
    const fs::path dir = writeTimeDirectory(caseDir.path(), "0.125", mine, {{"state", "step 7;\n"}});
    EXPECT_EQ(dir, caseDir.path() / "0.125");
    EXPECT_STREQ(writtenParticleFileName(), "particles.pvtp");

    // Every rank returns once the directory is in place: all of it is there for every rank.
    EXPECT_TRUE(fs::exists(dir / "particles.pvtp"));
    EXPECT_FALSE(fs::exists(dir / "particles.vtp"));
    EXPECT_EQ(readFile(dir / "state"), "step 7;\n") << "the extra files are rank 0's";
    for (int r = 0; r < ranks; ++r)
        EXPECT_TRUE(fs::exists(dir / ("particles_" + std::to_string(r) + ".vtp")));
    std::size_t entries = 0;
    for ([[maybe_unused]] const auto& e : fs::directory_iterator(caseDir.path())) ++entries;
    EXPECT_EQ(entries, 1u) << "no temporary left beside the time";
    const std::string index = readFile(dir / "particles.pvtp");
    EXPECT_NE(index.find("<PDataArray type=\"Float64\" Name=\"velocity\" NumberOfComponents=\"3\"/>"),
              std::string::npos)
        << index;
    EXPECT_NE(index.find("<Piece Source=\"particles_2.vtp\"/>"), std::string::npos) << index;
    // Outside the case: the other ranks may still be counting its entries.
    const fs::path lintScratch =
        fs::temp_directory_path() / ("mfdynMpiLint-" + std::to_string(::getpid()) + ".xml");
    EXPECT_EQ(xmllint(dir / "particles.pvtp", lintScratch), 0) << index;
    for (int r = 0; r < ranks; ++r)
        EXPECT_EQ(xmllint(dir / particlePieceFileName(r), lintScratch), 0) << "piece " << r;
    std::error_code ec;
    fs::remove(lintScratch, ec);

    // Each piece is that rank's particles alone.
    const ParticleFile piece = readVtp(dir / particlePieceFileName(rank));
    EXPECT_EQ(piece.particles->size(), mine.size());
    EXPECT_EQ(piece.time, 0.125);

    const ParticleFile whole = readTimeParticles(dir);
    EXPECT_EQ(whole.time, 0.125);
    expectAllPiecesInIdOrder(*whole.particles, total);
    EXPECT_EQ(whole.particles->nextGlobalId(), total);
}

TEST(TimeDirectoryInPieces, TheRunsNextIdTravelsWithThePieces) {
    // The particle of the highest id was removed on rank 1 only; the next id must stay above it
    // whichever pieces are read.
    const int rank = Communicator::rank(), ranks = Communicator::size();
    SharedScratch caseDir("nextId");
    const std::int64_t total = 3 * ranks;
    ParticleSet<2> mine = pieceOfRank(rank, ranks, total - 1);
    if (rank == 1) mine.reserveGlobalIdsBelow(total + 5);
    writeTimeDirectory(caseDir.path(), "1", mine);
    const ParticleFile whole = readTimeParticles(caseDir.path() / "1");
    expectAllPiecesInIdOrder(*whole.particles, total - 1);
    EXPECT_EQ(whole.particles->nextGlobalId(), total + 5);
}

TEST(TimeDirectoryInPieces, ReplacingATimeReplacesEveryPiece) {
    const int rank = Communicator::rank(), ranks = Communicator::size();
    SharedScratch caseDir("replace");
    writeTimeDirectory(caseDir.path(), "2", pieceOfRank(rank, ranks, 30), {{"stale", "x"}});
    writeTimeDirectory(caseDir.path(), "2", pieceOfRank(rank, ranks, 7));
    EXPECT_FALSE(fs::exists(caseDir.path() / "2" / "stale"));
    expectAllPiecesInIdOrder(*readTimeParticles(caseDir.path() / "2").particles, 7);
}

TEST(TimeDirectoryInPieces, RanksWithOtherFieldsAreRefusedOnEveryRank) {
    const int rank = Communicator::rank(), ranks = Communicator::size();
    SharedScratch caseDir("fields");
    ParticleSet<2> mine = pieceOfRank(rank, ranks, 9);
    if (rank == 2) mine.scalarField("pressure");
    std::string message;
    try {
        writeTimeDirectory(caseDir.path(), "3", mine);
    } catch (const Error& e) {
        message = e.what();
    }
    EXPECT_NE(message.find("rank 0 alone has [], rank 2 alone has [type=\"Float64\" Name=\"pressure\""),
              std::string::npos)
        << message;
    Communicator::barrier();
    EXPECT_FALSE(fs::exists(caseDir.path() / "3")) << "nothing is written";
}

TEST(TimeDirectoryInPieces, ARankThatCannotWriteItsPieceFailsTheWriteOnEveryRank) {
    const int rank = Communicator::rank(), ranks = Communicator::size();
    SharedScratch caseDir("failing");
    writeTimeDirectory(caseDir.path(), "4", pieceOfRank(rank, ranks, 9), {{"state", "good"}});
    // Rank 1's piece cannot be written (a region name the file format cannot hold); the others' can.
    ParticleSet<2> mine = pieceOfRank(rank, ranks, 12);
    if (rank == 1) mine.regionNames[0] = std::string("le\0ft", 5);
    std::string message;
    try {
        writeTimeDirectory(caseDir.path(), "4", mine, {{"state", "bad"}});
    } catch (const Error& e) {
        message = e.what();
    }
    EXPECT_NE(message.find("NUL character"), std::string::npos) << "rank " << rank << ": " << message;
    if (rank != 1) EXPECT_NE(message.find("(on rank 1 of 3)"), std::string::npos) << message;
    Communicator::barrier();
    EXPECT_EQ(readFile(caseDir.path() / "4" / "state"), "good") << "the earlier time is kept whole";
    expectAllPiecesInIdOrder(*readTimeParticles(caseDir.path() / "4").particles, 9);
    std::size_t entries = 0;
    for ([[maybe_unused]] const auto& e : fs::directory_iterator(caseDir.path())) ++entries;
    EXPECT_EQ(entries, 1u) << "the temporary is removed";
}
