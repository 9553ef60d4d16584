// Tait: B given or from c0, the two exclusive, and the closed form at a compression.
#include "EquationOfStateTestTools.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace mfdyn {
namespace {

using test::makeEos;

TEST(Tait, BFromSoundSpeed) {
    // Water-like: B = rho0 c0^2 / gamma = 1000 * 1480^2 / 7.
    const auto fromC0 = makeEos("type tait; rho0 1000; c0 1480;");
    const auto fromB =
        makeEos("type tait; rho0 1000; B " + std::to_string(1000.0 * 1480.0 * 1480.0 / 7.0) + ";");
    const double B = 1000.0 * 1480.0 * 1480.0 / 7.0;
    // P = B (1.01^7 - 1), evaluated by hand; std::to_string keeps 6 decimals of B, 1e-12 relative.
    EXPECT_NEAR(fromC0->pressure(1010.0, 0.0), B * (std::pow(1.01, 7) - 1.0), 1e-12 * B);
    EXPECT_NEAR(fromB->pressure(1010.0, 0.0), B * (std::pow(1.01, 7) - 1.0), 1e-9 * B);
    EXPECT_NEAR(fromC0->soundSpeedSquared(1000.0, 0.0), 1480.0 * 1480.0, 1e-12 * 1480.0 * 1480.0);
}

TEST(Tait, NeedsExactlyOneOfBAndC0) {
    try {
        makeEos("type tait; rho0 1000;");
        FAIL() << "built without B or c0";
    } catch (const InputError& error) {
        const std::string what = error.what();
        EXPECT_NE(what.find("'B'"), std::string::npos) << what;
        EXPECT_NE(what.find("'c0'"), std::string::npos) << what;
    }
    EXPECT_THROW(makeEos("type tait; rho0 1000; B 3e8; c0 1480;"), InputError);
    EXPECT_THROW(makeEos("type tait; rho0 1000; c0 1480; gamma 1;"), InputError);  // gamma > 1
}

}  // namespace
}  // namespace mfdyn
