// The keyword schema reader (core/KeywordSchema.hpp): a missing required keyword, a value outside
// its bounds and a word outside its choices are InputErrors at file:line naming the keyword; a
// default is applied and echoed once in the log; reading an undeclared name is a logic error; a
// registration carries its schema and source file into -listModels and -describe.
#include "core/KeywordSchema.hpp"

#include "core/Dictionary.hpp"
#include "core/Registry.hpp"

#include <gtest/gtest.h>

#include <cstdlib>
#include <functional>
#include <limits>
#include <stdexcept>

using namespace mfdyn;

namespace {

KeywordSchema widgetSchema() {
    return KeywordSchema("widgetForTest", "spring")
        .scalar("stiffness", "N/m", "spring constant")
        .greaterThan(0)
        .scalar("damping", "-", "damping ratio")
        .atLeast(0)
        .atMost(1)
        .orDefault(0.05)
        .word("law", {"linear", "cubic"}, "force law")
        .orDefault("linear")
        .integer("coils", "-", "number of coils")
        .atLeast(1)
        .optional()
        .flag("preloaded", "start compressed")
        .orDefault(false)
        .scalar("length", "m", "rest length")
        .greaterThan(0)
        .orEnclosing();
}

std::string messageOf(const std::function<void()>& f) {
    try {
        f();
    } catch (const InputError& e) {
        return e.what();
    }
    ADD_FAILURE() << "no InputError";
    return {};
}

bool contains(const std::string& text, const std::string& part) {
    return text.find(part) != std::string::npos;
}

}  // namespace

TEST(KeywordSchema, ReadsGivenValues) {
    const Dictionary dict = Dictionary::parse(
        "stiffness 2e3; damping 0.2; law cubic; coils 12; preloaded yes; length 0.1;", "widgetDict");
    const KeywordValues v = widgetSchema().read(dict);
    EXPECT_EQ(v.scalar("stiffness"), 2e3);
    EXPECT_EQ(v.scalar("damping"), 0.2);
    EXPECT_EQ(v.word("law"), "cubic");
    EXPECT_EQ(v.integer("coils"), 12);
    EXPECT_TRUE(v.flag("preloaded"));
    EXPECT_TRUE(v.given("coils"));
    EXPECT_TRUE(v.defaultsUsed().empty());
    EXPECT_TRUE(dict.unusedEntries().empty());  // every declared keyword was read
}

TEST(KeywordSchema, MissingRequiredKeywordNamesFileLineAndKeyword) {
    const Dictionary top =
        Dictionary::parse("springs\n{\n    a\n    {\n        damping 0.1;\n        length 1;\n    }\n}\n",
                          "constant/widgetDict");
    const std::string what = messageOf([&] { widgetSchema().read(top.subDict("springs").subDict("a")); });
    EXPECT_TRUE(contains(what, "constant/widgetDict:3")) << what;  // the sub-dictionary's line
    EXPECT_TRUE(contains(what, "missing keyword 'stiffness'")) << what;
    EXPECT_TRUE(contains(what, "N/m")) << what;
    EXPECT_TRUE(contains(what, "widgetForTest type 'spring'")) << what;
}

TEST(KeywordSchema, MissingEnclosingKeywordNamesBothScopes) {
    const Dictionary top = Dictionary::parse("a { spring { stiffness 1; } }", "widgetDict");
    const std::string what = messageOf([&] { widgetSchema().read(top.subDict("a").subDict("spring")); });
    EXPECT_TRUE(contains(what, "missing keyword 'length'")) << what;
    EXPECT_TRUE(contains(what, "looked for in 'a/spring' and in the enclosing 'a'")) << what;
}

