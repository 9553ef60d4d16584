// The probes function object in a hand-made run context: a 2D lattice carrying linear fields,
// so that first-order MLS gives the exact values at the probes (to the 10 digits of the CSV).
// In the same context, the functionObject family's keyword schemas (FunctionObjectKeywords).
#include "core/Dictionary.hpp"
#include "functionObjects/CableError.hpp"
#include "functionObjects/ConservedQuantities.hpp"
#include "functionObjects/DebrisCloud.hpp"
#include "functionObjects/EllipticalDropError.hpp"
#include "functionObjects/FieldMinMax.hpp"
#include "functionObjects/FunctionObject.hpp"
#include "functionObjects/IsothermalShockBarError.hpp"
#include "functionObjects/Probes.hpp"
#include "functionObjects/RiemannError.hpp"
#include "functionObjects/SwingingCubeError.hpp"
#include "particles/ParticleSet.hpp"

#include "../SchemaTestTools.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

using namespace mfdyn;
namespace fs = std::filesystem;

namespace {

const char* controlDictText = "endTime 1; deltaT 0.1; writeControl timeStep; writeInterval 1;\n";

class TestContext final : public RunContext {
public:
    explicit TestContext(const fs::path& root)
        : case_(root),
          time_(root / "system" / "controlDict", Dictionary::parse(controlDictText, "controlDict")) {
        time_.start(0.0, "0");
    }
    const Case& runCase() const override { return case_; }
    const Time& time() const override { return time_; }
    const FieldStore& fields() const override { return particles; }
    const std::string& startTimeName() const override { return start_; }

    Time& mutableTime() { return time_; }
    ParticleSet<2> particles;

private:
    Case case_;
    Time time_;
    std::string start_ = "0";
};

std::vector<std::string> lines(const fs::path& file) {
    std::ifstream in(file);
    std::vector<std::string> out;
    for (std::string line; std::getline(in, line);) out.push_back(line);
    return out;
}

std::vector<double> numbers(const std::string& line) {
    std::vector<double> out;
    std::istringstream in(line);
    for (std::string cell; std::getline(in, cell, ',');) out.push_back(std::stod(cell));
    return out;
}

// 21 x 21 particles on [0, 1]^2 shifted by `shift` in x; density = 1000 + 10x, velocity = (x, -2y).
void fill(ParticleSet<2>& p, double shift) {
    const int n = 21;
    p.resize(n * n);
    auto& rho = p.scalarField("density");
    auto& u = p.vectorField("velocity");
    for (int i = 0; i < n * n; ++i) {
        const Vector<2> x((i % n) / double(n - 1) + shift, (i / n) / double(n - 1));
        p.position()[i] = x;
        rho[i] = 1000.0 + 10.0 * x(0);
        u[i] = Vector<2>(x(0), -2.0 * x(1));
    }
}

}  // namespace

TEST(Probes, writesInterpolatedValuesPerWrite) {
    const fs::path root = fs::temp_directory_path() / ("mfdynProbesTest-" + std::to_string(::getpid()));
    fs::remove_all(root);
    fs::create_directories(root / "system");
    std::ofstream(root / "system" / "controlDict") << controlDictText;
    {
        TestContext context(root);
        fill(context.particles, 0.0);
        const Dictionary dict = Dictionary::parse(
            "type probes; fields (velocity density); points ((0.5 0.5 0) (0.3 0.6 0) (5 5 0));"
            "interpolation mls; h 0.065;",
            "probes");
        auto probes = FunctionObject::New(dict, "gauges", context);
        probes->write();
        // Move the particles by 0.1 in x: the fields move with them, so the values at the
        // fixed probes change; the interpolation must follow.
        context.mutableTime().advance(0.1);
        fill(context.particles, 0.1);
        probes->write();
    }
    const auto csv = lines(root / "postProcessing" / "gauges" / "0" / "probes.csv");
    ASSERT_EQ(csv.size(), 3u);
    EXPECT_EQ(csv[0],
              "time,p0_velocity_x,p0_velocity_y,p0_density,p1_velocity_x,p1_velocity_y,p1_density,"
              "p2_velocity_x,p2_velocity_y,p2_density");
    const auto first = numbers(csv[1]), second = numbers(csv[2]);
    ASSERT_EQ(first.size(), 10u);
    EXPECT_EQ(first[0], 0.0);
    EXPECT_NEAR(first[1], 0.5, 1e-9);
    EXPECT_NEAR(first[2], -1.0, 1e-9);
    EXPECT_NEAR(first[3], 1005.0, 1005.0 * 1e-9);
    EXPECT_NEAR(first[4], 0.3, 1e-9);
    EXPECT_NEAR(first[5], -1.2, 1e-9);
    EXPECT_TRUE(std::isnan(first[7]));  // probe 2 lies beyond every particle
    // The fields are functions of the particle positions, so after the shift they are the same
    // linear functions of x: unchanged values at the probes, now from other particles.
    EXPECT_NEAR(second[0], 0.1, 1e-12);
    EXPECT_NEAR(second[1], 0.5, 1e-9);
    EXPECT_NEAR(second[6], 1003.0, 1003.0 * 1e-9);
    fs::remove_all(root);
}

