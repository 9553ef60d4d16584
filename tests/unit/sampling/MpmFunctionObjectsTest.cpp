// The material point method's function objects (issue 17 item 9) on hand-made particle sets:
// bodyMomentum (per region mass, momentum, angular momentum about a centre), lowestPoint (the
// spring's tip: the deepest particle followed by its id, displacement and reference), bodyExtents
// (bounding extents and the thesis's top row / centre column of the hanging block, with
// references), and fieldMinMax's derived vonMisesStress (standard sqrt(3/2 s:s) with sigma_zz).
#include "core/Dictionary.hpp"
#include "core/Error.hpp"
#include "functionObjects/FunctionObject.hpp"
#include "functionObjects/VonMisesStress.hpp"
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

const char* controlDictText = "endTime 1; deltaT 1e-3; writeControl timeStep; writeInterval 1;\n";

template <int Dim>
class Context final : public RunContext {
public:
    explicit Context(const fs::path& root)
        : case_(root),
          time_(root / "system" / "controlDict", Dictionary::parse(controlDictText, "controlDict")) {
        time_.start(0, "0");
    }
    const Case& runCase() const override { return case_; }
    const Time& time() const override { return time_; }
    const FieldStore& fields() const override { return particles; }
    const std::string& startTimeName() const override { return start_; }
    void at(double t) { time_.start(t, "0"); }
    ParticleSet<Dim> particles;

private:
    Case case_;
    Time time_;
    std::string start_ = "0";
};

fs::path freshCase(const std::string& tag) {
    const fs::path root =
        fs::temp_directory_path() / ("mfdynMpmFo-" + tag + "-" + std::to_string(::getpid()));
    fs::remove_all(root);
    fs::create_directories(root / "system");
    std::ofstream(root / "system" / "controlDict") << controlDictText;
    return root;
}

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

std::unique_ptr<FunctionObject> make(const std::string& text, const std::string& name, const RunContext& c) {
    return FunctionObject::New(Dictionary::parse(text, "controlDict"), name, c);
}

template <int Dim>
std::string errorOf(const std::string& text, const RunContext& c) {
    try {
        make(text, "fo", c);
    } catch (const InputError& e) {
        return e.what();
    }
    return "no error";
}

// Two bodies in 2D: a (m 2 at (1 0), v (0 3); m 1 at (0 1), v (1 0)) and b (m 4 at (2 2), v (-1 1)).
void twoBodies(ParticleSet<2>& p) {
    p.resize(3);
    p.regionNames = {"a", "b"};
    const double m[3] = {2, 1, 4}, x[3][2] = {{1, 0}, {0, 1}, {2, 2}}, v[3][2] = {{0, 3}, {1, 0}, {-1, 1}};
    const std::int64_t r[3] = {0, 0, 1};
    auto& mass = p.scalarField("mass");
    auto& vel = p.vectorField("velocity");
    for (std::size_t i = 0; i < 3; ++i) {
        mass[i] = m[i];
        p.position()[i] = Vector<2>(x[i][0], x[i][1]);
        vel[i] = Vector<2>(v[i][0], v[i][1]);
        p.region()[i] = r[i];
        p.globalId()[i] = std::int64_t(i);
    }
}

}  // namespace

// About the origin: a has M 3, P (1 6), L_z = 2 (1 x 3) + 1 (0 x 0 - 1 x 1) = 5; b has M 4,
// P (-4 4), L_z = 4 (2 x 1 - 2 x (-1)) = 16. About (1 1): a's L is 0 (each r parallel to v), b's 8.
TEST(BodyMomentum, PerRegionSums) {
    const fs::path root = freshCase("momentum");
    Context<2> c(root);
    twoBodies(c.particles);
    {
        auto origin = make("type bodyMomentum;", "origin", c);
        auto shifted = make("type bodyMomentum; regions (b a); centre (1 1);", "shifted", c);
        origin->write();
        shifted->write();
        // A later write with b's velocity reversed: the summary's change is -2 P_b.
        c.at(0.5);
        c.particles.vectorField("velocity")[2] = Vector<2>(1, -1);
        origin->write();
        const auto summary = origin->summary();
        ASSERT_EQ(summary.size(), 6u);  // 2 bodies x (P_x, P_y, L_z)
        EXPECT_NE(summary[3].find("b_momentum_x change 8.000e+00 (-4 -> 4)"), std::string::npos)
            << summary[3];
    }
    const auto a = lines(root / "postProcessing" / "origin" / "0" / "bodyMomentum.csv");
    ASSERT_EQ(a.size(), 3u);
    EXPECT_EQ(a[0],
              "time,a_mass,a_momentum_x,a_momentum_y,a_angularMomentum_z,b_mass,b_momentum_x,b_momentum_y,"
              "b_angularMomentum_z");
    const auto row = numbers(a[1]);
    const double expected[] = {0, 3, 1, 6, 5, 4, -4, 4, 16};
    ASSERT_EQ(row.size(), 9u);
    for (std::size_t k = 0; k < 9; ++k) EXPECT_DOUBLE_EQ(row[k], expected[k]) << k;
    const auto b = lines(root / "postProcessing" / "shifted" / "0" / "bodyMomentum.csv");
    ASSERT_GE(b.size(), 2u);
    EXPECT_EQ(b[0].substr(0, 11), "time,b_mass");
    const auto rowB = numbers(b[1]);
    EXPECT_DOUBLE_EQ(rowB[4], 8.0);  // b's L_z about (1 1)
    EXPECT_DOUBLE_EQ(rowB[8], 0.0);  // a's
    fs::remove_all(root);
}

