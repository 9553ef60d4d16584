// One Courant keyword for every method (issue 15 item 3): controlDict's maxCo, with a method's
// own default when the controlDict gives none (tlSph asks Time::maxCo(0.3)).
#include "core/Dictionary.hpp"
#include "core/Time.hpp"

#include <gtest/gtest.h>

using namespace mfdyn;

namespace {

Time makeTime(const std::string& text) {
    Time time("/nonexistent/controlDict", Dictionary::parse(text, "controlDict"));
    time.start(0.0, "0");
    return time;
}

}  // namespace

TEST(Courant, theMethodDefaultAppliesOnlyWhenTheControlDictGivesNoMaxCo) {
    const Time without = makeTime("endTime 1; deltaT 0.1; writeInterval 1;");
    EXPECT_EQ(without.maxCo(), 1.0);     // the shared default, as before
    EXPECT_EQ(without.maxCo(0.3), 0.3);  // tlSph's default
    const Time with = makeTime("endTime 1; deltaT 0.1; writeInterval 1; maxCo 0.15;");
    EXPECT_EQ(with.maxCo(), 0.15);
    EXPECT_EQ(with.maxCo(0.3), 0.15);  // a given maxCo wins over the method's default
    // Given equal to the default of Time (1): still the given value, not the method's.
    EXPECT_EQ(makeTime("endTime 1; deltaT 0.1; writeInterval 1; maxCo 1;").maxCo(0.3), 1.0);
}
