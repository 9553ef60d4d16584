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

namespace {

// Two families of one name in two methods (contract: a family base may declare methodName), each
// with a type "shared" of the same name and one type of its own.
struct SmootherA {
    static constexpr const char* familyName = "smootherForTest";
    static constexpr const char* methodName = "methodA";
    using Selector = Registry<SmootherA, const Dictionary&>;
    explicit SmootherA(const Dictionary&) {}
    virtual ~SmootherA() = default;
    virtual std::string who() const = 0;
};
struct SmootherB {
    static constexpr const char* familyName = "smootherForTest";
    static constexpr const char* methodName = "methodB";
    using Selector = Registry<SmootherB, const Dictionary&>;
    explicit SmootherB(const Dictionary&) {}
    virtual ~SmootherB() = default;
    virtual std::string who() const = 0;
};
struct SharedA final : SmootherA {
    using SmootherA::SmootherA;
    std::string who() const override { return "A shared"; }
};
struct OnlyA final : SmootherA {
    using SmootherA::SmootherA;
    std::string who() const override { return "A only"; }
};
struct SharedB final : SmootherB {
    using SmootherB::SmootherB;
    std::string who() const override { return "B shared"; }
};
struct OnlyB final : SmootherB {
    using SmootherB::SmootherB;
    std::string who() const override { return "B only"; }
};

MFDYN_REGISTER(SmootherA, SharedA, "shared", "method A's shared-name smoother");
MFDYN_REGISTER(SmootherA, OnlyA, "onlyInA", "method A's own smoother");
MFDYN_REGISTER(SmootherB, SharedB, "shared", "method B's shared-name smoother");
MFDYN_REGISTER(SmootherB, OnlyB, "onlyInB", "method B's own smoother");

bool contains(const std::string& text, const std::string& part) {
    return text.find(part) != std::string::npos;
}

}  // namespace

TEST(Registry, MethodScopedFamiliesOfOneNameAreDistinct) {
    // The same type name in both methods is no clash, and each method selects its own class.
    RegistryIndex::global().checkConflicts();
    const Dictionary dict = Dictionary::parse("type shared;", "dict");
    EXPECT_EQ(SmootherA::Selector::New(dict)->who(), "A shared");
    EXPECT_EQ(SmootherB::Selector::New(dict)->who(), "B shared");
    EXPECT_EQ(SmootherA::Selector::names(), (std::vector<std::string>{"onlyInA", "shared"}));
    EXPECT_EQ(SmootherB::Selector::names(), (std::vector<std::string>{"onlyInB", "shared"}));
    EXPECT_EQ(familyTitle<SmootherA>(), "smootherForTest (methodA)");
    EXPECT_EQ(familyTitle<Greeter>(), "greeterForTest");  // a family without methodName is unchanged
    ASSERT_NE(RegistryIndex::global().findFamily("smootherForTest", "methodB"), nullptr);
    EXPECT_EQ(RegistryIndex::global().findFamily("smootherForTest"), nullptr);  // no shared one
    EXPECT_EQ(RegistryIndex::global().familiesNamed("smootherForTest").size(), 2u);
}

TEST(Registry, UnknownTypeOfAScopedFamilyNamesItAndListsOnlyItsTypes) {
    // Method B's type in method A's dictionary: the message says which family was searched, and
    // does not offer B's types, which A cannot select.
    const Dictionary dict = Dictionary::parse("\ntype onlyInB;", "aProperties");
    try {
        SmootherA::Selector::New(dict);
        FAIL() << "no error";
    } catch (const InputError& e) {
        const std::string what = e.what();
        EXPECT_TRUE(contains(what, "aProperties:2:1")) << what;
        EXPECT_TRUE(contains(what, "unknown smootherForTest (methodA) type 'onlyInB'")) << what;
        EXPECT_TRUE(contains(what, "valid smootherForTest (methodA) types:")) << what;
        EXPECT_TRUE(contains(what, "onlyInA")) << what;
        EXPECT_FALSE(contains(what, "onlyInB  (")) << what;
    }
}

