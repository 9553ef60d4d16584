// CsvFile, the postProcessing/ CSV writer (issue 14): nothing is touched before the first row, a
// time series continues an earlier run's file from the start time, and a file with other columns
// is moved aside rather than mixed or lost.
#include "core/Dictionary.hpp"
#include "functionObjects/CsvFile.hpp"
#include "functionObjects/FunctionObject.hpp"
#include "particles/ParticleSet.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>

using namespace mfdyn;
namespace fs = std::filesystem;

namespace {

std::string read(const fs::path& file) {
    std::ifstream in(file, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

void put(const fs::path& file, const std::string& text) {
    fs::create_directories(file.parent_path());
    std::ofstream(file, std::ios::binary) << text;
}

class CsvFileTest : public ::testing::Test {
protected:
    void SetUp() override {
        root = fs::temp_directory_path() / ("mfdynCsvFileTest-" + std::to_string(::getpid()) + "-" +
                                            ::testing::UnitTest::GetInstance()->current_test_info()->name());
        fs::remove_all(root);
        fs::create_directories(root);
    }
    void TearDown() override { fs::remove_all(root); }
    fs::path root;
};

const std::string earlierRun =
    "time,a,b\n"
    "0,1,2\n"
    "0.1,3,4\n"
    "0.2,5,6\n"
    "0.3,7,8\n"
    "0.4,9,1";  // cut off by a kill: no newline

}  // namespace

TEST_F(CsvFileTest, ConstructionTouchesNothing) {
    const fs::path series = root / "a" / "0" / "series.csv", table = root / "b" / "0" / "table.csv";
    put(series, earlierRun);
    {
        CsvFile csv(series, {"time", "a", "b"});
        CsvFile other(root / "c" / "0" / "new.csv", {"time", "x"});
        EXPECT_EQ(read(series), earlierRun);
        EXPECT_FALSE(fs::exists(root / "c")) << "directory created before any row";
    }
    // A series that got no row leaves the old file as it was and makes no new one.
    EXPECT_EQ(read(series), earlierRun);
    EXPECT_FALSE(fs::exists(root / "c"));
    // A table (first column not time) is written whole: with no row, its header.
    { CsvFile csv(table, {"x", "y"}); }
    EXPECT_EQ(read(table), "x,y\n");
}

// The defect: with ios::trunc at construction, a FunctionObjectList whose last entry was bad
// emptied the earlier objects' CSVs (to their header) before the run stopped on the error.
TEST_F(CsvFileTest, BadLastFunctionObjectLeavesEarlierCsvsAlone) {
    class Context final : public RunContext {
    public:
        explicit Context(const fs::path& root)
            : case_(root),
              time_(root / "system" / "controlDict",
                    Dictionary::parse("endTime 1; deltaT 0.1; writeInterval 1;", "controlDict")) {
            time_.start(0.0, "0");
            particles.resize(3);
            particles.scalarField("density");
        }
        const Case& runCase() const override { return case_; }
        const Time& time() const override { return time_; }
        const FieldStore& fields() const override { return particles; }
        const std::string& startTimeName() const override { return start_; }
        ParticleSet<2> particles;

    private:
        Case case_;
        Time time_;
        std::string start_ = "0";
    };
    fs::create_directories(root / "system");
    Context context(root);
    const fs::path csv = root / "postProcessing" / "minMax" / "0" / "fieldMinMax.csv";
    const std::string earlier = "time,density_min,density_minId,density_max,density_maxId\n0,1,0,1,0\n";
    put(csv, earlier);
    const Dictionary controlDict = Dictionary::parse(
        "functions { minMax { type fieldMinMax; fields (density); } bad { type noSuchFunctionObject; } }",
        "controlDict");
    EXPECT_THROW(FunctionObjectList(controlDict, context), InputError);
    EXPECT_EQ(read(csv), earlier);
}

TEST_F(CsvFileTest, RestartContinuesTheSeriesFromTheStartTime) {
    const fs::path file = root / "series.csv";
    put(file, earlierRun);
    {
        // Restarted from t = 0.2: the rows before it stay, the row at 0.2 and after (and the cut
        // row) belonged to the earlier run's future and are replaced by this run's.
        CsvFile csv(file, {"time", "a", "b"}, 0.2);
        EXPECT_EQ(read(file), earlierRun);
        csv.row({0.2, 50, 60});
        csv.row({0.25, 70, 80});
    }
    EXPECT_EQ(read(file), "time,a,b\n0,1,2\n0.1,3,4\n0.2,50,60\n0.25,70,80\n");
    // The earlier run's rows that were replaced are not lost; no temporary is left behind.
    EXPECT_EQ(read(root / "series.csv.old"), earlierRun);
    EXPECT_EQ(std::distance(fs::directory_iterator(root), fs::directory_iterator()), 2);

    // A rerun from the start replaces every row; with the start time taken from the first row
    // when none is given.
    {
        CsvFile csv(file, {"time", "a", "b"});
        csv.row({0, 9, 9});
    }
    EXPECT_EQ(read(file), "time,a,b\n0,9,9\n");
    EXPECT_EQ(read(root / "series.csv.old1"), "time,a,b\n0,1,2\n0.1,3,4\n0.2,50,60\n0.25,70,80\n");

    // Only a cut-off row to drop: nothing worth an aside copy.
    put(file, "time,a,b\n0,1,2\n0.1,3");
    {
        CsvFile csv(file, {"time", "a", "b"}, 0.1);
        csv.row({0.1, 4, 5});
    }
    EXPECT_EQ(read(file), "time,a,b\n0,1,2\n0.1,4,5\n");
    EXPECT_FALSE(fs::exists(root / "series.csv.old2"));
}

TEST_F(CsvFileTest, ContinuationAppendsToACompleteFileAndKeepsLabelledRows) {
    const fs::path file = root / "errorNorms.csv";
    const std::string earlier = "time,field,L1,L2,Linf\n0.1,density,1,2,3\n0.1,pressure,4,5,6\n";
    put(file, earlier);
    {
        CsvFile csv(file, {"time", "field", "L1", "L2", "Linf"}, 0.2);
        csv.row(0.2, "density", {7, 8, 9});
    }
    EXPECT_EQ(read(file), earlier + "0.2,density,7,8,9\n");
}

TEST_F(CsvFileTest, OtherColumnsMoveTheOldFileAsideRatherThanMix) {
    const fs::path file = root / "probes.csv";
    put(file, earlierRun);
    {
        CsvFile csv(file, {"time", "a", "b", "c"}, 0.2);
        csv.row({0.2, 1, 2, 3});
    }
    EXPECT_EQ(read(file), "time,a,b,c\n0.2,1,2,3\n");
    EXPECT_EQ(read(root / "probes.csv.old"), earlierRun);
    // A second change keeps the first aside copy too.
    {
        CsvFile csv(file, {"time", "a"}, 0.3);
        csv.row({0.3, 1});
    }
    EXPECT_EQ(read(file), "time,a\n0.3,1\n");
    EXPECT_EQ(read(root / "probes.csv.old"), earlierRun);
    EXPECT_EQ(read(root / "probes.csv.old1"), "time,a,b,c\n0.2,1,2,3\n");
}