TEST(KeywordSchema, EnclosingDictionaryGivesTheValueAndOwnEntryWins) {
    const Dictionary top = Dictionary::parse(
        "a { length 2; spring { stiffness 1; } } b { length 2; spring { stiffness 1; length 3; } }",
        "widgetDict");
    EXPECT_EQ(widgetSchema().read(top.subDict("a").subDict("spring")).scalar("length"), 2.0);
    EXPECT_EQ(widgetSchema().read(top.subDict("b").subDict("spring")).scalar("length"), 3.0);
    // `stiffness` is not orEnclosing: a material's entry is not taken for it.
    const Dictionary c = Dictionary::parse("c { stiffness 1; spring { length 1; } }", "widgetDict");
    EXPECT_TRUE(contains(messageOf([&] { widgetSchema().read(c.subDict("c").subDict("spring")); }),
                         "missing keyword 'stiffness'"));
}

TEST(KeywordSchema, OutOfBoundsValueNamesBoundAndUnit) {
    const Dictionary dict = Dictionary::parse("length 1;\nstiffness -3;", "widgetDict");
    const std::string what = messageOf([&] { widgetSchema().read(dict); });
    EXPECT_TRUE(contains(what, "widgetDict:2")) << what;
    EXPECT_TRUE(contains(what, "keyword 'stiffness': expected a value > 0 (N/m), found -3")) << what;
    const Dictionary two = Dictionary::parse("length 1; stiffness 3; damping 1.5;", "widgetDict");
    EXPECT_TRUE(
        contains(messageOf([&] { widgetSchema().read(two); }), "expected a value >= 0 and <= 1, found 1.5"));
    const Dictionary three = Dictionary::parse("length 1; stiffness 3; coils 0;", "widgetDict");
    EXPECT_TRUE(
        contains(messageOf([&] { widgetSchema().read(three); }), "keyword 'coils': expected a value >= 1"));
}

TEST(KeywordSchema, WrongTypeIsAnInputError) {
    const Dictionary dict = Dictionary::parse("length 1; stiffness soft;", "widgetDict");
    EXPECT_TRUE(contains(messageOf([&] { widgetSchema().read(dict); }),
                         "keyword 'stiffness': expected a real number"));
    const Dictionary coils = Dictionary::parse("length 1; stiffness 1; coils 2.5;", "widgetDict");
    EXPECT_TRUE(
        contains(messageOf([&] { widgetSchema().read(coils); }), "keyword 'coils': expected an integer"));
}

TEST(KeywordSchema, WrongWordListsTheValidChoices) {
    const Dictionary dict = Dictionary::parse("length 1; stiffness 1; law cubik;", "widgetDict");
    const std::string what = messageOf([&] { widgetSchema().read(dict); });
    EXPECT_TRUE(contains(what, "keyword 'law': expected one of linear | cubic, found 'cubik'")) << what;
    EXPECT_TRUE(contains(what, "did you mean 'cubic'")) << what;
}

TEST(KeywordSchema, DefaultsAreAppliedAndEchoedOnce) {
    const Dictionary top =
        Dictionary::parse("parts { spring { stiffness 1; length 1; law cubic; } }", "widgetDict");
    const Dictionary& dict = top.subDict("parts").subDict("spring");
    testing::internal::CaptureStdout();
    const KeywordValues v = widgetSchema().read(dict);
    const std::string log = testing::internal::GetCapturedStdout();
    EXPECT_EQ(v.scalar("damping"), 0.05);
    EXPECT_FALSE(v.flag("preloaded"));
    EXPECT_FALSE(v.given("damping"));
    EXPECT_FALSE(v.optionalScalar("coils"));  // optional, no default: absent
    EXPECT_EQ(v.defaultsUsed(), (std::vector<std::string>{"damping 0.05", "preloaded no"}));
    EXPECT_EQ(log, "widgetForTest spring (parts/spring): damping 0.05 (default); preloaded no (default)\n");
    // The dictionary keeps them for the solver's "Defaults used" summary.
    EXPECT_EQ(dict.defaultsUsed(),
              (std::vector<std::string>{"parts/spring/damping 0.05", "parts/spring/preloaded no"}));
}

