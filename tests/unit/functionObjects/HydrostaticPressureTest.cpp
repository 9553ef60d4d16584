// hydrostaticPressure (issue 18 item 5: the pressure along a line against rho g (H - h)) on a
// hand-made column, built through FunctionObject::New from a dictionary as controlDict gives it:
// the binning by height, the measured and the given free surface, the band left out below it, the
// sampling line (particles off it ignored), the error norms and the worst bin, and the refused
// input. The column: rho 1000, g 10, ten particles at h = 0.05, 0.15, ..., 0.95 on the line x = 0.5
// with p = rho g (1 - h), so H = 0.95 + surfaceOffset 0.05 = 1. With surfaceBand 0.2 and 3 bins
// over [0.05, 0.8] (width 0.25) the bins hold h = {0.05, 0.15, 0.25}, {0.35, 0.45}, {0.55, 0.65,
// 0.75}: mean heights 0.15, 0.4, 0.65, exact 8500, 6000, 3500 Pa. A linear p has its bin mean at the
// bin's mean height, so the exact column's errors are round-off (1e-9 relative is ample).
#include "FunctionObjectTestCase.hpp"
#include "core/Dictionary.hpp"
#include "core/Error.hpp"
#include "functionObjects/FunctionObject.hpp"
#include "particles/ParticleSet.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

using namespace mfdyn;
namespace fs = std::filesystem;

namespace {

using Context = functionObjectTest::TestContext<2>;
fs::path freshCase(const std::string& tag) {
    return functionObjectTest::freshCase("Hydrostatic", tag);
}
const auto& rows = functionObjectTest::csvRows;

std::unique_ptr<FunctionObject> make(const std::string& text, const RunContext& c) {
    return FunctionObject::New(Dictionary::parse(text, "controlDict"), "p", c);
}

std::string errorOf(const std::string& text, const RunContext& c) {
    try {
        make(text, c);
    } catch (const InputError& e) {
        return e.what();
    }
    return "no error";
}

// The column (ids 0-9, region water) and two particles of region tank at x = 3 with a pressure
// far from hydrostatic (ids 10, 11 at h = 0.3 and 1.5: above the column, so a measured H over
// every particle would be 1.55).
void column(ParticleSet<2>& p, bool pressure = true) {
    p.resize(12);
    p.regionNames = {"water", "tank"};
    auto& mass = p.scalarField("mass");
    for (std::size_t i = 0; i < 12; ++i) {
        const double h = i < 10 ? 0.05 + 0.1 * double(i) : (i == 10 ? 0.3 : 1.5);
        mass[i] = 1;
        p.position()[i] = Vector<2>(i < 10 ? 0.5 : 3.0, h);
        p.region()[i] = i < 10 ? 0 : 1;
        p.globalId()[i] = std::int64_t(i);
    }
    if (!pressure) return;
    auto& pr = p.scalarField("pressure");
    for (std::size_t i = 0; i < 12; ++i) pr[i] = i < 10 ? 1000.0 * 10.0 * (1 - p.position()[i][1]) : 1e6;
}

const char* columnDict =
    "type hydrostaticPressure; rho 1000; g 10; bins 3; surfaceBand 0.2; surfaceOffset 0.05; "
    "point (0.5 0); halfWidth 0.25;";

}  // namespace

TEST(HydrostaticPressure, ExactColumn) {
    const fs::path root = freshCase("exact");
    Context c(root);
    column(c.particles);
    {
        auto p = make(columnDict, c);
        p->write();
        const auto norms = p->errorNorms();
        ASSERT_EQ(norms.size(), 1u);
        EXPECT_EQ(norms[0].field, "pressure");
        EXPECT_LT(norms[0].Linf, 1e-9 * 8500);
        EXPECT_NEAR(norms[0].exactL1, 6000, 1e-9 * 6000);
        EXPECT_NEAR(norms[0].exactLinf, 8500, 1e-9 * 8500);
        EXPECT_NEAR(norms[0].exactL2, std::sqrt((8500.0 * 8500 + 6000.0 * 6000 + 3500.0 * 3500) / 3), 1e-6);
        const std::string s = p->summary()[0];
        EXPECT_NE(s.find("H = 1,"), std::string::npos) << s;
        EXPECT_NE(s.find("over 3 bins"), std::string::npos) << s;
    }
    const auto profile = rows(root / "postProcessing" / "p" / "0" / "profile.csv");
    ASSERT_EQ(profile.size(), 3u);
    const double height[3] = {0.15, 0.4, 0.65}, exact[3] = {8500, 6000, 3500}, count[3] = {3, 2, 3};
    for (int b = 0; b < 3; ++b) {
        EXPECT_NEAR(profile[b][1], height[b], 1e-9) << "bin " << b;
        EXPECT_NEAR(profile[b][2], exact[b], 1e-6) << "bin " << b;
        EXPECT_NEAR(profile[b][3], exact[b], 1e-6) << "bin " << b;
        EXPECT_EQ(profile[b][5], count[b]) << "bin " << b;
    }
    fs::remove_all(root);
}

