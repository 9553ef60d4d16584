// Grid output: the .vti of the node fields read back bit for bit, and a grid method's grid.vti
// listed in particles.pvd as part 1 of each written time, through SolverRun as a solver writes
// it, with restart truncation and purgeWrite keeping particles and grid entries together.
#include "core/Application.hpp"
#include "grid/CartesianGrid.hpp"
#include "grid/VtiWriter.hpp"
#include "particles/ParticleSet.hpp"
#include "particles/PvdIndex.hpp"
#include "particles/TimeDirectory.hpp"
#include "particles/XmlElement.hpp"
#include "solver/Solver.hpp"
#include "solver/SolverRun.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>

#include <unistd.h>

namespace mfdyn {
namespace {

namespace fs = std::filesystem;

std::string readText(const fs::path& file) {
    std::ifstream in(file, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

TEST(VtiWriter, nodeFieldsRoundTripBitForBit) {
    CartesianGrid<2> grid(Vector<2>(-0.5, 0.25), Vector<2>(0.1, 1.0 / 3.0), {3, 2});  // 4 x 3 nodes
    auto& mass = grid.nodes().field<double>("mass");
    auto& v = grid.nodes().field<Vector<2>>("velocity");
    auto& id = grid.nodes().field<std::int64_t>("colour");
    for (std::size_t n = 0; n < grid.nodeCount(); ++n) {
        mass[n] = 1.0 / double(n + 3);  // not exact in decimal: a text format would lose bits
        v[n] = Vector<2>(std::sqrt(double(n)), -double(n) / 7.0);
        id[n] = std::int64_t(n) * 1000 - 5;
    }
    const double time = 0.1 + 0.2;
    const ExtraFile file = vtiFile(grid, time);
    EXPECT_EQ(file.first, "grid.vti");
    const VtiImage image = parseVti(file.second, "grid.vti");
    EXPECT_EQ(image.dimension, 2);
    EXPECT_EQ(image.time, time);
    EXPECT_EQ(image.cells, (std::array<std::int64_t, 3>{3, 2, 0}));
    EXPECT_EQ(image.origin[0], -0.5);
    EXPECT_EQ(image.spacing[1], 1.0 / 3.0);  // 17 digits: exact
    EXPECT_EQ(image.spacing[2], 0.1);        // the missing axis takes x's spacing
    ASSERT_EQ(image.arrays.size(), 3u);
    const VtiImage::Array* m = image.find("mass");
    const VtiImage::Array* u = image.find("velocity");
    const VtiImage::Array* c = image.find("colour");
    ASSERT_TRUE(m && u && c);
    EXPECT_EQ(u->components, 3);  // padded to 3D, as particles.vtp
    EXPECT_EQ(c->type, "Int64");
    for (std::size_t n = 0; n < grid.nodeCount(); ++n) {
        EXPECT_EQ(m->values[n], mass[n]);
        EXPECT_EQ(u->values[3 * n], v[n][0]);
        EXPECT_EQ(u->values[3 * n + 1], v[n][1]);
        EXPECT_EQ(u->values[3 * n + 2], 0.0);
        EXPECT_EQ(c->values[n], double(id[n]));
    }
    // The header is XML that our parser (and so ParaView's) reads: ImageData with the extent.
    std::size_t stop = 0;
    const XmlElement root = XmlElement::parse(file.second, "grid.vti", "AppendedData", &stop);
    const XmlElement* imageData = root.findChild("ImageData");
    ASSERT_NE(imageData, nullptr);
    EXPECT_EQ(*imageData->findAttribute("WholeExtent"), "0 3 0 2 0 0");
    // A chosen subset, in the order asked for.
    const VtiImage some = parseVti(vtiText(grid, 0.0, {"colour", "mass"}), "some.vti");
    ASSERT_EQ(some.arrays.size(), 2u);
    EXPECT_EQ(some.arrays[0].name, "colour");
}

TEST(VtiWriter, oneAndThreeDimensionsAndErrors) {
    CartesianGrid<3> cube(Vector<3>(0, 0, 0), Vector<3>(0.5, 0.25, 0.125), {2, 4, 8});
    auto& s = cube.nodes().field<SymmTensor<3>>("stress");
    s[cube.nodeIndex({2, 4, 8})].c = {1, 2, 3, 4, 5, 6};
    const VtiImage image = parseVti(vtiText(cube, 1.0), "cube.vti");
    EXPECT_EQ(image.cells, (std::array<std::int64_t, 3>{2, 4, 8}));
    const auto* a = image.find("stress");
    ASSERT_NE(a, nullptr);
    ASSERT_EQ(a->components, 6);
    EXPECT_EQ(a->values[6 * (cube.nodeCount() - 1) + 4], 5.0);  // yz of the last node (x fastest)
    // A tensor is row-major in the file, column-major in memory (VtpWriter.hpp): F_xy is the
    // file's second component.
    auto& F = cube.nodes().field<Tensor<3>>("deformationGradient");
    F[1] = Tensor<3>::Identity();
    F[1](0, 1) = 2.0;
    const VtiImage withF = parseVti(vtiText(cube, 1.0, {"deformationGradient"}), "cube.vti");
    EXPECT_EQ(withF.arrays[0].values[9 + 1], 2.0);
    EXPECT_EQ(withF.arrays[0].values[9 + 3], 0.0);
    EXPECT_EQ(withF.arrays[0].values[9 + 4], 1.0);

    CartesianGrid<1> line(Vector<1>(2.0), Vector<1>(0.5), {4});
    line.nodes().field<double>("mass")[4] = 7.0;
    const VtiImage l = parseVti(vtiText(line, 0.0), "line.vti");
    EXPECT_EQ(l.dimension, 1);
    EXPECT_EQ(l.find("mass")->values[4], 7.0);

    try {
        vtiText(line, 0.0, {"velocity"});
        FAIL() << "a field the grid does not have must be refused";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("no node field 'velocity'; the grid has mass"),
                  std::string::npos)
            << e.what();
    }
    // A cut file is an InputError naming it, not a read past the end.
    const std::string text = vtiText(line, 0.0);
    EXPECT_THROW(parseVti(text.substr(0, text.size() - 60), "cut.vti"), InputError);
    EXPECT_THROW(parseVti("<VTKFile type=\"PolyData\"/>", "other.vti"), InputError);
}

// Pieces (several ranks' grid output): slabs along the last axis that share one node layer,
// each the whole image's values there to the bit, and an index that names them with their
// extents; no more pieces than cell layers.
TEST(VtiWriter, piecesAreSlabsOfTheWholeImage) {
    CartesianGrid<3> cube(Vector<3>(0, -1, 0.5), Vector<3>(0.5, 0.25, 0.125), {2, 3, 7});
    auto& mass = cube.nodes().field<double>("mass");
    auto& v = cube.nodes().field<Vector<3>>("velocity");
    for (std::size_t n = 0; n < cube.nodeCount(); ++n) {
        mass[n] = 1.0 / double(n + 3);
        v[n] = Vector<3>(double(n), -std::sqrt(double(n)), 1.0 / double(n + 1));
    }
    const VtiImage whole = parseVti(vtiText(cube, 0.5), "grid.vti");
    const std::size_t layer = 3 * 4;  // nodes in an xy layer
    for (int pieces : {1, 2, 3, 7}) {
        std::int64_t expectedFirst = 0;
        for (int r = 0; r < pieces; ++r) {
            const VtiImage piece = parseVti(vtiPieceText(cube, 0.5, {}, r, pieces), "grid_r.vti");
            const auto [first, last] = gridSlab(7, r, pieces);
            EXPECT_EQ(first, expectedFirst) << "pieces share their boundary layer";
            expectedFirst = last;
            EXPECT_EQ(piece.first, (std::array<std::int64_t, 3>{0, 0, first}));
            EXPECT_EQ(piece.cells, (std::array<std::int64_t, 3>{2, 3, last}));
            EXPECT_EQ(piece.origin, whole.origin);
            EXPECT_EQ(piece.spacing, whole.spacing);
            EXPECT_EQ(piece.time, 0.5);
            ASSERT_EQ(piece.arrays.size(), whole.arrays.size());
            for (std::size_t a = 0; a < whole.arrays.size(); ++a) {
                const auto& all = whole.arrays[a].values;
                const std::size_t width = std::size_t(whole.arrays[a].components);
                const std::vector<double> slab(
                    all.begin() + std::ptrdiff_t(std::size_t(first) * layer * width),
                    all.begin() + std::ptrdiff_t(std::size_t(last + 1) * layer * width));
                EXPECT_EQ(piece.arrays[a].values, slab)
                    << whole.arrays[a].name << ", piece " << r << " of " << pieces;
            }
        }
        EXPECT_EQ(expectedFirst, 7) << "the last piece ends at the last layer";
    }
    EXPECT_EQ(gridPieceCount(cube, 3), 3);
    EXPECT_EQ(gridPieceCount(cube, 9), 7);  // one cell layer a piece at most

    const std::string index =
        pvtiText(cube, {"velocity"}, 2, [](int r) { return "grid_" + std::to_string(r) + ".vti"; });
    EXPECT_NE(index.find("<PImageData WholeExtent=\"0 2 0 3 0 7\" GhostLevel=\"0\""), std::string::npos)
        << index;
    EXPECT_NE(index.find("<PDataArray type=\"Float64\" Name=\"velocity\" NumberOfComponents=\"3\"/>"),
              std::string::npos)
        << index;
    EXPECT_EQ(index.find("mass"), std::string::npos) << "only the fields asked for";
    EXPECT_NE(index.find("<Piece Extent=\"0 2 0 3 0 3\" Source=\"grid_0.vti\"/>"), std::string::npos)
        << index;
    EXPECT_NE(index.find("<Piece Extent=\"0 2 0 3 3 7\" Source=\"grid_1.vti\"/>"), std::string::npos)
        << index;

    // In 2D the slabs run along y.
    CartesianGrid<2> plane(Vector<2>(0, 0), Vector<2>(1, 1), {4, 5});
    plane.nodes().field<double>("mass")[plane.nodeIndex({4, 5})] = 2.0;
    const VtiImage top = parseVti(vtiPieceText(plane, 0.0, {}, 1, 2), "grid_1.vti");
    EXPECT_EQ(top.first, (std::array<std::int64_t, 3>{0, 2, 0}));
    EXPECT_EQ(top.cells, (std::array<std::int64_t, 3>{4, 5, 0}));
    EXPECT_EQ(top.find("mass")->values.back(), 2.0);
    EXPECT_EQ(top.find("mass")->values.size(), 5u * 4u);
}

// ---- a grid method in a few lines: particles drift, the grid counts the steps ----------------
template <int Dim>
class GridDriftSolver final : public Solver {
public:
    explicit GridDriftSolver(SolverRun& run)
        : Solver(run),
          owner_(adoptParticleSet<Dim>(run.takeParticles())),
          x_(owner_->position()),
          v_(owner_->vectorField("velocity")),
          grid_(Vector<Dim>::Zero(), Vector<Dim>::Constant(0.5), cells()),
          steps_(grid_.nodes().template field<double>("steps")) {}
    TimeStepVote stableTimeStep() override { return {0.1, "fixed"}; }
    void step(double dt) override {
        for (std::size_t i = 0; i < x_.size(); ++i) x_[i] += dt * v_[i];
        for (double& s : steps_) s += 1.0;
    }
    ParticleSetBase& particles() override { return *owner_; }
    std::vector<ExtraFile> extraOutput() const override { return {vtiFile(grid_, time().value())}; }

private:
    static typename CartesianGrid<Dim>::Ijk cells() {
        typename CartesianGrid<Dim>::Ijk n;
        n.fill(2);
        return n;
    }
    std::unique_ptr<ParticleSet<Dim>> owner_;
    std::vector<Vector<Dim>>& x_;
    std::vector<Vector<Dim>>& v_;
    CartesianGrid<Dim> grid_;
    std::vector<double>& steps_;
};

void writeControlDict(const fs::path& dir, const std::string& startTime, const std::string& extra) {
    std::ofstream(dir / "system/controlDict")
        << "application gridDrift;\nstartFrom startTime;\nstartTime " << startTime
        << ";\nstopAt endTime;\nendTime 0.4;\n"
           "deltaT 0.1;\nadjustTimeStep no;\nwriteControl adjustableRunTime;\nwriteInterval 0.2;\n"
           "writePrecision 6;\n"
        << extra;
}

fs::path makeCase(const std::string& name, const std::string& extra) {
    const fs::path dir =
        fs::temp_directory_path() / ("mfdyn-gridOutput-" + name + "-" + std::to_string(::getpid()));
    fs::remove_all(dir);
    fs::create_directories(dir / "system");
    writeControlDict(dir, "0", extra);
    ParticleSet<2> p(2);
    auto& v = p.vectorField("velocity");
    for (std::size_t i = 0; i < 2; ++i) {
        p.globalId()[i] = std::int64_t(i);
        p.position()[i] = Vector<2>(0.25 + 0.5 * double(i), 0.5);
        v[i] = Vector<2>(0.1, 0.0);
    }
    p.scalarField("mass").assign(2, 1.0);
    p.scalarField("density").assign(2, 1.0);
    writeTimeDirectory(dir, "0", p);
    return dir;
}

int run(const fs::path& dir) {
    ApplicationInfo info{"gridDrift", "grid output test", {}, {}};
    std::string a0 = "gridDrift", a1 = "-case", a2 = dir.string();
    char* argv[] = {a0.data(), a1.data(), a2.data()};
    return runSolver<GridDriftSolver>(Arguments::parse(3, argv, info), "gridDrift");
}

// (time, part, file) of every entry.
std::vector<std::tuple<double, int, std::string>> listing(const fs::path& pvd) {
    std::vector<std::tuple<double, int, std::string>> out;
    const PvdIndex index = PvdIndex::read(pvd);  // kept: entries() is a reference into it
    for (const auto& e : index.entries()) out.emplace_back(e.time, e.part, e.file);
    return out;
}

TEST(GridOutput, theGridIsPartOneOfEachTimeInParticlesPvd) {
    const fs::path dir = makeCase("series", "");
    ASSERT_EQ(run(dir), 0);
    using Row = std::tuple<double, int, std::string>;
    const std::vector<Row> expected{{0.0, 0, "0/particles.vtp"},
                                    {0.2, 0, "0.2/particles.vtp"},
                                    {0.2, 1, "0.2/grid.vti"},
                                    {0.4, 0, "0.4/particles.vtp"},
                                    {0.4, 1, "0.4/grid.vti"}};
    EXPECT_EQ(listing(dir / "particles.pvd"), expected);
    // The text ParaView reads: part="1" on the grid's DataSet.
    const std::string pvd = readText(dir / "particles.pvd");
    EXPECT_NE(pvd.find("<DataSet timestep=\"0.20000000000000001\" part=\"1\" file=\"0.2/grid.vti\"/>"),
              std::string::npos)
        << pvd;
    // The grid written with the time: 4 steps of 0.1 to t = 0.4.
    const VtiImage image = parseVti(readText(dir / "0.4/grid.vti"), "0.4/grid.vti");
    EXPECT_EQ(image.find("steps")->values[0], 4.0);
    EXPECT_NEAR(image.time, 0.4, 1e-15);

    // Restart from 0.2 (its state): the later entries go, both parts, and are written again
    // once each; the 0.2 entries keep their parts (a copy without the part put the grid in the
    // particles' place).
    writeControlDict(dir, "0.2", "");
    ASSERT_EQ(run(dir), 0);
    EXPECT_EQ(listing(dir / "particles.pvd"), expected);
    fs::remove_all(dir);
}

TEST(GridOutput, purgeWriteRemovesEveryPartOfAPurgedTime) {
    const fs::path dir = makeCase("purge", "purgeWrite 1;\n");
    ASSERT_EQ(run(dir), 0);
    EXPECT_FALSE(fs::exists(dir / "0.2"));
    using Row = std::tuple<double, int, std::string>;
    const std::vector<Row> expected{
        {0.0, 0, "0/particles.vtp"}, {0.4, 0, "0.4/particles.vtp"}, {0.4, 1, "0.4/grid.vti"}};
    EXPECT_EQ(listing(dir / "particles.pvd"), expected);
    fs::remove_all(dir);
}

}  // namespace
}  // namespace mfdyn