TEST(KeywordSchema, UndeclaredNameIsALogicErrorNamingTheModel) {
    const Dictionary dict = Dictionary::parse("stiffness 1; length 1;", "widgetDict");
    const KeywordValues v = widgetSchema().read(dict);
    try {
        v.scalar("stifness");
        FAIL() << "undeclared keyword read";
    } catch (const std::logic_error& e) {
        EXPECT_TRUE(contains(e.what(), "widgetForTest spring")) << e.what();
        EXPECT_TRUE(contains(e.what(), "'stifness'")) << e.what();
    }
    EXPECT_THROW(v.word("stiffness"), std::logic_error);  // declared as a real number
    EXPECT_THROW(KeywordSchema("f", "t").scalar("x", "-", "x").atLeast(0).orDefault(-1.0), std::logic_error);
    EXPECT_THROW(KeywordSchema("f", "t").word("w", {"a", "b"}, "w").orDefault("c"), std::logic_error);
}

TEST(KeywordSchema, TypoOfADeclaredKeywordIsSuggested) {
    const Dictionary dict = Dictionary::parse("stiffness 1; length 1; dampng 0.1;", "widgetDict");
    widgetSchema().read(dict);
    const auto unused = dict.unusedEntries();
    ASSERT_EQ(unused.size(), 1u);
    EXPECT_EQ(unused[0].suggestion, "damping");
}

TEST(KeywordSchema, SummaryAndSampleValues) {
    const std::string summary = widgetSchema().summary("  ");
    EXPECT_TRUE(contains(summary, "  stiffness  N/m  required")) << summary;
    EXPECT_TRUE(contains(summary, "default 0.05")) << summary;
    EXPECT_TRUE(contains(summary, ">= 0 and <= 1")) << summary;
    EXPECT_TRUE(contains(summary, "linear | cubic")) << summary;
    EXPECT_TRUE(contains(summary, "or in the enclosing dictionary")) << summary;
    const KeywordSchema schema = widgetSchema();
    const auto& keys = schema.keywords();
    EXPECT_EQ(keys[0].sampleValue(), "1");
    EXPECT_EQ(keys[1].sampleValue(), "0.05");
    EXPECT_EQ(keys[3].sampleValue(), "1");
    EXPECT_EQ(formatKeywordNumber(0.1), "0.1");
    EXPECT_EQ(formatKeywordNumber(1.0 / 3.0), "0.3333333333333333");
}

// ---- registration ----------------------------------------------------------------------------

namespace {

struct Widget {
    static constexpr const char* familyName = "widgetForTest";
    using Selector = Registry<Widget, const Dictionary&>;
    explicit Widget(const Dictionary&) {}
    virtual ~Widget() = default;
};

struct Spring final : Widget {
    static KeywordSchema keywords() { return widgetSchema(); }
    explicit Spring(const Dictionary& dict)
        : Widget(dict), stiffness(keywords().read(dict).scalar("stiffness")) {}
    double stiffness;
};

struct Lever final : Widget {  // no schema yet: registers as before
    using Widget::Widget;
};

MFDYN_REGISTER(Widget, Spring, "spring", "a spring");
MFDYN_REGISTER(Widget, Lever, "lever", "a lever");

}  // namespace

