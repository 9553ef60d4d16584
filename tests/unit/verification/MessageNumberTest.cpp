// Numbers in the verification solutions' messages (issue 14): std::to_string printed a tiny value
// such as 1e-320 as "0.000000", which hides the value the user gave. They show the shortest text
// that reads back as the value (formatKeywordNumber): 1e-320 is "9.99989e-321".
#include "verification/EllipticalDrop.hpp"
#include "verification/RiemannEquationOfState.hpp"

#include "core/Error.hpp"

#include <gtest/gtest.h>

#include <functional>
#include <string>

using namespace mfdyn;

namespace {
std::string messageOf(const std::function<void()>& f) {
    try {
        f();
    } catch (const Error& e) {
        return e.what();
    }
    return "no Error";
}
}  // namespace

TEST(MessageNumbers, tinyValuesAreShownNotZero) {
    EXPECT_EQ(messageOf([] { RiemannEquationOfState::idealGas(1e-320); }),
              "RiemannEquationOfState::idealGas: gamma must be > 1, found 9.99989e-321");
    EXPECT_EQ(messageOf([] { RiemannEquationOfState::stiffenedGas(1.4, -1e-320); }),
              "RiemannEquationOfState::stiffenedGas: pRef must be >= 0, found -9.99989e-321");
    EXPECT_EQ(
        messageOf([] { RiemannEquationOfState::linearBarotropic(-1e-320, 1500.0); }),
        "RiemannEquationOfState::linearBarotropic: rho0 and c0 must be > 0, found rho0 = -9.99989e-321, "
        "c0 = 1500");
    EXPECT_EQ(messageOf([] { EllipticalDrop(0.5, 100.0).state(-1e-320); }),
              "EllipticalDrop: time must be >= 0, found -9.99989e-321");
}
