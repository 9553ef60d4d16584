// ErrorNorms on hand-computed data, and on the exact Sod profile sampled by particles.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "core/Error.hpp"
#include "verification/ErrorNorms.hpp"
#include "verification/ShockTubeSolution.hpp"

namespace mfdyn {
namespace {

TEST(ErrorNorms, handComputed) {
    // Errors 1, -2, 3 (the 4th particle lies outside the window) with weights 1, 1, 2.
    const std::vector<double> x{0.0, 0.5, 1.0, 2.0}, f{1.0, -2.0, 3.0, 100.0}, w{1.0, 1.0, 2.0, 1.0};
    const auto n = ErrorNorms::compute(
        x, f, w, [](double) { return 0.0; }, 0.0, 1.0);
    EXPECT_EQ(n.count, 3u);
    EXPECT_DOUBLE_EQ(n.totalWeight, 4.0);
    EXPECT_DOUBLE_EQ(n.l1, (1.0 + 2.0 + 6.0) / 4.0);
    EXPECT_DOUBLE_EQ(n.l2, std::sqrt((1.0 + 4.0 + 18.0) / 4.0));
    EXPECT_DOUBLE_EQ(n.linf, 3.0);
}

TEST(ErrorNorms, exactFieldHasZeroError) {
    const auto gas = RiemannEquationOfState::idealGas(1.4);
    const ShockTubeSolution tube(0.5, {1.0, 0.0, 1.0}, gas, {0.125, 0.0, 0.1}, gas);
    std::vector<double> x, rho, w;
    for (int i = 0; i < 400; ++i) {
        x.push_back((i + 0.5) / 400.0);
        rho.push_back(tube.state(x.back(), 0.2).density);
        w.push_back(1.0 / 400.0);
    }
    auto exact = [&](double xi) { return tube.state(xi, 0.2).density; };
    const auto n = ErrorNorms::compute(x, rho, w, exact, 0.0, 1.0);
    EXPECT_EQ(n.count, 400u);
    EXPECT_EQ(n.l1, 0.0);
    EXPECT_EQ(n.linf, 0.0);
    // A uniform offset of 0.01 gives 0.01 in every norm.
    for (double& r : rho) r += 0.01;
    const auto m = ErrorNorms::compute(x, rho, w, exact, 0.0, 1.0);
    EXPECT_NEAR(m.l1, 0.01, 1e-12);
    EXPECT_NEAR(m.l2, 0.01, 1e-12);
    EXPECT_NEAR(m.linf, 0.01, 1e-12);
}

TEST(ErrorNorms, badInputIsAnError) {
    const std::vector<double> x{0.0, 1.0}, f{0.0, 0.0}, w{1.0, -1.0}, shortW{1.0};
    auto zero = [](double) { return 0.0; };
    EXPECT_THROW(ErrorNorms::compute(x, f, shortW, zero, 0.0, 1.0), Error);
    EXPECT_THROW(ErrorNorms::compute(x, f, w, zero, 0.0, 1.0), Error);
    const std::vector<double> ok{1.0, 1.0};
    EXPECT_THROW(ErrorNorms::compute(x, f, ok, zero, 2.0, 3.0), Error);
    EXPECT_THROW(ErrorNorms::compute(
                     x, f, ok, [](double) { return std::nan(""); }, 0.0, 1.0),
                 Error);
}

}  // namespace
}  // namespace mfdyn
