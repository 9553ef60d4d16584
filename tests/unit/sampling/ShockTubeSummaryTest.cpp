// The messages of the 1D shock-tube function objects (issue 14): a relative error against an
// exact zero printed `+inf%`, an empty plateau `nan`, and a state the exact Riemann solver refuses
// was reported without file or line.
#include "core/Dictionary.hpp"
#include "functionObjects/FunctionObject.hpp"
#include "particles/ParticleSet.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>

using namespace mfdyn;
namespace fs = std::filesystem;

namespace {

class Context1D final : public RunContext {
public:
    explicit Context1D(const fs::path& root)
        : root_(root),
          case_(root),
          time_(root / "system" / "controlDict",
                Dictionary::parse("endTime 1; deltaT 0.01; writeInterval 1;", "controlDict")) {
        time_.start(0.0, "0");
    }
    ~Context1D() override { fs::remove_all(root_); }
    const Case& runCase() const override { return case_; }
    const Time& time() const override { return time_; }
    const FieldStore& fields() const override { return particles; }
    const std::string& startTimeName() const override { return start_; }
    Time& mutableTime() { return time_; }

    // n particles evenly in [from, to] with uniform density, velocity and pressure.
    void fill(int n, double from, double to, double rho, double v, double p) {
        particles.resize(std::size_t(n));
        auto& x = particles.position();
        auto& m = particles.scalarField("mass");
        auto& density = particles.scalarField("density");
        auto& velocity = particles.vectorField("velocity");
        auto& pressure = particles.scalarField("pressure");
        auto& h = particles.scalarField("smoothingLength");
        const double dx = (to - from) / (n - 1);
        for (int i = 0; i < n; ++i) {
            x[i] = Vector<1>(from + i * dx);
            m[i] = rho * dx, density[i] = rho, velocity[i] = Vector<1>(v), pressure[i] = p, h[i] = 1.3 * dx;
        }
    }
    ParticleSet<1> particles;

private:
    fs::path root_;
    Case case_;
    Time time_;
    std::string start_ = "0";
};

fs::path scratch(const std::string& name) {
    const fs::path root =
        fs::temp_directory_path() / ("mfdynShockTube-" + name + "-" + std::to_string(::getpid()));
    fs::create_directories(root / "system");
    return root;
}

std::string joined(const std::vector<std::string>& lines) {
    std::string all;
    for (const auto& l : lines) all += l + "\n";
    return all;
}

// Two equal streams meeting at x0: the exact star velocity is 0.
const char* collision =
    "type riemannError;\n"
    "x0 0.5;\n"
    "interval (0 1);\n"
    "left { density 1; velocity 1; pressure 1; equationOfState { type idealGas; gamma 1.4; } }\n"
    "right { density 1; velocity -1; pressure 1; equationOfState { type idealGas; gamma 1.4; } }\n";

}  // namespace

TEST(ShockTubeSummary, StarVelocityAgainstAnExactZeroIsNotAPercentage) {
    Context1D context(scratch("zero"));
    context.fill(201, 0, 1, 2, 1e-3, 3);
    auto riemann = FunctionObject::New(Dictionary::parse(collision, "controlDict"), "riemann", context);
    context.mutableTime().advance(0.1);
    riemann->write();
    const std::string summary = joined(riemann->summary());
    EXPECT_EQ(summary.find("inf"), std::string::npos) << summary;
    EXPECT_EQ(summary.find("nan"), std::string::npos) << summary;
    EXPECT_NE(summary.find("star velocity 0.001 (exact 0, n/a (exact value 0; off by 0.001))"),
              std::string::npos)
        << summary;
    EXPECT_NE(summary.find("star pressure 3 (exact"), std::string::npos) << summary;
}

TEST(ShockTubeSummary, EmptyStarPlateauIsSaidSo) {
    Context1D context(scratch("empty"));
    context.fill(11, 0, 0.1, 1, 0, 1);  // far left of the waves
    auto riemann = FunctionObject::New(Dictionary::parse(collision, "controlDict"), "riemann", context);
    context.mutableTime().advance(0.1);
    riemann->write();
    const std::string summary = joined(riemann->summary());
    EXPECT_EQ(summary.find("nan"), std::string::npos) << summary;
    EXPECT_NE(summary.find("no particles in the plateau"), std::string::npos) << summary;
}

TEST(ShockTubeSummary, StateTheExactSolverRefusesNamesItsLine) {
    Context1D context(scratch("p0"));
    context.fill(11, 0, 1, 1, 0, 1);
    const std::string text =
        "type riemannError;\n"
        "x0 0.5;\n"
        "interval (0 1);\n"
        "left { density 1; velocity 0; pressure 1; equationOfState { type idealGas; gamma 1.4; } }\n"
        "right\n"
        "{\n"
        "    density 0.125;\n"
        "    velocity 0;\n"
        "    pressure 0;\n"
        "    equationOfState { type idealGas; gamma 1.4; }\n"
        "}\n";
    try {
        FunctionObject::New(Dictionary::parse(text, "system/controlDict"), "riemann", context);
        FAIL() << "no error";
    } catch (const InputError& e) {
        const std::string what = e.what();
        EXPECT_NE(what.find("system/controlDict:9:"), std::string::npos) << what;
        EXPECT_NE(what.find("keyword 'pressure'"), std::string::npos) << what;
        EXPECT_NE(what.find("right state has P = 0"), std::string::npos) << what;
    }
    // Vacuum (both sides rushing apart) belongs to the two states together: at 'right' too.
    const std::string apart =
        "type riemannError; x0 0.5; interval (0 1);\n"
        "left { density 1; velocity -20; pressure 1; equationOfState { type idealGas; gamma 1.4; } }\n"
        "right { density 1; velocity 20; pressure 1; equationOfState { type idealGas; gamma 1.4; } }\n";
    try {
        FunctionObject::New(Dictionary::parse(apart, "system/controlDict"), "riemann", context);
        FAIL() << "no error";
    } catch (const InputError& e) {
        const std::string what = e.what();
        EXPECT_NE(what.find("system/controlDict:3:"), std::string::npos) << what;
        EXPECT_NE(what.find("vacuum"), std::string::npos) << what;
    }
}

TEST(ShockTubeSummary, IsothermalShockBarSaysWhatItCouldNotMeasure) {
    Context1D context(scratch("bar"));
    context.fill(11, 0, 0.1, 1, 1, 0);  // only in bar 1's far end: no plateau, no front
    auto bar = FunctionObject::New(Dictionary::parse("type isothermalShockBarError;", "controlDict"), "bar",
                                   context);
    context.mutableTime().advance(0.1);
    bar->write();
    const std::string summary = joined(bar->summary());
    EXPECT_EQ(summary.find("nan"), std::string::npos) << summary;
    EXPECT_EQ(summary.find("largest relative error"), std::string::npos) << summary;
    EXPECT_NE(summary.find("no particles in the plateau impact"), std::string::npos) << summary;
    EXPECT_NE(summary.find("impactShock not found"), std::string::npos) << summary;
}