// 3D: L = m r x v per component; 1 particle m 2 at (1 2 3), v (4 5 6): r x v = (-3 6 -3).
TEST(BodyMomentum, AngularMomentumIn3D) {
    const fs::path root = freshCase("momentum3");
    Context<3> c(root);
    auto& p = c.particles;
    p.resize(1);
    p.regionNames = {"ball"};
    p.scalarField("mass")[0] = 2;
    p.position()[0] = Vector<3>(1, 2, 3);
    p.vectorField("velocity")[0] = Vector<3>(4, 5, 6);
    p.region()[0] = 0;
    {
        auto fo = make("type bodyMomentum;", "m", c);
        fo->write();
    }
    const auto row = numbers(lines(root / "postProcessing" / "m" / "0" / "bodyMomentum.csv")[1]);
    const double expected[] = {0, 2, 8, 10, 12, -6, 12, -6};
    ASSERT_EQ(row.size(), 8u);
    for (std::size_t k = 0; k < 8; ++k) EXPECT_DOUBLE_EQ(row[k], expected[k]) << k;
    fs::remove_all(root);
}

TEST(BodyMomentum, UnknownRegionListsTheRegions) {
    const fs::path root = freshCase("momentumBad");
    Context<2> c(root);
    twoBodies(c.particles);
    const std::string e = errorOf<2>("type bodyMomentum; regions (a c);", c);
    EXPECT_NE(e.find("no region 'c' in this run; regions: a b"), std::string::npos) << e;
    EXPECT_NE(e.find("controlDict:1"), std::string::npos) << e;
    fs::remove_all(root);
}

// The spring (note section 4.1): 10 points at y = 0.81 ... 0.99 of region bar, and a lower
// region `floor` that must not be taken. The bar's lowest point (y 0.81) is followed; moved down by
// 3e-3 it gives displacement 3e-3, against the reference 2.943e-3 (+1.9%).
TEST(LowestPoint, FollowsTheDeepestParticleOfItsRegion) {
    const fs::path root = freshCase("lowest");
    Context<2> c(root);
    auto& p = c.particles;
    p.resize(12);
    p.regionNames = {"floor", "bar"};
    for (std::size_t i = 0; i < 10; ++i) {
        p.position()[i] = Vector<2>(0.03, 0.99 - 0.02 * double(i));  // the lowest last
        p.region()[i] = 1;
        p.globalId()[i] = std::int64_t(20 + i);
    }
    p.position()[10] = Vector<2>(0.5, 0.1), p.region()[10] = 0, p.globalId()[10] = 5;
    p.position()[11] = Vector<2>(0.7, 0.1), p.region()[11] = 0, p.globalId()[11] = 6;
    {
        auto fo = make("type lowestPoint; region bar; reference 2.943e-3;", "tip", c);
        fo->write();
        EXPECT_EQ(fo->referenceValues()[0].value, 0.0);
        // The particles reordered (as a solver may) and the tip moved down by 3e-3, the others too.
        std::swap(p.position()[9], p.position()[0]);
        std::swap(p.globalId()[9], p.globalId()[0]);
        p.position()[0][1] -= 3e-3;
        p.position()[1][1] -= 10e-3;  // not the tracked one: it was not the lowest at the start
        c.at(1.0);
        fo->write();
        const auto ref = fo->referenceValues();
        ASSERT_EQ(ref.size(), 1u);
        EXPECT_EQ(ref[0].name, "displacement");
        EXPECT_NEAR(ref[0].value, 3e-3, 1e-15);
        EXPECT_EQ(ref[0].exact, 2.943e-3);
        const auto summary = fo->summary();
        ASSERT_EQ(summary.size(), 1u);
        EXPECT_NE(summary[0].find(
                      "particle 29, displacement 0.003 (mean over 2 writes 0.0015), largest 0.003 at t = 1"),
                  std::string::npos)
            << summary[0];
    }
    const auto csv = lines(root / "postProcessing" / "tip" / "0" / "lowestPoint.csv");
    ASSERT_EQ(csv.size(), 3u);
    EXPECT_EQ(csv[0], "time,displacement,meanDisplacement,position_x,position_y");
    const auto last = numbers(csv[2]);
    EXPECT_NEAR(last[1], 3e-3, 1e-15);
    EXPECT_NEAR(last[4], 0.807, 1e-15);
    fs::remove_all(root);
}