TEST(KeywordSchema, RegistrationCarriesSchemaAndSourceFile) {
    const RegistryFamily* fam = RegistryIndex::global().findFamily("widgetForTest");
    ASSERT_NE(fam, nullptr);
    const RegistryItem* spring = fam->find("spring");
    const RegistryItem* lever = fam->find("lever");
    ASSERT_TRUE(spring && lever);
    ASSERT_NE(spring->keywords, nullptr);
    EXPECT_EQ(spring->keywords().keywords().size(), widgetSchema().keywords().size());
    EXPECT_EQ(lever->keywords, nullptr);
    EXPECT_EQ(spring->sourceFile, "tests/unit/core/KeywordSchemaTest.cpp");
    const Dictionary dict = Dictionary::parse("type spring; stiffness 4; length 1;", "widgetDict");
    testing::internal::CaptureStdout();
    EXPECT_NE(Widget::Selector::New(dict), nullptr);
    testing::internal::GetCapturedStdout();

    const std::string listing = RegistryIndex::global().listing();
    EXPECT_TRUE(contains(listing, "a spring  [coreKeywordSchemaTest]\n        stiffness  N/m  required"))
        << listing;
    const std::string described = RegistryIndex::global().describe("widgetForTest/spring");
    EXPECT_TRUE(contains(described, "source:  tests/unit/core/KeywordSchemaTest.cpp")) << described;
    EXPECT_TRUE(contains(described, "damping ratio")) << described;
    EXPECT_TRUE(contains(RegistryIndex::global().describe("lever"), "no schema declared yet"));
    EXPECT_TRUE(contains(RegistryIndex::global().describe("widgetForTest"), "lever"));
    EXPECT_THROW(RegistryIndex::global().describe("sprng"), InputError);
}

TEST(KeywordSchema, VectorDefaultsAndLength) {
    const KeywordSchema schema = KeywordSchema("widgetForTest", "pair")
                                     .vector("coefficients", "-", "(a b)")
                                     .atLeast(0)
                                     .ofLength(2)
                                     .orDefault(std::vector<double>{0.5, 2.0})
                                     .vector("anyLength", "m", "a list")
                                     .optional();
    const Keyword* pair = schema.find("coefficients");
    ASSERT_NE(pair, nullptr);
    EXPECT_EQ(pair->defaultValue, "(0.5 2)");
    EXPECT_EQ(pair->typeText(), "a list of 2 reals (...)");
    const Dictionary defaults = Dictionary::parse("type pair;", "pair");
    EXPECT_EQ(schema.read(defaults).vector("coefficients"), (std::vector<double>{0.5, 2.0}));
    const Dictionary given = Dictionary::parse("type pair; coefficients (1 3); anyLength (1 2 3 4);", "pair");
    const KeywordValues v = schema.read(given);
    EXPECT_EQ(v.vector("coefficients"), (std::vector<double>{1.0, 3.0}));
    EXPECT_EQ(v.vector("anyLength").size(), 4u);
    const std::string wrongLength =
        messageOf([&] { schema.read(Dictionary::parse("coefficients (1 2 3);", "pair")); });
    EXPECT_NE(wrongLength.find("keyword 'coefficients'"), std::string::npos) << wrongLength;
    EXPECT_NE(wrongLength.find("expected 2 values"), std::string::npos) << wrongLength;
    const std::string negative =
        messageOf([&] { schema.read(Dictionary::parse("coefficients (1 -2);", "pair")); });
    EXPECT_NE(negative.find(">= 0"), std::string::npos) << negative;
    // A default of another length than declared is a programming error.
    EXPECT_THROW(KeywordSchema("widgetForTest", "bad")
                     .vector("c", "-", "c")
                     .ofLength(2)
                     .orDefault(std::vector<double>{1.0}),
                 std::logic_error);
}

