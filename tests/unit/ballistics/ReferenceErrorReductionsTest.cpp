// The reference-error function objects reduce over every rank. Under MPI a rank may hold no
// particles; it must still reach every global reduction the others make (or they wait for it
// forever), and the norms must count the particles of all ranks. On one process the global hooks
// return their argument, so what can fail here is whether they are reached: globalReductionCount
// (core/Parallel.hpp) counts the calls.
#include "ballistics/ParticleFlightSolver.hpp"
#include "ballistics/TrajectoryError.hpp"
#include "core/Parallel.hpp"
#include "functionObjects/EllipticalDropError.hpp"
#include "particles/ParticleSet.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>

namespace mfdyn {
namespace {

namespace fs = std::filesystem;

const char* controlDictText = "endTime 1; deltaT 0.1; writeControl timeStep; writeInterval 1;\n";

// A body force with no closed-form trajectory (trajectoryError must refuse it).
class NoExactTrajectory final : public BodyForce {
public:
    NoExactTrajectory() : BodyForce(Dictionary::parse("", "test"), 2) {}
    void acceleration(const double*, double, double* a) const override { a[0] = a[1] = 0; }
    double potential(const double*) const override { return 0; }
};

// One rank's view of a 2D run: its particles (possibly none) and a body force.
class Context final : public RunContext, public BodyForceSolver {
public:
    Context(const std::string& name, std::unique_ptr<BodyForce> force)
        : root_(fs::temp_directory_path() / ("mfdyn-ballistics-" + name + "-" + std::to_string(::getpid()))),
          case_(makeRoot(root_)),
          time_(root_ / "system" / "controlDict", Dictionary::parse(controlDictText, "controlDict")),
          force_(std::move(force)) {
        time_.start(0.0, "0");
        particles.vectorField("velocity");
        particles.scalarField("mass");
        particles.scalarField("density");
    }
    ~Context() override { fs::remove_all(root_); }
    const Case& runCase() const override { return case_; }
    const Time& time() const override { return time_; }
    const FieldStore& fields() const override { return particles; }
    const std::string& startTimeName() const override { return start_; }
    const BodyForce& bodyForce() const override { return *force_; }

