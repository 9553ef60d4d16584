// The half-space profile of the shape functions (mpm/contact/HalfSpaceProfile.cpp), which the
// multiField contact's surface-gap check reads surfaces from: the nodal centre of a half-space
// filled up to the node against its closed form (quadratic B-spline -13/32, linear hat -1/3,
// cubic B-spline -(int_0^2 r N)/(1/2) = -0.5), the ends of the range (an empty support at
// -R, the full support centred on the node), monotonicity, and the inverse.
#include "core/Dictionary.hpp"
#include "grid/shapeFunctions/ShapeFunction.hpp"
#include "mpm/contact/HalfSpaceProfile.hpp"

#include <gtest/gtest.h>

#include <memory>
#include <string>

namespace mfdyn {
namespace {

HalfSpaceProfile profileOf(const std::string& type) {
    const auto shape = ShapeFunction<2>::New(Dictionary::parse("type " + type + ";\n", "test"));
    return HalfSpaceProfile(*shape);
}

// The trapezoid table resolves c to about 1e-7 cells; 1e-6 leaves room for the interpolation.
constexpr double tableTolerance = 1e-6;

TEST(HalfSpaceProfile, CentreOfAHalfFilledSupportMatchesTheClosedForm) {
    // Quadratic B-spline: (5/64 + 1/8) / (1/2) = 13/32 (the file's derivation).
    EXPECT_NEAR(profileOf("quadraticBSpline").centre(0.0), -13.0 / 32.0, tableTolerance);
    // Linear hat: int_0^1 r (1 - r) dr / (1/2) = (1/6) / (1/2).
    EXPECT_NEAR(profileOf("linear").centre(0.0), -1.0 / 3.0, tableTolerance);
    // Cubic B-spline: int_0^1 r (2/3 - r^2 + r^3/2) dr + int_1^2 r (2 - r)^3 / 6 dr
    //   = (1/3 - 1/4 + 1/10) + (1/6)(int_0^1 (2 - u) u^3 du = 2/4 - 1/5) = 11/60 + 1/20 = 7/30,
    // over 1/2: 7/15.
    EXPECT_NEAR(profileOf("cubicBSpline").centre(0.0), -7.0 / 15.0, tableTolerance);
}

TEST(HalfSpaceProfile, EndsOfTheRange) {
    const HalfSpaceProfile p = profileOf("quadraticBSpline");
    EXPECT_DOUBLE_EQ(p.supportHalfWidth(), 1.5);
    // A sliver at the support's edge has its centre there; the whole support is centred on the node.
    EXPECT_NEAR(p.centre(-1.5 + 1e-3), -1.5, 2e-3);
    EXPECT_NEAR(p.centre(1.5), 0.0, tableTolerance);
    EXPECT_DOUBLE_EQ(p.surface(0.5), 1.5);    // beyond the full support's centre: clamped
    EXPECT_DOUBLE_EQ(p.surface(-2.0), -1.5);  // beyond the support: clamped
}

TEST(HalfSpaceProfile, SurfaceInvertsCentreAcrossTheSupport) {
    for (const char* type : {"linear", "quadraticBSpline", "cubicBSpline"}) {
        const HalfSpaceProfile p = profileOf(type);
        const double R = p.supportHalfWidth();
        double previous = -R;
        for (double s = -R + 0.05; s < R - 0.05; s += 0.05) {
            const double c = p.centre(s);
            EXPECT_GT(c, previous) << type << " at s = " << s;
            previous = c;
            EXPECT_NEAR(p.surface(c), s, 1e-4) << type << " at s = " << s;
        }
    }
}

}  // namespace
}  // namespace mfdyn