TEST(Probes, unknownFieldIsAnInputError) {
    const fs::path root = fs::temp_directory_path() / ("mfdynProbesTest2-" + std::to_string(::getpid()));
    fs::create_directories(root / "system");
    std::ofstream(root / "system" / "controlDict") << controlDictText;
    TestContext context(root);
    fill(context.particles, 0.0);
    const Dictionary dict =
        Dictionary::parse("type probes; fields (pressure); points ((0.5 0.5 0)); h 0.065;", "probes");
    try {
        FunctionObject::New(dict, "gauges", context);
        ADD_FAILURE() << "no error";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("no field 'pressure'"), std::string::npos) << e.what();
    }
    fs::remove_all(root);
}

TEST(FunctionObjectKeywords, EveryTypeDeclaresItsKeywordsThenWriteControl) {
    const auto schemas = {CableError::keywords(),       ConservedQuantities::keywords(),
                          DebrisCloud::keywords(),      EllipticalDropError::keywords(),
                          FieldMinMax::keywords(),      IsothermalShockBarError::keywords(),
                          Probes::keywords(),           RiemannError::keywords(),
                          SwingingCubeError::keywords()};
    test::expectRegisteredSchemas("functionObject", schemas, "libraries/functionObjects/");
    const KeywordSchema common = functionObjectKeywords();
    for (const KeywordSchema& schema : schemas) test::expectEndsWith(schema, common);
    EXPECT_EQ(common.find("writeControl")->defaultValue, "timeStep");
    EXPECT_EQ(RiemannError::keywords().find("fields")->defaultValue, "(density velocity pressure)");
    // The interpolation keywords are declared once, with each caller's defaults.
    EXPECT_EQ(Probes::keywords().find("interpolation")->defaultValue, "shepard");
    EXPECT_EQ(SwingingCubeError::keywords().find("interpolation")->defaultValue, "mls");
    EXPECT_EQ(SwingingCubeError::keywords().find("positionField")->defaultValue, "referencePosition");
}

TEST(FunctionObjectKeywords, BadEntriesNameTheEntry) {
    const fs::path root = fs::temp_directory_path() / ("mfdynFoKeywords-" + std::to_string(::getpid()));
    fs::create_directories(root / "system");
    std::ofstream(root / "system" / "controlDict") << controlDictText;
    {
        TestContext context(root);
        fill(context.particles, 0.0);
        const auto errorOf = [&](const std::string& text) {
            return test::inputErrorOf(
                [&] { FunctionObject::New(Dictionary::parse(text, "functions/f"), "f", context); }, text);
        };
        const auto expectIn = [](const std::string& message, const std::string& part) {
            EXPECT_NE(message.find(part), std::string::npos) << "'" << part << "' not in: " << message;
        };
        const std::string control = errorOf("type fieldMinMax; fields (density); writeControl sometimes;");
        expectIn(control, "keyword 'writeControl'");
        expectIn(control, "timeStep | runTime | adjustableRunTime | writeTime");
        expectIn(errorOf("type fieldMinMax; fields (density); writeControl runTime;"),
                 "missing keyword 'writeInterval'");
        expectIn(errorOf("type fieldMinMax; fields (density); writeInterval 2.5;"), "whole number of steps");
        expectIn(errorOf("type fieldMinMax; fields (density); mode sideways;"), "magnitude | component");
        expectIn(errorOf("type fieldMinMax;"), "missing keyword 'fields'");
        expectIn(errorOf("type probes; fields (density); points ((0.5 0.5 0)); h 0.065; interpolation rbf;"),
                 "shepard | mls");
        expectIn(errorOf("type probes; fields (density); points ((0.5 0.5 0)); h -1;"), "keyword 'h'");
        expectIn(errorOf("type probes; fields (density); points ((0.5 0.5 0)); h 0.065; positionField x0;"),
                 "vector field 'x0'");
        const std::string trim = errorOf(
            "type debrisCloud; direction (1 0); front 0; rear 1; trim 0.5; "
            "targetRegions (plate);");
        expectIn(trim, "keyword 'trim'");
        expectIn(trim, "< 0.5");
        expectIn(errorOf("type swingingCubeError; rho0 1100; youngsModulus 17e6; poissonRatio 0.5; "
                         "amplitude 5e-4;"),
                 "keyword 'poissonRatio'");
        expectIn(errorOf("type cableError; rho0 8000; youngsModulus 2e11; length 10; loadedLength 12; "
                         "velocity 5;"),
                 "loadedLength <= length");
    }
    fs::remove_all(root);
}
