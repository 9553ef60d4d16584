// fpm/splitting: the stages of one step (doc/methods/fpm.md §3.1). Lie: each part once over dt in
// the order given (the thesis's shear -> euler -> rotation); Strang: A(dt/2) B(dt/2) C(dt) B(dt/2)
// A(dt/2), so that the fractions of every part sum to 1; one part alone is that part over dt.
#include "fpm/splitting/Splitting.hpp"

#include "core/Dictionary.hpp"

#include <gtest/gtest.h>

namespace mfdyn {
namespace {

using fpm::Subsystem;

std::unique_ptr<fpm::Splitting> splitting(const char* type) {
    return fpm::Splitting::New(Dictionary::parse(std::string("type ") + type + ";", "test"));
}

TEST(Splitting, lieIsEachPartOnceInOrder) {
    const auto s = splitting("lie");
    const auto stages = s->stages({Subsystem::shear, Subsystem::euler, Subsystem::rotation});
    ASSERT_EQ(stages.size(), 3u);
    EXPECT_EQ(stages[0].part, Subsystem::shear);
    EXPECT_EQ(stages[1].part, Subsystem::euler);
    EXPECT_EQ(stages[2].part, Subsystem::rotation);
    for (const auto& st : stages) EXPECT_EQ(st.fraction, 1.0);
    EXPECT_EQ(s->order(), 1);
}

TEST(Splitting, strangIsSymmetricWithHalfSteps) {
    const auto s = splitting("strang");
    const auto stages = s->stages({Subsystem::shear, Subsystem::euler, Subsystem::rotation});
    const Subsystem parts[5] = {Subsystem::shear, Subsystem::euler, Subsystem::rotation, Subsystem::euler,
                                Subsystem::shear};
    const double fractions[5] = {0.5, 0.5, 1.0, 0.5, 0.5};
    ASSERT_EQ(stages.size(), 5u);
    for (int k = 0; k < 5; ++k) {
        EXPECT_EQ(stages[std::size_t(k)].part, parts[k]) << k;
        EXPECT_EQ(stages[std::size_t(k)].fraction, fractions[k]) << k;
    }
    EXPECT_EQ(s->order(), 2);
    const auto one = s->stages({Subsystem::euler});
    ASSERT_EQ(one.size(), 1u);
    EXPECT_EQ(one[0].fraction, 1.0);
    const auto two = s->stages({Subsystem::shear, Subsystem::euler});
    ASSERT_EQ(two.size(), 3u);
    EXPECT_EQ(two[1].part, Subsystem::euler);
    EXPECT_EQ(two[1].fraction, 1.0);
}

TEST(Splitting, anUnknownTypeNamesTheChoices) {
    try {
        splitting("lei");
        FAIL() << "no error";
    } catch (const Error& e) {
        const std::string what = e.what();
        EXPECT_NE(what.find("lie"), std::string::npos) << what;
        EXPECT_NE(what.find("strang"), std::string::npos) << what;
    }
}

}  // namespace
}  // namespace mfdyn