TEST(KeywordSchema, NamesListsTablesAndExamples) {
    const KeywordSchema schema = KeywordSchema("widgetForTest", "probe")
                                     .identifier("field", "a field of the run")
                                     .orDefault("density")
                                     .words("regions", "regions read")
                                     .orDefaultNames({"a", "b"})
                                     .words("tags", "tags")
                                     .optional()
                                     .table("rows", "s, m", "rows the model parses")
                                     .example("((0 1))")
                                     .vector("normal", "-", "a direction")
                                     .example("(1 0 0)")
                                     .optional();
    EXPECT_EQ(schema.find("regions")->defaultValue, "(a b)");
    EXPECT_EQ(schema.find("rows")->sampleValue(), "((0 1))");
    EXPECT_EQ(schema.find("normal")->sampleValue(), "(1 0 0)");  // not the zeros of the default rule
    const Dictionary dict = Dictionary::parse("field velocity; tags (x y); rows ((0 (1 2)) (1 (3 4)));", "d");
    const KeywordValues v = schema.read(dict);
    EXPECT_EQ(v.word("field"), "velocity");                               // any name is valid
    EXPECT_EQ(v.words("regions"), (std::vector<std::string>{"a", "b"}));  // the default
    EXPECT_EQ(v.words("tags"), (std::vector<std::string>{"x", "y"}));
    EXPECT_TRUE(v.given("rows"));
    EXPECT_TRUE(dict.unusedEntries().empty());  // the table is marked read for the model
    const std::string empty =
        messageOf([&] { schema.read(Dictionary::parse("tags (); rows ((0 1));", "d")); });
    EXPECT_TRUE(contains(empty, "keyword 'tags'")) << empty;
    EXPECT_TRUE(contains(empty, "expected at least one name")) << empty;
    const std::string missing = messageOf([&] { schema.read(Dictionary::parse("field x;", "d")); });
    EXPECT_TRUE(contains(missing, "missing keyword 'rows'")) << missing;
}

// Hardening (issue 14).

// A subnormal value in a bound message threw std::out_of_range from std::stod ("Error (internal):
// stod"). The value is shown as read, in %g style with the digits that read back to it.
TEST(KeywordSchema, SubnormalValuesAreShownAsRead) {
    EXPECT_EQ(formatKeywordNumber(5e-321), "4.99994e-321");
    EXPECT_EQ(formatKeywordNumber(1e-320), "9.99989e-321");  // not "0.000000"
    EXPECT_EQ(formatKeywordNumber(std::numeric_limits<double>::denorm_min()), "4.94066e-324");
    for (const double x : {5e-321, 1e-320, 2.2250738585072014e-308, 1.7976931348623157e308, 0.1 + 0.2})
        EXPECT_EQ(std::strtod(formatKeywordNumber(x).c_str(), nullptr), x) << formatKeywordNumber(x);
    EXPECT_EQ(formatKeywordNumber(2.65e8), "2.65e+08");
    EXPECT_EQ(formatKeywordNumber(0.1 + 0.2), "0.30000000000000004");

    const Dictionary dict =
        Dictionary::parse("length 1;\nstiffness 1;\ncoils 1;\ndamping -5e-321;", "widgetDict");
    const std::string what = messageOf([&] { widgetSchema().read(dict); });
    EXPECT_TRUE(contains(
        what, "widgetDict:4:1: keyword 'damping': expected a value >= 0 and <= 1, found -4.99994e-321"))
        << what;
}

// A misspelt `intervall` was reported only as a missing `interval`: the message names the key that
// is there. A key that is another keyword of the schema is not offered as the typo.
TEST(KeywordSchema, MissingKeywordNamesTheMisspeltKey) {
    const KeywordSchema schema = KeywordSchema("widgetForTest", "timer")
                                     .scalar("interval", "s", "time between ticks")
                                     .greaterThan(0)
                                     .integer("intervals", "-", "number of ticks")
                                     .optional();
    const Dictionary typo = Dictionary::parse("\nintervall 0.5;", "timerDict");
    EXPECT_EQ(
        messageOf([&] { schema.read(typo); }),
        "timerDict:1:1: missing keyword 'interval' (time between ticks, a real number in s), required by "
        "widgetForTest type 'timer' (found 'intervall': did you mean 'interval'?)");
    const Dictionary other = Dictionary::parse("intervals 3;", "timerDict");
    const std::string what = messageOf([&] { schema.read(other); });
    EXPECT_TRUE(contains(what, "missing keyword 'interval'")) << what;
    EXPECT_FALSE(contains(what, "found 'intervals'")) << what;
}