// Ties go to the lowest global id; a direction given (here +x: "down" is to the right) is normalised.
TEST(LowestPoint, TiesAndDirection) {
    const fs::path root = freshCase("lowestTie");
    Context<2> c(root);
    auto& p = c.particles;
    p.resize(3);
    p.regionNames = {"body"};
    p.position()[0] = Vector<2>(1, 0), p.globalId()[0] = 7;
    p.position()[1] = Vector<2>(1, 5), p.globalId()[1] = 3;
    p.position()[2] = Vector<2>(0, 0), p.globalId()[2] = 1;
    auto fo = make("type lowestPoint; direction (2 0);", "side", c);
    fo->write();
    p.position()[1][0] += 0.25;  // id 3, the tracked one
    fo->write();
    EXPECT_NE(fo->summary()[0].find("particle 3, displacement 0.25"), std::string::npos) << fo->summary()[0];
    EXPECT_TRUE(fo->referenceValues().empty());  // no reference given
    const std::string bad = errorOf<2>("type lowestPoint; direction (0 0);", c);
    EXPECT_NE(bad.find("non-zero"), std::string::npos) << bad;
    const std::string region = errorOf<2>("type lowestPoint; region bar;", c);
    EXPECT_NE(region.find("no region 'bar' in this run; regions: body"), std::string::npos) << region;
    fs::remove_all(root);
}

// A 4 x 4 block of points on [0, 0.06]^2 (k = 4: l_x = l_y = 0.06 (1 - 1/4) = 0.045), region
// block, beside a region other. Then a hanging block's shape: the top row contracted to half its
// width, the bottom row and the rest unchanged, the column x = 0.0225 (the centre column: of
// 0.0225 and 0.0375, equally near 0.03, the smaller x) stretched downward by 0.02.
TEST(BodyExtents, BoundsAndTheThesisLines) {
    const fs::path root = freshCase("extents");
    Context<2> c(root);
    auto& p = c.particles;
    p.resize(17);
    p.regionNames = {"other", "block"};
    const double h = 0.015;
    for (int j = 0; j < 4; ++j)
        for (int i = 0; i < 4; ++i) {
            const std::size_t k = std::size_t(4 * j + i);
            p.position()[k] = Vector<2>((i + 0.5) * h, (j + 0.5) * h);
            p.region()[k] = 1;
            p.globalId()[k] = std::int64_t(k);
        }
    p.position()[16] = Vector<2>(5, 5), p.region()[16] = 0, p.globalId()[16] = 16;
    {
        auto bounds = make("type bodyExtents; region block;", "bounds", c);
        auto rows =
            make("type bodyExtents; region block; mode lines; reference (0.0321 0.1208);", "lines", c);
        bounds->write();
        rows->write();
        EXPECT_NEAR(rows->referenceValues()[0].value, 0.045, 1e-15);
        EXPECT_NEAR(rows->referenceValues()[1].value, 0.045, 1e-15);
        for (int i = 0; i < 4; ++i) {  // top row to half its width about x = 0.03
            auto& x = p.position()[std::size_t(12 + i)];
            x[0] = 0.03 + 0.5 * (x[0] - 0.03);
        }
        p.position()[1][1] -= 0.02;  // bottom of the centre column (x = 0.0225)
        p.position()[2][1] -= 0.01;  // bottom of the other middle column: not in the line
        c.at(1.0);
        bounds->write();
        rows->write();
        const auto ref = rows->referenceValues();
        ASSERT_EQ(ref.size(), 2u);
        EXPECT_EQ(ref[0].name, "l_x");
        EXPECT_NEAR(ref[0].value, 0.0225, 1e-15);  // the top row's half width
        EXPECT_EQ(ref[0].exact, 0.0321);
        EXPECT_EQ(ref[1].name, "l_y");
        EXPECT_NEAR(ref[1].value, 0.065, 1e-15);  // 0.045 + 0.02
        EXPECT_EQ(ref[1].exact, 0.1208);
        EXPECT_TRUE(bounds->referenceValues().empty());
    }
    const auto b = lines(root / "postProcessing" / "bounds" / "0" / "bodyExtents.csv");
    ASSERT_EQ(b.size(), 3u);
    EXPECT_EQ(b[0], "time,l_x,l_y");
    const auto last = numbers(b[2]);
    EXPECT_NEAR(last[1], 0.045, 1e-15);  // the bottom rows still span 0.045
    EXPECT_NEAR(last[2], 0.065, 1e-15);
    fs::remove_all(root);
}

