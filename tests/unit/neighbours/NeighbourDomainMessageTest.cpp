// The neighbour-search domain's message shows the bounds given (issue 14): std::to_string showed
// [0.000000, 0.000000] for a box from 0 to 1e-320, an empty-looking box that hid the real cause.
#include "particles/NeighbourDomain.hpp"

#include "core/Error.hpp"

#include <gtest/gtest.h>

#include <string>

using namespace mfdyn;

TEST(NeighbourDomainMessage, tinyBoundsAreShownNotZero) {
    std::string what = "no Error";
    try {
        NeighbourDomain<2> domain(Vector<2>(0.0, 1e-320), Vector<2>(1.0, 0.0));
    } catch (const Error& e) {
        what = e.what();
    }
    EXPECT_EQ(what.rfind("neighbour search domain: direction 1 needs lo < hi, found [9.99989e-321, 0]", 0),
              0u)
        << what;
}
