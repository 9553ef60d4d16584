// Runtime selection: New reads `type`, an unknown or missing type lists the valid ones, a
// duplicate registration is reported naming both registrants.
#include "core/Registry.hpp"

#include <gtest/gtest.h>

using namespace mfdyn;

namespace {

struct Greeter {
    static constexpr const char* familyName = "greeterForTest";
    using Selector = Registry<Greeter, const Dictionary&, int>;
    Greeter(const Dictionary&, int times) : times(times) {}
    virtual ~Greeter() = default;
    virtual std::string greet() const = 0;
    int times;
};

struct Hello final : Greeter {
    Hello(const Dictionary& dict, int times) : Greeter(dict, times), name(dict.get<std::string>("name")) {}
    std::string greet() const override { return "hello " + name + " x" + std::to_string(times); }
    std::string name;
};

struct Goodbye final : Greeter {
    using Greeter::Greeter;
    std::string greet() const override { return "goodbye"; }
};

MFDYN_REGISTER(Greeter, Hello, "hello", "says hello");
MFDYN_REGISTER(Greeter, Goodbye, "goodbye", "says goodbye");

}  // namespace

TEST(Registry, NewSelectsByTypeAndPassesArguments) {
    const Dictionary dict = Dictionary::parse("type hello; name world;", "dict");
    EXPECT_EQ(Greeter::Selector::New(dict, 3)->greet(), "hello world x3");
    EXPECT_EQ(Greeter::Selector::names(), (std::vector<std::string>{"goodbye", "hello"}));
}

TEST(Registry, UnknownTypeNamesFileLineAndListsValidTypes) {
    const Dictionary dict = Dictionary::parse("name x;\ntype helo;", "greeterDict");
    try {
        Greeter::Selector::New(dict, 1);
        FAIL() << "no error";
    } catch (const InputError& e) {
        const std::string what = e.what();
        EXPECT_NE(what.find("greeterDict:2:1"), std::string::npos) << what;
        EXPECT_NE(what.find("unknown greeterForTest type 'helo'"), std::string::npos) << what;
        EXPECT_NE(what.find("did you mean 'hello'"), std::string::npos) << what;
        EXPECT_LT(what.find("goodbye"), what.find("hello  ("));  // listed in order
    }
}

TEST(Registry, MissingTypeListsValidTypes) {
    const Dictionary dict = Dictionary::parse("name x;", "greeterDict");
    try {
        Greeter::Selector::New(dict, 1);
        FAIL() << "no error";
    } catch (const InputError& e) {
        const std::string what = e.what();
        EXPECT_NE(what.find("missing keyword 'type'"), std::string::npos) << what;
        EXPECT_NE(what.find("goodbye"), std::string::npos) << what;
    }
}

TEST(Registry, ListingShowsFamiliesTypesAndDescriptions) {
    const std::string listing = RegistryIndex::global().listing();
    EXPECT_NE(listing.find("greeterForTest\n"), std::string::npos) << listing;
    EXPECT_NE(listing.find("says goodbye"), std::string::npos) << listing;
}

TEST(Registry, DuplicateNameIsFatalNamingBothRegistrants) {
    RegistryIndex index;
    index.add("family", RegistryItem{"same", "first", "libA.so", nullptr});
    index.add("family", RegistryItem{"same", "second", "libB.so", nullptr});
    try {
        index.checkConflicts();
        FAIL() << "no error";
    } catch (const Error& e) {
        const std::string what = e.what();
        EXPECT_NE(what.find("libA.so"), std::string::npos) << what;
        EXPECT_NE(what.find("libB.so"), std::string::npos) << what;
    }
}

namespace {

template <int Dim>
struct Stepper {
    static constexpr const char* familyName = "stepperForTest";
    using Selector = Registry<Stepper, const Dictionary&>;
    explicit Stepper(const Dictionary&) {}
    virtual ~Stepper() = default;
    virtual int dimension() const = 0;
};

template <int Dim>
struct PlainStepper final : Stepper<Dim> {
    using Stepper<Dim>::Stepper;
    int dimension() const override { return Dim; }
};

MFDYN_REGISTER_DIM(Stepper, PlainStepper, "plain", "a family templated on the dimension");

}  // namespace

TEST(Registry, DimensionTemplatedFamilyHasOneNameAndAnInstancePerDimension) {
    const Dictionary dict = Dictionary::parse("type plain;", "dict");
    EXPECT_EQ(Stepper<1>::Selector::New(dict)->dimension(), 1);
    EXPECT_EQ(Stepper<2>::Selector::New(dict)->dimension(), 2);
    EXPECT_EQ(Stepper<3>::Selector::New(dict)->dimension(), 3);
    EXPECT_EQ(Stepper<3>::Selector::names(), std::vector<std::string>{"plain"});
    RegistryIndex::global().checkConflicts();  // three registrations of one name are no clash
    const std::string listing = RegistryIndex::global().listing();
    const auto first = listing.find("a family templated on the dimension");
    EXPECT_EQ(listing.find("a family templated on the dimension", first + 1), std::string::npos) << listing;
}
