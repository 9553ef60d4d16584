// Interpolation finds a point's particles through CellBins: the stencil's particles are exactly
// those whose own support holds the point (brute force), at variable h, inside and outside the
// cloud; and a cloud spread over more than 2^20 support radii, which the old private grid (21-bit
// packed cell keys) refused with "the particles span more than 2^20 support radii", is sampled.
#include "functionObjects/Interpolation.hpp"
#include "particles/ParticleSet.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

using namespace mfdyn;

namespace {

Dictionary dictionary(const std::string& text) {
    return Dictionary::parse(text, "test");
}

template <int Dim>
void expectStencilsMatchBruteForce(unsigned seed) {
    const std::size_t n = 400;
    ParticleSet<Dim> particles(n);
    std::mt19937 random(seed);
    std::uniform_real_distribution<double> u(0.0, 1.0), hRange(0.03, 0.12);
    auto& h = particles.scalarField("smoothingLength");
    for (std::size_t i = 0; i < n; ++i) {
        for (int d = 0; d < Dim; ++d) particles.position()[i](d) = u(random);
        h[i] = hRange(random);
    }
    const Interpolation interpolation(dictionary("interpolation shepard;"), particles);
    const Kernel& kernel = interpolation.kernel();
    std::uniform_real_distribution<double> wide(-0.3, 1.3);
    std::size_t found = 0;
    for (int q = 0; q < 200; ++q) {
        SamplePoint x{0, 0, 0};
        for (int d = 0; d < Dim; ++d) x[d] = wide(random);
        std::vector<std::size_t> expected;
        for (std::size_t j = 0; j < n; ++j) {
            double r2 = 0;
            for (int d = 0; d < Dim; ++d) r2 += std::pow(particles.position()[j](d) - x[d], 2);
            const double r = std::sqrt(r2);
            if (r < kernel.supportRadius(h[j]) && kernel.W(r, h[j], Dim) > 0) expected.push_back(j);
        }
        auto got = interpolation.stencil(x).particles;
        std::sort(got.begin(), got.end());
        EXPECT_EQ(got, expected) << "point " << q;
        found += expected.size();
    }
    EXPECT_GT(found, 200u);  // the comparison is not of empty sets
}

TEST(InterpolationCells, stencilsMatchBruteForce1D) {
    expectStencilsMatchBruteForce<1>(1);
}
TEST(InterpolationCells, stencilsMatchBruteForce2D) {
    expectStencilsMatchBruteForce<2>(2);
}
TEST(InterpolationCells, stencilsMatchBruteForce3D) {
    expectStencilsMatchBruteForce<3>(3);
}

// Two particles 10^4 apart with support 2e-3 (5e6 support radii): each point near one finds it.
TEST(InterpolationCells, cloudWiderThanTwoToTheTwentySupportRadii) {
    ParticleSet<2> particles(2);
    particles.position()[0] = Vector<2>(0.0, 0.0);
    particles.position()[1] = Vector<2>(1e4, 0.0);
    particles.scalarField("f") = {3.0, 7.0};
    const Interpolation interpolation(dictionary("interpolation shepard; h 1e-3;"), particles);
    const auto stencils = interpolation.stencils({{1e-4, 0, 0}, {1e4 - 1e-4, 0, 0}, {5e3, 0, 0}});
    const auto values = Interpolation::apply(stencils, particles.field("f"));
    EXPECT_DOUBLE_EQ(values[0][0], 3.0);
    EXPECT_DOUBLE_EQ(values[1][0], 7.0);
    EXPECT_EQ(stencils[2].status, Interpolation::Status::noNeighbours);
}

}  // namespace