// +120 Pa on the particle at h = 0.45: bin 2's mean 6060 against 6000, +1%, the worst bin; the
// norms L1 = 60/3, L2 = sqrt(60^2/3), Linf = 60. The given free surface H = 1 and the region in
// place of the line give the same.
TEST(HydrostaticPressure, WorstBinAndNorms) {
    const fs::path root = freshCase("worst");
    Context c(root);
    column(c.particles);
    c.particles.scalarField("pressure")[4] += 120;
    for (const std::string& text :
         {std::string(columnDict),
          std::string("type hydrostaticPressure; rho 1000; g 10; bins 3; surfaceBand 0.2; "
                      "region water; freeSurface 1;")}) {
        auto p = make(text, c);
        p->write();
        const auto norms = p->errorNorms();
        ASSERT_EQ(norms.size(), 1u) << text;
        EXPECT_NEAR(norms[0].L1, 20, 1e-8) << text;
        EXPECT_NEAR(norms[0].L2, std::sqrt(1200.0), 1e-8) << text;
        EXPECT_NEAR(norms[0].Linf, 60, 1e-8) << text;
        const auto refs = p->referenceValues();
        ASSERT_EQ(refs.size(), 1u);
        EXPECT_EQ(refs[0].name, "worstBin");
        EXPECT_NEAR(refs[0].value, 6060, 1e-8) << text;
        EXPECT_NEAR(refs[0].exact, 6000, 1e-8) << text;
        const std::string s = p->summary()[0];
        EXPECT_NE(s.find("the largest relative error 1% at h = 0.4 "), std::string::npos) << s;
    }
    // Without the line or the region, the tank's particles count: H is 1.5 + 0.05 and the errors huge.
    auto all =
        make("type hydrostaticPressure; rho 1000; g 10; bins 3; surfaceBand 0.2; surfaceOffset 0.05;", c);
    all->write();
    EXPECT_NE(all->summary()[0].find("H = 1.55,"), std::string::npos) << all->summary()[0];
    EXPECT_GT(all->errorNorms()[0].Linf, 1e5);
    all.reset();
    fs::remove_all(root);
}

TEST(HydrostaticPressure, RefusedInput) {
    const fs::path root = freshCase("errors");
    Context c(root);
    column(c.particles);
    const std::string alone =
        errorOf("type hydrostaticPressure; rho 1000; g 10; bins 3; surfaceBand 0.2; point (0.5 0);", c);
    EXPECT_NE(alone.find("point and halfWidth go together"), std::string::npos) << alone;
    EXPECT_NE(alone.find("controlDict"), std::string::npos) << alone;
    const std::string region =
        errorOf("type hydrostaticPressure; rho 1000; g 10; bins 3; surfaceBand 0.2; region watr;", c);
    EXPECT_NE(region.find("water"), std::string::npos) << region;
    EXPECT_NE(region.find("tank"), std::string::npos) << region;
    const std::string band = errorOf("type hydrostaticPressure; rho 1000; g 10; bins 3;", c);
    EXPECT_NE(band.find("surfaceBand"), std::string::npos) << band;
    const std::string bins = errorOf("type hydrostaticPressure; rho 1000; g 10; bins 0; surfaceBand 0;", c);
    EXPECT_NE(bins.find("bins"), std::string::npos) << bins;
    // A run without a pressure field (a solid with a constitutive law): the fields there are.
    Context solid(root);
    column(solid.particles, false);
    const std::string field =
        errorOf("type hydrostaticPressure; rho 1000; g 10; bins 3; surfaceBand 0;", solid);
    EXPECT_NE(field.find("no field 'pressure'"), std::string::npos) << field;
    fs::remove_all(root);
}
