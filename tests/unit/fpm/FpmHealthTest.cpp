// fpmSolid's health indicators (FpmSolver::healthIndicators) on a hand-made lattice, run end to end:
// 3 x 3 x 3 particles of spacing 1 with h = 1.5, so that a particle's neighbours of positive fit
// weight are itself, those at distance 1 and those at sqrt(2) (sqrt(3) lies beyond h). A corner
// has 1 + 3 + 3 = 7, an edge's middle 1 + 4 + 5 = 10, a face's centre 1 + 5 + 8 = 14, the centre
// 1 + 6 + 12 = 19: the fewest is 7, the 8 corners fall below the fit's minimum 2(d + 1) = 8 (the
// run goes on with fitFallback shepard), and the worst particle is the corner of lowest id, 0.
#include "../CsvTestTools.hpp"
#include "core/Application.hpp"
#include "fpm/FpmSolver.hpp"
#include "particles/ParticleSet.hpp"
#include "particles/TimeDirectory.hpp"
#include "solver/SolverRun.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include <unistd.h>

namespace mfdyn {
namespace {

namespace fs = std::filesystem;

void writeFile(const fs::path& file, const std::string& text) {
    fs::create_directories(file.parent_path());
    std::ofstream(file) << text;
}

std::map<std::string, double> lastHealthRow(const fs::path& dir) {
    return mfdyn::testing::lastCsvRow(dir / "postProcessing/health/0/health.csv");
}

TEST(FpmHealth, NeighbourDeficiencyOnALatticeByHand) {
    const fs::path dir = fs::temp_directory_path() / ("mfdyn-fpm-health-" + std::to_string(::getpid()));
    fs::remove_all(dir);
    ParticleSet<3> p(27);
    auto& v = p.vectorField("velocity");
    auto& m = p.scalarField("mass");
    auto& rho = p.scalarField("density");
    for (int k = 0; k < 3; ++k)
        for (int j = 0; j < 3; ++j)
            for (int i = 0; i < 3; ++i) {
                const auto a = std::size_t(i + 3 * j + 9 * k);
                p.globalId()[a] = std::int64_t(a);
                p.position()[a] = Vector<3>(i, j, k);
                v[a] = Vector<3>::Zero();
                m[a] = 1;
                rho[a] = 1;
            }
    writeFile(dir / "system/controlDict",
              "application fpmSolid;\nstartFrom startTime;\nstartTime 0;\nstopAt endTime;\nendTime 0.01;\n"
              "deltaT 0.01;\nadjustTimeStep no;\nwriteControl timeStep;\nwriteInterval 1;\n");
    writeFile(dir / "constant/fpmProperties",
              "subsystems (rotation);\nfitWeight { type truncatedGaussian; alpha 6.25; squared yes; }\n"
              "order 1;\nderivatives full;\nfitFallback shepard;\nsmoothingLength 1.5;\n"
              "motion { velocity frozen; }\n");
    writeTimeDirectory(dir, "0", p);
    ApplicationInfo info{"fpmSolid", "the fpmSolid unit tests", {}, {}};
    std::string a0 = "fpmSolid", a1 = "-case", a2 = dir.string();
    char* argv[] = {a0.data(), a1.data(), a2.data()};
    ASSERT_EQ(runSolver<FpmSolver>(Arguments::parse(3, argv, info), "fpmSolid"), 0);
    auto row = lastHealthRow(dir);
    ASSERT_TRUE(row.count("neighbourDeficiency") && row.count("fitConditioning"));
    EXPECT_EQ(row["neighbourDeficiency"], 7);
    EXPECT_EQ(row["neighbourDeficiency_count"], 8);
    EXPECT_EQ(row["neighbourDeficiency_worstId"], 0);
    // Every fit of 7 or more points around the lattice's particles is well posed (linear basis):
    // none below minReciprocalCondition 1e-10, and none better than a perfect 1.
    EXPECT_EQ(row["fitConditioning_count"], 0);
    EXPECT_GT(row["fitConditioning"], 1e-3);
    EXPECT_LE(row["fitConditioning"], 1);
    fs::remove_all(dir);
}

}  // namespace
}  // namespace mfdyn
