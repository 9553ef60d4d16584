// tlSph's health indicators (TlSphHealth.hpp): the hourglass measure of Ganzenmueller 2015 is zero
// to round-off for any affine motion and equals the zig-zag's own pair strain for an hourglass mode,
// which the particle's corrected gradient does not see; the correction matrix's conditioning is 1
// inside a lattice, about 0.3 at a cube's corner, and tiny in a layer far thinner than h.
#include "tlSph/TlSphHealth.hpp"

#include "core/Dictionary.hpp"
#include "meshfreeOperators/ReferenceOperators.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>

namespace mfdyn {
namespace {

struct Lattice3 {
    std::vector<Vector<3>> X;
    std::vector<double> V;
    std::vector<int> parity;  // (-1)^(i+j+k)
    std::size_t centre = 0;
    double dx = 0;
};

// A nodal lattice of m^3 points with spacing dx (faces included, tributary volumes).
Lattice3 cube(int m, double dx) {
    Lattice3 l;
    l.dx = dx;
    for (int i = 0; i < m; ++i)
        for (int j = 0; j < m; ++j)
            for (int k = 0; k < m; ++k) {
                l.X.push_back(Vector<3>(i * dx, j * dx, k * dx));
                double V = dx * dx * dx;
                for (int c : {i, j, k})
                    if (c == 0 || c == m - 1) V *= 0.5;
                l.V.push_back(V);
                l.parity.push_back((i + j + k) % 2 ? -1 : 1);
                if (i == m / 2 && j == m / 2 && k == m / 2) l.centre = l.X.size() - 1;
            }
    return l;
}

std::unique_ptr<Kernel> wendland() {
    return Kernel::New(Dictionary::parse("type wendlandC2;", "test"));
}

ReferenceOperators<3> operatorsOf(const Lattice3& l, const Kernel& kernel) {
    ReferenceOperators<3>::Options options;
    options.laplacian = false;
    return ReferenceOperators<3>(l.X, l.V, 1.3 * l.dx, kernel, options);
}

double largestHourglass(const ReferenceOperators<3>& ops, const std::vector<Vector<3>>& x,
                        const std::vector<Tensor<3>>& F) {
    double largest = 0;
    for (std::size_t a = 0; a < x.size(); ++a)
        largest =
            std::max(largest, hourglassIndicator<3>(a, ops.neighbours(), ops.referencePositions().data(),
                                                    x.data(), F[a], x.size()));
    return largest;
}

TEST(TlSphHealth, hourglassIsZeroForAnyAffineMotion) {
    const auto kernel = wendland();
    const Lattice3 l = cube(7, 0.1);
    const auto ops = operatorsOf(l, *kernel);
    // A large rotation, a stretch of 2.5 and a shear: F far from I, as in the spinning cube.
    Tensor<3> A;
    A << 0.3, -2.1, 0.4, 1.9, 0.2, -0.7, 0.1, 0.5, 2.5;
    std::vector<Vector<3>> x;
    for (const auto& X : l.X) x.push_back(A * X + Vector<3>(3, -1, 7));
    // F as tlSph has it in {p,F}: the corrected gradient of the motion (exact on linear fields).
    const std::vector<Tensor<3>> F = ops.gradientOf(x);
    // Round-off: |x| ~ 10 over a pair of length dx = 0.1, 1e-16 relative.
    EXPECT_LT(largestHourglass(ops, x, F), 1e-12);
}

TEST(TlSphHealth, hourglassSeesAZigZagThatFDoesNot) {
    const auto kernel = wendland();
    const Lattice3 l = cube(7, 0.1);
    const auto ops = operatorsOf(l, *kernel);
    // The zig-zag (hourglass) mode u = delta dx (-1)^(i+j+k) e_z, on a uniform stretch.
    const double delta = 0.1;
    std::vector<Vector<3>> x;
    for (std::size_t a = 0; a < l.X.size(); ++a)
        x.push_back(1.2 * l.X[a] + Vector<3>(0, 0, delta * l.dx * l.parity[a]));
    const std::vector<Tensor<3>> F = ops.gradientOf(x);
    // Inside, the mode is even about the particle and the corrected gradient odd: F sees the
    // stretch alone, and a nearest neighbour (|X_ab| = dx, opposite parity) is 2 delta dx off.
    EXPECT_LT((F[l.centre] - 1.2 * Tensor<3>::Identity()).norm(), 1e-12);
    const double centre = hourglassIndicator<3>(l.centre, ops.neighbours(), ops.referencePositions().data(),
                                                x.data(), F[l.centre], x.size());
    EXPECT_NEAR(centre, 2 * delta, 1e-12);
    // At the solver's threshold 0.2 there, and nowhere below it (the faces see at least as much).
    EXPECT_GE(largestHourglass(ops, x, F), 2 * delta - 1e-12);
    // Ten times smaller, ten times smaller: the measure is the mode's amplitude over the spacing.
    std::vector<Vector<3>> y;
    for (std::size_t a = 0; a < l.X.size(); ++a)
        y.push_back(1.2 * l.X[a] + Vector<3>(0, 0, 0.1 * delta * l.dx * l.parity[a]));
    const std::vector<Tensor<3>> G = ops.gradientOf(y);
    EXPECT_NEAR(hourglassIndicator<3>(l.centre, ops.neighbours(), ops.referencePositions().data(), y.data(),
                                      G[l.centre], y.size()),
                0.2 * delta, 1e-12);
}

TEST(TlSphHealth, correctionConditioningOfALatticeItsCornerAndAThinLayer) {
    const auto kernel = wendland();
    const Lattice3 l = cube(7, 0.1);
    const auto ops = operatorsOf(l, *kernel);
    const double h = 1.3 * l.dx;
    auto conditioning = [&](const ReferenceOperators<3>& o, const std::vector<double>& V, std::size_t a) {
        return correctionConditioning<3>(a, o.neighbours(), o.referencePositions().data(), V.data(), *kernel,
                                         h);
    };
    // Cubic symmetry: B is a multiple of I inside.
    EXPECT_NEAR(conditioning(ops, l.V, l.centre), 1.0, 1e-12);
    // The corner (index 0): one octant, about 0.3 (0.316), far above the threshold 0.01.
    const double corner = conditioning(ops, l.V, 0);
    EXPECT_GT(corner, 0.2);
    EXPECT_LT(corner, 0.4);
    for (std::size_t a = 0; a < l.X.size(); ++a) EXPECT_GT(conditioning(ops, l.V, a), corner - 1e-12);
    // Two layers 0.02 dx apart (a sheet far thinner than h): B's normal direction is (0.02)^2 of the
    // others, below the threshold, yet above what ReferenceOperators refuses (1e-8).
    std::vector<Vector<3>> X;
    std::vector<double> V;
    for (int i = 0; i < 9; ++i)
        for (int j = 0; j < 9; ++j)
            for (int k = 0; k < 2; ++k) {
                X.push_back(Vector<3>(i * l.dx, j * l.dx, k * 0.02 * l.dx));
                V.push_back(l.dx * l.dx * 0.01 * l.dx);
            }
    ReferenceOperators<3>::Options options;
    options.laplacian = false;
    const ReferenceOperators<3> thin(X, V, h, *kernel, options);
    const double sheet = conditioning(thin, V, 4 * 18 + 4 * 2);  // the middle of the sheet
    EXPECT_LT(sheet, 0.01);
    EXPECT_GT(sheet, 1e-6);
}

}  // namespace
}  // namespace mfdyn