TEST(BodyExtents, BadInput) {
    const fs::path root = freshCase("extentsBad");
    Context<3> c(root);
    c.particles.resize(1);
    c.particles.regionNames = {"block"};
    const std::string lines = errorOf<3>("type bodyExtents; mode lines;", c);
    EXPECT_NE(lines.find("needs a 2D run"), std::string::npos) << lines;
    const std::string ref = errorOf<3>("type bodyExtents; reference (1 2);", c);
    EXPECT_NE(ref.find("expected 3 extents"), std::string::npos) << ref;
    const std::string mode = errorOf<3>("type bodyExtents; mode rows;", c);
    EXPECT_NE(mode.find("bounds"), std::string::npos) << mode;
    fs::remove_all(root);
}

// sigma_vM = sqrt(1/2 [(sxx - syy)^2 + (syy - szz)^2 + (szz - sxx)^2] + 3 (sxy^2 + syz^2 + sxz^2)):
// uniaxial 100 gives 100 (the thesis code's formula: 141.4); pure shear 10 gives 10 sqrt 3;
// plane strain diag(100, 0, 30) gives sqrt(7900) = 88.882; hydrostatic gives 0.
TEST(VonMisesStress, StandardFormula) {
    EXPECT_DOUBLE_EQ(vonMisesStress(100, 0, 0, 0, 0, 0), 100.0);
    EXPECT_DOUBLE_EQ(vonMisesStress(0, 0, 0, 10, 0, 0), 10 * std::sqrt(3.0));
    EXPECT_DOUBLE_EQ(vonMisesStress(0, 0, 0, 0, 0, 10), 10 * std::sqrt(3.0));
    EXPECT_NEAR(vonMisesStress(100, 0, 30, 0, 0, 0), 88.88194417315589, 1e-12);
    EXPECT_EQ(vonMisesStress(-5, -5, -5, 0, 0, 0), 0.0);
}

// fieldMinMax's derived field from cauchyStress (xx, yy, xy) and cauchyStressZZ in 2D: particle
// 0 uniaxial 100, particle 1 plane strain diag(100, 0, 30), particle 2 shear 10 with sigma_zz 0.
TEST(VonMisesStress, DerivedFieldOfFieldMinMax) {
    const fs::path root = freshCase("vonMises");
    Context<2> c(root);
    auto& p = c.particles;
    p.resize(3);
    for (std::size_t i = 0; i < 3; ++i) p.globalId()[i] = std::int64_t(10 + i);
    const std::string none = errorOf<2>("type fieldMinMax; fields (vonMisesStress);", c);
    EXPECT_NE(none.find("'cauchyStress'"), std::string::npos) << none;
    auto& sigma = p.symmTensorField("cauchyStress");
    const std::string noZZ = errorOf<2>("type fieldMinMax; fields (vonMisesStress);", c);
    EXPECT_NE(noZZ.find("'cauchyStressZZ'"), std::string::npos) << noZZ;
    EXPECT_NE(noZZ.find("controlDict:1"), std::string::npos) << noZZ;
    auto& zz = p.scalarField("cauchyStressZZ");
    sigma[0](0, 0) = 100;
    sigma[1](0, 0) = 100, zz[1] = 30;
    sigma[2](0, 1) = 10;
    {
        auto fo = make("type fieldMinMax; fields (vonMisesStress);", "vm", c);
        fo->write();
    }
    const auto csv = lines(root / "postProcessing" / "vm" / "0" / "fieldMinMax.csv");
    ASSERT_EQ(csv.size(), 2u);
    EXPECT_EQ(csv[0], "time,vonMisesStress_min,vonMisesStress_minId,vonMisesStress_max,vonMisesStress_maxId");
    const auto row = numbers(csv[1]);
    // fieldMinMax.csv holds 10 significant digits.
    EXPECT_NEAR(row[1], 10 * std::sqrt(3.0), 1e-8);
    EXPECT_EQ(row[2], 12.0);
    EXPECT_NEAR(row[3], 100.0, 1e-8);
    EXPECT_EQ(row[4], 10.0);
    fs::remove_all(root);
}

// 3D: the six components of cauchyStress, no cauchyStressZZ needed.
TEST(VonMisesStress, ThreeDimensionalField) {
    const fs::path root = freshCase("vonMises3");
    Context<3> c(root);
    auto& p = c.particles;
    p.resize(1);
    auto& sigma = p.symmTensorField("cauchyStress");
    sigma[0](0, 0) = 100, sigma[0](2, 2) = 30, sigma[0](1, 2) = 10;
    const VonMisesField field(p, "test");
    EXPECT_NEAR(field(0), std::sqrt(7900.0 + 300.0), 1e-10);
    fs::remove_all(root);
}