    Time& mutableTime() { return time_; }
    ParticleSet<2> particles;

private:
    static fs::path makeRoot(const fs::path& root) {
        fs::remove_all(root);
        fs::create_directories(root / "system");
        std::ofstream(root / "system" / "controlDict") << controlDictText;
        return root;
    }
    fs::path root_;
    Case case_;
    Time time_;
    std::unique_ptr<BodyForce> force_;
    std::string start_ = "0";
};

std::unique_ptr<BodyForce> gravity() {
    return BodyForce::New(Dictionary::parse("type uniformGravity; g (0 -10 0);", "test"), 2);
}

TEST(ReferenceErrorReductions, TrajectoryErrorOnARankWithoutParticlesStillSumsWithTheOthers) {
    Context context("emptyTrajectory", gravity());
    TrajectoryError error(Dictionary::parse("type trajectoryError;", "trajectory"), "trajectory", context);
    context.mutableTime().advance(0.1);
    const auto before = globalReductionCount.load();
    error.write();
    // One: the sums, which also tell every rank that no rank has a particle (then no row, on all).
    // Before, a rank without particles returned first and left the others in their reduction.
    EXPECT_EQ(globalReductionCount.load() - before, 1u);
    EXPECT_TRUE(error.errorNorms().empty());
}

TEST(ReferenceErrorReductions, TrajectoryErrorNormsAndMaximaAreOverEveryRank) {
    Context context("trajectory", gravity());
    auto& p = context.particles;
    p.resize(3);
    auto& v = p.vectorField("velocity");
    // Each particle is compared with its own start state, found by its global id.
    for (std::size_t i = 0; i < 3; ++i)
        p.globalId()[i] = std::int64_t(i), p.position()[i] = Vector<2>(double(i), 0), v[i] = Vector<2>(1, 0);
    TrajectoryError error(Dictionary::parse("type trajectoryError;", "trajectory"), "trajectory", context);
    // After tau = 0.1 the exact state is x = x0 + (0.1, -0.05), v = (1, -1). Put particle k off
    // it by 0.001 k in x and 0.002 k in v_x: L1 = mean, Linf = the largest, exactly these numbers.
    context.mutableTime().advance(0.1);
    for (std::size_t i = 0; i < 3; ++i) {
        p.position()[i] = Vector<2>(double(i) + 0.1 + 0.001 * double(i), -0.05);
        v[i] = Vector<2>(1 + 0.002 * double(i), -1);
    }
    const auto before = globalReductionCount.load();
    error.write();
    // Three: the sums and both maxima (a rank-local maximum would be the largest of one rank only).
    EXPECT_EQ(globalReductionCount.load() - before, 3u);
    const auto norms = error.errorNorms();
    ASSERT_EQ(norms.size(), 2u);
    EXPECT_EQ(norms[0].field, "position");
    EXPECT_NEAR(norms[0].L1, 0.001, 1e-12);  // (0 + 0.001 + 0.002) / 3
    EXPECT_NEAR(norms[0].L2, std::sqrt((1e-6 + 4e-6) / 3), 1e-12);
    EXPECT_NEAR(norms[0].Linf, 0.002, 1e-12);
    EXPECT_EQ(norms[1].field, "velocity");
    EXPECT_NEAR(norms[1].L1, 0.002, 1e-12);
    EXPECT_NEAR(norms[1].Linf, 0.004, 1e-12);
}

// Under MPI particles change rank and order (a migration sorts each rank's by global id): each is
// compared with its own start state, found by its id, not with the one at its index then.
TEST(ReferenceErrorReductions, TrajectoryErrorFollowsEachParticleByItsGlobalId) {
    Context context("trajectoryOrder", gravity());
    auto& p = context.particles;
    p.resize(3);
    auto& v = p.vectorField("velocity");
    for (std::size_t i = 0; i < 3; ++i)
        p.globalId()[i] = std::int64_t(i), p.position()[i] = Vector<2>(double(i), 0), v[i] = Vector<2>(1, 0);
    TrajectoryError error(Dictionary::parse("type trajectoryError;", "trajectory"), "trajectory", context);
    context.mutableTime().advance(0.1);
    p.reorder({2, 1, 0});
    // Each exactly on its trajectory: x0 + (0.1, -0.05), v = (1, -1); by index 0 would be 2 off.
    for (std::size_t i = 0; i < 3; ++i) {
        p.position()[i] = Vector<2>(double(p.globalId()[i]) + 0.1, -0.05);
        v[i] = Vector<2>(1, -1);
    }
    error.write();
    const auto norms = error.errorNorms();
    ASSERT_EQ(norms.size(), 2u);
    EXPECT_LT(norms[0].Linf, 1e-15);  // round-off of x0 + 0.1
    EXPECT_LT(norms[1].Linf, 1e-15);
}

TEST(ReferenceErrorReductions, TrajectoryErrorRefusesAForceWithoutExactTrajectoryOnEveryRank) {
    // With no particles here, the old check (made at a particle) never ran: this rank went on while
    // the ranks with particles stopped with the error.
    Context context("noExact", std::make_unique<NoExactTrajectory>());
    try {
        TrajectoryError(Dictionary::parse("type trajectoryError;", "trajectory"), "trajectory", context);
        FAIL() << "a body force without an exact trajectory must be refused";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("has no exact trajectory to compare with"), std::string::npos)
            << e.what();
    }
}

TEST(ReferenceErrorReductions, EllipticalDropErrorOnARankWithoutParticlesStillSumsWithTheOthers) {
    Context context("emptyDrop", gravity());
    EllipticalDropError error(Dictionary::parse("type ellipticalDropError; radius 1;", "drop"), "drop",
                              context);
    const auto before = globalReductionCount.load();
    error.write();
    // One: the first moments, which also count the particles of every rank (none: no row anywhere).
    EXPECT_EQ(globalReductionCount.load() - before, 1u);
    EXPECT_TRUE(error.errorNorms().empty());
}

}  // namespace
}  // namespace mfdyn