// A word outside the choices is quoted as a short excerpt, not whole.
TEST(KeywordSchema, WrongWordIsQuotedShort) {
    const Dictionary dict =
        Dictionary::parse("length 1; stiffness 1; law \"" + std::string(5000, 'x') + "\";", "widgetDict");
    const std::string what = messageOf([&] { widgetSchema().read(dict); });
    EXPECT_TRUE(contains(what, "expected one of linear | cubic, found 'xxx")) << what;
    EXPECT_LT(what.size(), 300u) << what;
}

namespace {

KeywordSchema projectionSchema() {
    return KeywordSchema("solverForTest", "projection")
        .scalar("tolerance", "-", "relative residual to stop at")
        .greaterThan(0)
        .orDefault(1e-10)
        .integer("maxIterations", "-", "iterations at most")
        .atLeast(1);
}

KeywordSchema solverSchema() {
    return KeywordSchema("solver", "solverForTest")
        .scalar("cfl", "-", "Courant number")
        .greaterThan(0)
        .dictionary("projection", "the projection's settings")
        .optional()
        .nested(&projectionSchema);
}

}  // namespace

TEST(KeywordSchema, NestedSchemaValidatesAGivenSubDictionaryAtItsLine) {
    // Given: read through the nested schema, values and defaults available from the same read.
    const Dictionary good =
        Dictionary::parse("cfl 0.5;\nprojection\n{\n    maxIterations 20;\n}\n", "solverDict");
    testing::internal::CaptureStdout();
    const KeywordValues v = solverSchema().read(good);
    const std::string log = testing::internal::GetCapturedStdout();
    EXPECT_TRUE(v.given("projection"));
    EXPECT_EQ(v.nested("projection").integer("maxIterations"), 20);
    EXPECT_EQ(v.nested("projection").scalar("tolerance"), 1e-10);
    EXPECT_TRUE(contains(log, "tolerance 1e-10 (default)")) << log;

    // A bad value inside: the error is at the sub-dictionary's line and names the keyword.
    const Dictionary bad =
        Dictionary::parse("cfl 0.5;\nprojection\n{\n    maxIterations 0;\n}\n", "solverDict");
    const std::string message = messageOf([&] { solverSchema().read(bad); });
    EXPECT_TRUE(contains(message, "solverDict:4")) << message;
    EXPECT_TRUE(contains(message, "maxIterations")) << message;
    EXPECT_TRUE(contains(message, ">= 1")) << message;

    // A missing required keyword inside names the nested schema.
    const Dictionary missing = Dictionary::parse("cfl 0.5;\nprojection { }\n", "solverDict");
    EXPECT_TRUE(
        contains(messageOf([&] { solverSchema().read(missing); }), "missing keyword 'maxIterations'"));

    // Absent and optional: not read, and asking for its values is a programming error.
    const Dictionary absent = Dictionary::parse("cfl 0.5;", "solverDict");
    const KeywordValues none = solverSchema().read(absent);
    EXPECT_FALSE(none.given("projection"));
    EXPECT_THROW((void)none.nested("projection"), std::logic_error);
    EXPECT_THROW((void)none.nested("cfl"), std::logic_error);
    // Only a dictionary keyword takes a nested schema.
    EXPECT_THROW(KeywordSchema("f", "t").scalar("x", "-", "x").nested(&projectionSchema), std::logic_error);
}

TEST(KeywordSchema, NestedKeywordsAreListedIndentedUnderTheirDictionary) {
    const std::string summary = solverSchema().summary("  ");
    const auto dict = summary.find("  projection");
    const auto inner = summary.find("      tolerance");
    EXPECT_NE(dict, std::string::npos) << summary;
    EXPECT_NE(inner, std::string::npos) << summary;
    EXPECT_LT(dict, inner) << summary;
    EXPECT_NE(summary.find("      maxIterations"), std::string::npos) << summary;
}