TEST(Registry, ListingAndDescribeNameScopedFamilies) {
    const RegistryIndex& index = RegistryIndex::global();
    const std::string listing = index.listing();
    EXPECT_TRUE(contains(listing, "\nsmootherForTest (methodA)\n")) << listing;
    EXPECT_TRUE(contains(listing, "\nsmootherForTest (methodB)\n")) << listing;
    EXPECT_LT(listing.find("smootherForTest (methodA)"), listing.find("smootherForTest (methodB)"));

    // The bare name lists both families.
    const std::string both = index.describe("smootherForTest");
    EXPECT_TRUE(contains(both, "smootherForTest (methodA)\n")) << both;
    EXPECT_TRUE(contains(both, "smootherForTest (methodB)\n")) << both;
    EXPECT_TRUE(contains(both, "onlyInA") && contains(both, "onlyInB")) << both;

    // method/family lists one.
    const std::string onlyB = index.describe("methodB/smootherForTest");
    EXPECT_TRUE(contains(onlyB, "smootherForTest (methodB)\n")) << onlyB;
    EXPECT_FALSE(contains(onlyB, "onlyInA")) << onlyB;

    // family/type gives the type of every family of that name; method/family/type one of them.
    const std::string sharedBoth = index.describe("smootherForTest/shared");
    EXPECT_TRUE(contains(sharedBoth, "smootherForTest (methodA) shared: method A's")) << sharedBoth;
    EXPECT_TRUE(contains(sharedBoth, "smootherForTest (methodB) shared: method B's")) << sharedBoth;
    const std::string sharedA = index.describe("methodA/smootherForTest/shared");
    EXPECT_TRUE(contains(sharedA, "smootherForTest (methodA) shared")) << sharedA;
    EXPECT_FALSE(contains(sharedA, "method B's")) << sharedA;

    // A wrong method names the families, scoped ones by their key.
    try {
        (void)index.describe("methodC/smootherForTest/shared");
        FAIL() << "no error";
    } catch (const InputError& e) {
        EXPECT_TRUE(contains(e.what(), "families:")) << e.what();
        EXPECT_TRUE(contains(e.what(), " methodA/smootherForTest")) << e.what();
    }
}

TEST(Registry, DuplicateInAScopedFamilyNamesTheScopedFamily) {
    RegistryIndex index;
    index.add("family", RegistryItem{"same", "first", "libA.so", nullptr}, "m1");
    index.add("family", RegistryItem{"same", "second", "libB.so", nullptr}, "m2");
    index.checkConflicts();  // one name in two methods: no clash
    index.add("family", RegistryItem{"same", "third", "libC.so", nullptr}, "m2");
    try {
        index.checkConflicts();
        FAIL() << "no error";
    } catch (const Error& e) {
        EXPECT_TRUE(
            contains(e.what(), "family (m2) type 'same' is registered twice: by libB.so and by libC.so"))
            << e.what();
    }
}

// A registration's source file is the path in the source tree whatever form __FILE__ takes: the
// absolute path a plain build gives, or one relative to the compiler's directory in the build
// tree (ccache with base_dir rewrites them so; Ninja compiles in build/, Makefiles in each
// target's subdirectory). mfDoc's pages and tests name the sources by it.
TEST(Registry, SourceFileIsRelativeToTheSourceTreeForAnyFormOfFile) {
    EXPECT_EQ(sourceFileRelative("../libraries/core/Registry.cpp"), "libraries/core/Registry.cpp");
    EXPECT_EQ(sourceFileRelative("../../../tests/unit/core/RegistryTest.cpp"),
              "tests/unit/core/RegistryTest.cpp");
    EXPECT_EQ(sourceFileRelative("./libraries/core/Registry.cpp"), "libraries/core/Registry.cpp");
    EXPECT_EQ(sourceFileRelative(__FILE__), "tests/unit/core/RegistryTest.cpp");
    EXPECT_EQ(sourceFileRelative(""), "");
}
