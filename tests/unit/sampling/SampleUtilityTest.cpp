// The sample utility end to end: a small 2D case written with writeTimeDirectory, sampled with
// first-order MLS, so that the linear fields it carries come back exactly (to the 10
// significant digits of the CSV).
#include "core/Dictionary.hpp"
#include "particles/ParticleSet.hpp"
#include "particles/TimeDirectory.hpp"

#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

using namespace mfdyn;
namespace fs = std::filesystem;

namespace {

class SampleCase : public ::testing::Test {
protected:
    void SetUp() override {
        dir_ = fs::temp_directory_path() / ("mfdynSampleTest-" + std::to_string(::getpid()) + "-" +
                                            ::testing::UnitTest::GetInstance()->current_test_info()->name());
        fs::remove_all(dir_);
        fs::create_directories(dir_ / "system");
    }
    void TearDown() override { fs::remove_all(dir_); }

    // 21 x 21 particles on [0, 1]^2 with density = 1000 + 10x and velocity = (x, -2y) + t (1, 0).
    void writeTime(const std::string& name, double t) {
        const int n = 21;
        ParticleSet<2> p(n * n);
        auto& rho = p.scalarField("density");
        auto& u = p.vectorField("velocity");
        for (int i = 0; i < n * n; ++i) {
            const Vector<2> x((i % n) / double(n - 1), (i / n) / double(n - 1));
            p.position()[i] = x;
            p.globalId()[i] = i;
            rho[i] = 1000.0 + 10.0 * x(0);
            u[i] = Vector<2>(x(0) + t, -2.0 * x(1));
        }
        writeTimeDirectory(dir_, name, p);
    }

    void writeSampleDict(const std::string& fields, bool plot = false) {
        std::ofstream(dir_ / "system" / "sampleDict")
            << "interpolation mls;\nkernel { type wendlandC2; }\nh 0.065;\nfields (" << fields << ");\n"
            << "sets\n{\n    centreline { type line; start (0.2 0.5 0); end (0.8 0.5 0); nPoints 7; }\n"
            << "    gauges { type points; points ((0.25 0.75 0) (0.5 0.5 0)); }\n}\n"
            << "plot " << (plot ? "yes" : "no") << ";\n";
    }

    // Runs sample with `options`; returns its exit status, with its output in output_.
    int sample(const std::string& options) {
        const fs::path log = dir_ / "sample.log";
        const std::string command = std::string(MFDYN_SAMPLE_EXE) + " -case " + dir_.string() + " " +
                                    options + " > " + log.string() + " 2>&1";
        const int status = std::system(command.c_str());
        output_ = read(log);
        return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    }

    static std::string read(const fs::path& file) {
        std::ifstream in(file);
        std::stringstream s;
        s << in.rdbuf();
        return s.str();
    }

    static std::vector<std::string> lines(const std::string& text) {
        std::vector<std::string> out;
        std::istringstream in(text);
        for (std::string line; std::getline(in, line);) out.push_back(line);
        return out;
    }

    static std::vector<double> numbers(const std::string& line) {
        std::vector<double> out;
        std::istringstream in(line);
        for (std::string cell; std::getline(in, cell, ',');) out.push_back(std::stod(cell));
        return out;
    }

    fs::path dir_;
    std::string output_;
};

}  // namespace

