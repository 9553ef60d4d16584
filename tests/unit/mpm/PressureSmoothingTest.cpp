// pressureSmoothing (mpm/PressureSmoothing.hpp, mpm/pressureSmoothing/): cellPressure and
// cellJacobian on hand-made particles, selected by the word as mpmProperties does. A uniform
// state is left as it is; a checkerboard (alternating J, so alternating Tait pressure, among the
// four points of one cell) is removed; the cell's volume-weighted pressure (cellPressure) and its
// present volume sum V0 J (cellJacobian) are kept; cells, materials and solids are not mixed.
// Tolerances: 1e-12 relative where the identity is exact and only round-off of a few sums of
// four or eight terms differs.
#include "core/Dictionary.hpp"
#include "core/Error.hpp"
#include "mpm/MpmModels.hpp"
#include "mpm/PressureSmoothing.hpp"

#include <Eigen/LU>
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace mfdyn {
namespace {

// Tait water, p = B ((rho/rho0)^7 - 1) = B (J^-7 - 1): the pressure the callbacks give.
constexpr double B = 3.2e4;
double tait(double J) { return B * (std::pow(J, -7.0) - 1.0); }

template <int Dim>
std::unique_ptr<PressureSmoothing<Dim>> select(const std::string& word) {
    const Dictionary d = Dictionary::parse("pressureSmoothing " + word + ";", "mpmProperties");
    return selectByWord<PressureSmoothing<Dim>>(d, "pressureSmoothing", "none");
}

// Particles of a 2D fluid on a grid of 2 x 1 unit cells, with sigma = -p(J) I + a deviator
// (sigma_xy = tau, a viscous stress) and the plane-strain sigma_zz = -p(J).
struct Particles2 {
    CartesianGrid<2> grid{Vector<2>(0, 0), Vector<2>(1, 1), {2, 1}};
    std::vector<Vector<2>> x;
    std::vector<double> m, rho0, J, zz;
    std::vector<std::int64_t> material;
    std::vector<Tensor<2>> F;
    std::vector<SymmTensor<2>> sigma;
    std::vector<char> fluid{1, 1, 0};  // materials 0 and 1 fluids, 2 a solid

    void add(double px, double py, double mass, double density, double jacobian, std::int64_t k = 0,
             double tau = 0) {
        x.emplace_back(px, py);
        m.push_back(mass);
        rho0.push_back(density);
        J.push_back(jacobian);
        material.push_back(k);
        // An F with det F = J that is not a pure dilatation (a shear kept by F-bar).
        Tensor<2> f;
        f << jacobian, 0.3, 0, 1;
        F.push_back(f);
        SymmTensor<2> s;
        s(0, 0) = s(1, 1) = -tait(jacobian);
        s(0, 1) = tau;
        sigma.push_back(s);
        zz.push_back(-tait(jacobian));
    }
    double V(std::size_t p) const { return J[p] * m[p] / rho0[p]; }
    double pressure(std::size_t p) const { return -sigma[p](0, 0); }
    PressureSmoothingFields<2> fields() {
        PressureSmoothingFields<2> f;
        f.position = x;
        f.mass = m;
        f.referenceDensity = rho0;
        f.material = material;
        f.deformationGradient = F;
        f.jacobian = J;
        f.cauchyStress = sigma;
        f.cauchyStressZZ = zz;
        f.smoothed = [this](std::int64_t k) { return fluid[std::size_t(k)] != 0; };
        f.pressureAt = [](std::size_t, double j) { return tait(j); };
        return f;
    }
    void apply(const std::string& word) {
        auto model = select<2>(word);
        auto f = fields();
        model->apply(grid, f);
    }
};

// The four sub-cell centres of cell (0, 0) with J alternating 1 -+ d: a checkerboard.
Particles2 checkerboard(double d = 0.004) {
    Particles2 s;
    s.add(0.25, 0.25, 1.0, 1000, 1 - d, 0, 5.0);
    s.add(0.75, 0.25, 1.1, 1000, 1 + d, 0, -2.0);
    s.add(0.25, 0.75, 0.9, 1000, 1 + d, 0, 1.0);
    s.add(0.75, 0.75, 1.0, 1000, 1 - d, 0, 0.0);
    return s;
}

TEST(PressureSmoothing, wordsSelectTheModels) {
    EXPECT_FALSE(select<2>("none")->active());
    EXPECT_TRUE(select<2>("cellPressure")->active());
    EXPECT_TRUE(select<3>("cellJacobian")->active());
    EXPECT_EQ(select<1>("cellJacobian")->type(), "cellJacobian");
}

TEST(PressureSmoothing, unknownWordListsTheChoices) {
    try {
        select<2>("cellPresure");
        FAIL() << "no error for an unknown word";
    } catch (const InputError& e) {
        const std::string what = e.what();
        EXPECT_NE(what.find("mpmProperties"), std::string::npos) << what;
        EXPECT_NE(what.find("cellPressure"), std::string::npos) << what;
        EXPECT_NE(what.find("cellJacobian"), std::string::npos) << what;
        EXPECT_NE(what.find("none"), std::string::npos) << what;
    }
}

TEST(PressureSmoothing, uniformStateUnchanged) {
    for (const char* word : {"cellPressure", "cellJacobian"}) {
        Particles2 s;
        for (double y : {0.25, 0.75})
            for (double x : {0.25, 0.75, 1.25, 1.75}) s.add(x, y, 1.0, 1000, 0.998, 0, 3.0);
        const Particles2 before = s;
        s.apply(word);
        for (std::size_t p = 0; p < s.x.size(); ++p) {
            const double scale = tait(0.998);
            EXPECT_NEAR(s.sigma[p](0, 0), before.sigma[p](0, 0), 1e-12 * scale) << word;
            EXPECT_NEAR(s.sigma[p](1, 1), before.sigma[p](1, 1), 1e-12 * scale) << word;
            EXPECT_EQ(s.sigma[p](0, 1), 3.0) << word;
            EXPECT_NEAR(s.zz[p], before.zz[p], 1e-12 * scale) << word;
            EXPECT_NEAR(s.J[p], 0.998, 1e-15) << word;
            EXPECT_LT((s.F[p] - before.F[p]).norm(), 1e-15) << word;
        }
    }
}

TEST(PressureSmoothing, cellPressureRemovesTheCheckerboardAndKeepsTheMean) {
    Particles2 s = checkerboard();
    const Particles2 before = s;
    // The hand-computed volume-weighted mean of the four pressures.
    double volume = 0, sum = 0;
    for (std::size_t p = 0; p < 4; ++p) {
        volume += s.V(p);
        sum += s.V(p) * tait(s.J[p]);
    }
    const double mean = sum / volume;
    ASSERT_GT(std::abs(tait(0.996) - tait(1.004)), 0.05 * std::abs(mean) + 100);  // a real checkerboard
    s.apply("cellPressure");
    double after = 0;
    for (std::size_t p = 0; p < 4; ++p) {
        EXPECT_NEAR(s.pressure(p), mean, 1e-12 * B);
        EXPECT_NEAR(-s.sigma[p](1, 1), mean, 1e-12 * B);
        EXPECT_NEAR(-s.zz[p], mean, 1e-12 * B);
        EXPECT_EQ(s.sigma[p](0, 1), before.sigma[p](0, 1));  // the deviator is kept
        EXPECT_EQ(s.J[p], before.J[p]);                      // J and F are not touched
        EXPECT_EQ(s.F[p], before.F[p]);
        after += s.V(p) * s.pressure(p);
    }
    EXPECT_NEAR(after, sum, 1e-12 * std::abs(sum));
}

TEST(PressureSmoothing, cellJacobianRemovesTheCheckerboardAndKeepsTheVolume) {
    Particles2 s = checkerboard();
    const Particles2 before = s;
    double reference = 0, present = 0;
    for (std::size_t p = 0; p < 4; ++p) {
        reference += s.m[p] / s.rho0[p];
        present += s.m[p] / s.rho0[p] * s.J[p];
    }
    const double mean = present / reference;
    s.apply("cellJacobian");
    double kept = 0;
    for (std::size_t p = 0; p < 4; ++p) {
        EXPECT_NEAR(s.J[p], mean, 1e-15);
        EXPECT_NEAR(s.F[p].determinant(), mean, 1e-14);
        // F scaled by one factor: its shape (the ratio of its entries) kept.
        EXPECT_NEAR(s.F[p](0, 1) / s.F[p](1, 1), before.F[p](0, 1) / before.F[p](1, 1), 1e-14);
        EXPECT_NEAR(s.pressure(p), tait(mean), 1e-12 * B);
        EXPECT_NEAR(-s.zz[p], tait(mean), 1e-12 * B);
        EXPECT_EQ(s.sigma[p](0, 1), before.sigma[p](0, 1));
        kept += s.m[p] / s.rho0[p] * s.J[p];
    }
    EXPECT_NEAR(kept, present, 1e-15 * present);
}

TEST(PressureSmoothing, cellsMaterialsAndSolidsAreNotMixed) {
    for (const char* word : {"cellPressure", "cellJacobian"}) {
        Particles2 s = checkerboard();
        // Cell (1, 0): two points of fluid 0 and two of fluid 1 (another rho0), and a solid.
        s.add(1.25, 0.25, 1.0, 1000, 0.999, 0);
        s.add(1.75, 0.25, 1.0, 1000, 0.997, 0);
        s.add(1.25, 0.75, 1.0, 1.2, 0.990, 1);
        s.add(1.75, 0.75, 2.0, 1.2, 0.980, 1);
        s.add(1.50, 0.50, 7.8, 7800, 0.950, 2);
        const Particles2 before = s;
        s.apply(word);
        // Each group's mean from its own members only.
        auto expect = [&](std::vector<std::size_t> group) {
            double w = 0, wp = 0, wj = 0;
            for (std::size_t p : group) {
                const double V0 = before.m[p] / before.rho0[p];
                const double weight = std::string(word) == "cellPressure" ? V0 * before.J[p] : V0;
                w += weight;
                wp += weight * tait(before.J[p]);
                wj += weight * before.J[p];
            }
            const double p = std::string(word) == "cellPressure" ? wp / w : tait(wj / w);
            for (std::size_t q : group) EXPECT_NEAR(s.pressure(q), p, 1e-12 * B) << word << " particle " << q;
        };
        expect({0, 1, 2, 3});
        expect({4, 5});
        expect({6, 7});
        EXPECT_EQ(s.sigma[8](0, 0), before.sigma[8](0, 0)) << word;  // the solid untouched
        EXPECT_EQ(s.J[8], before.J[8]) << word;
        EXPECT_EQ(s.zz[8], before.zz[8]) << word;
    }
}

TEST(PressureSmoothing, orderOfParticlesDoesNotMatter) {
    // The same checkerboard listed backwards: the same values per particle (to the round-off of
    // sums of four terms taken in another order).
    for (const char* word : {"cellPressure", "cellJacobian"}) {
        Particles2 a = checkerboard(), b;
        for (std::size_t p = 4; p-- > 0;) b.add(a.x[p][0], a.x[p][1], a.m[p], a.rho0[p], a.J[p], 0, a.sigma[p](0, 1));
        a.apply(word);
        b.apply(word);
        for (std::size_t p = 0; p < 4; ++p) EXPECT_NEAR(a.pressure(p), b.pressure(3 - p), 1e-12 * B) << word;
    }
}

TEST(PressureSmoothing, cellJacobianIn3DScalesByTheCubeRoot) {
    CartesianGrid<3> grid(Vector<3>(0, 0, 0), Vector<3>(1, 1, 1), {1, 1, 1});
    std::vector<Vector<3>> x;
    std::vector<double> m(8, 0.125), rho0(8, 1000), J;
    std::vector<std::int64_t> material(8, 0);
    std::vector<Tensor<3>> F;
    std::vector<SymmTensor<3>> sigma(8);
    for (int k = 0; k < 8; ++k) {
        x.emplace_back(0.25 + 0.5 * (k & 1), 0.25 + 0.5 * ((k >> 1) & 1), 0.25 + 0.5 * ((k >> 2) & 1));
        const double j = (k % 2) ? 1.003 : 0.997;
        J.push_back(j);
        Tensor<3> f = Tensor<3>::Identity();
        f(0, 0) = j;
        f(0, 2) = 0.1;
        F.push_back(f);
        for (int d = 0; d < 3; ++d) sigma[k](d, d) = -tait(j);
    }
    PressureSmoothingFields<3> f;
    f.position = x;
    f.mass = m;
    f.referenceDensity = rho0;
    f.material = material;
    f.deformationGradient = F;
    f.jacobian = J;
    f.cauchyStress = sigma;
    f.smoothed = [](std::int64_t) { return true; };
    f.pressureAt = [](std::size_t, double j) { return tait(j); };
    std::vector<double> stored(8, -1.0);
    f.pressure = stored;
    select<3>("cellJacobian")->apply(grid, f);
    for (int k = 0; k < 8; ++k) {
        EXPECT_NEAR(J[k], 1.0, 1e-15);
        EXPECT_NEAR(F[k].determinant(), 1.0, 1e-14);
        for (int d = 0; d < 3; ++d) EXPECT_NEAR(sigma[k](d, d), -tait(1.0), 1e-12 * B);
        EXPECT_NEAR(stored[k], tait(1.0), 1e-12 * B);  // the stored pressure written when given
    }
}

}  // namespace
}  // namespace mfdyn