TEST_F(SampleCase, latestTimeLineAndPoints) {
    writeTime("0", 0.0);
    writeTime("0.5", 0.5);
    writeSampleDict("density velocity", true);
    ASSERT_EQ(sample("-latestTime"), 0) << output_;
    // A plot for the line set only, or a note that gnuplot is missing.
    const fs::path png = dir_ / "postProcessing" / "sample" / "0.5" / "centreline.png";
    EXPECT_TRUE(fs::exists(png) || output_.find("gnuplot not found") != std::string::npos) << output_;
    EXPECT_FALSE(fs::exists(dir_ / "postProcessing" / "sample" / "0.5" / "gauges.png"));
    EXPECT_FALSE(fs::exists(dir_ / "postProcessing" / "sample" / "0"));

    const auto line = lines(read(dir_ / "postProcessing" / "sample" / "0.5" / "centreline.csv"));
    ASSERT_EQ(line.size(), 8u);
    EXPECT_EQ(line[0], "distance,x,y,z,density,velocity_x,velocity_y");
    // Point 3 of 7 from (0.2, 0.5) to (0.8, 0.5) is (0.5, 0.5), at distance 0.3: density 1005,
    // velocity (0.5 + 0.5, -1). The CSV holds 10 significant digits, so 1e-9 relative.
    const auto mid = numbers(line[4]);
    ASSERT_EQ(mid.size(), 7u);
    EXPECT_NEAR(mid[0], 0.3, 1e-12);
    EXPECT_NEAR(mid[1], 0.5, 1e-12);
    EXPECT_NEAR(mid[4], 1005.0, 1005.0 * 1e-9);
    EXPECT_NEAR(mid[5], 1.0, 1e-9);
    EXPECT_NEAR(mid[6], -1.0, 1e-9);

    const auto gauges = lines(read(dir_ / "postProcessing" / "sample" / "0.5" / "gauges.csv"));
    ASSERT_EQ(gauges.size(), 3u);
    EXPECT_EQ(gauges[0], "index,x,y,z,density,velocity_x,velocity_y");
    const auto first = numbers(gauges[1]);
    EXPECT_EQ(first[0], 0.0);
    EXPECT_NEAR(first[4], 1002.5, 1002.5 * 1e-9);
    EXPECT_NEAR(first[6], -1.5, 1e-9);
}

TEST_F(SampleCase, timeSelection) {
    writeTime("0", 0.0);
    writeTime("0.25", 0.25);
    writeTime("0.5", 0.5);
    writeSampleDict("density");
    ASSERT_EQ(sample("-time 0.1:0.5"), 0) << output_;
    EXPECT_FALSE(fs::exists(dir_ / "postProcessing" / "sample" / "0"));
    EXPECT_TRUE(fs::exists(dir_ / "postProcessing" / "sample" / "0.25" / "gauges.csv"));
    EXPECT_TRUE(fs::exists(dir_ / "postProcessing" / "sample" / "0.5" / "gauges.csv"));
    fs::remove_all(dir_ / "postProcessing");
    ASSERT_EQ(sample("-time 0.25"), 0) << output_;
    EXPECT_TRUE(fs::exists(dir_ / "postProcessing" / "sample" / "0.25" / "centreline.csv"));
    EXPECT_FALSE(fs::exists(dir_ / "postProcessing" / "sample" / "0.5"));
    ASSERT_EQ(sample(""), 0) << output_;
    EXPECT_TRUE(fs::exists(dir_ / "postProcessing" / "sample" / "0" / "centreline.csv"));
    EXPECT_EQ(sample("-time 0.7"), 1);
    EXPECT_NE(output_.find("matches no time directory"), std::string::npos) << output_;
}

TEST_F(SampleCase, unknownFieldListsFields) {
    writeTime("0", 0.0);
    writeSampleDict("pressure");
    EXPECT_EQ(sample(""), 1);
    EXPECT_NE(output_.find("no field 'pressure'"), std::string::npos) << output_;
    EXPECT_NE(output_.find("density"), std::string::npos) << output_;
    EXPECT_NE(output_.find("velocity"), std::string::npos) << output_;
}

TEST_F(SampleCase, badSetType) {
    writeTime("0", 0.0);
    std::ofstream(dir_ / "system" / "sampleDict")
        << "h 0.065; fields (density); sets { plane { type plane; } }\n";
    EXPECT_EQ(sample(""), 1);
    EXPECT_NE(output_.find("'plane' is not a set type; valid choices: line | points"), std::string::npos)
        << output_;
}

TEST_F(SampleCase, noTimeDirectories) {
    writeSampleDict("density");
    EXPECT_EQ(sample(""), 1);
    EXPECT_NE(output_.find("no time directories"), std::string::npos) << output_;
}
