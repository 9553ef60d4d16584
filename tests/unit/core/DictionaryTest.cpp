// Dictionary: the data-driven fixtures in fixtures/*.dict (each states its expectation in its
// leading comments), then typed look-up, tracking, editing and copying.
#include "core/Dictionary.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <fstream>
#include <sstream>

#include <unistd.h>

namespace fs = std::filesystem;
using namespace mfdyn;

namespace {

const fs::path fixtureDir = MFDYN_FIXTURE_DIR;

std::string readText(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

std::string trim(std::string s) {
    const auto b = s.find_first_not_of(" \t\r");
    if (b == std::string::npos) return {};
    return s.substr(b, s.find_last_not_of(" \t\r") - b + 1);
}

std::string valueString(const Entry& e) {
    std::string s;
    for (const Token& t : e.tokens) s += (s.empty() ? "" : " ") + t.str();
    return s;
}

// One expectation line: `// expect<-kind>: path = value`, `// expect-error: L:C message`, `// etc: dir`.
struct Expectation {
    std::string kind, path, value;
};

std::vector<Expectation> expectationsOf(const std::string& text) {
    std::vector<Expectation> out;
    std::istringstream in(text);
    std::string line;
    while (std::getline(in, line) && line.rfind("//", 0) == 0) {
        line = trim(line.substr(2));
        const auto colon = line.find(':');
        if (colon == std::string::npos) continue;
        Expectation x{line.substr(0, colon), {}, trim(line.substr(colon + 1))};
        if (x.kind != "expect-error" && x.kind != "etc") {
            const auto eq = x.value.find(" =");
            if (eq == std::string::npos) continue;
            x.path = trim(x.value.substr(0, eq));
            x.value = trim(x.value.substr(eq + 2));
        }
        out.push_back(x);
    }
    return out;
}

std::vector<std::string> fixtureNames() {
    std::vector<std::string> names;
    for (const auto& f : fs::directory_iterator(fixtureDir))
        if (f.path().extension() == ".dict") names.push_back(f.path().filename().string());
    std::sort(names.begin(), names.end());
    return names;
}

const Entry& scoped(const Dictionary& d, const std::string& path) {
    const Entry* e = d.findScoped(path);
    if (!e) throw std::runtime_error("no entry " + path);
    return *e;
}

class Fixture : public ::testing::TestWithParam<std::string> {};

TEST_P(Fixture, meetsItsExpectations) {
    const fs::path file = fixtureDir / GetParam();
    const auto expectations = expectationsOf(readText(file));
    ASSERT_FALSE(expectations.empty()) << "fixture states no expectation";
    ReadOptions options;
    const Expectation* error = nullptr;
    for (const auto& x : expectations) {
        if (x.kind == "etc") options.etcDirectories.push_back(fixtureDir / x.value);
        if (x.kind == "expect-error") error = &x;
    }
    if (error) {
        // "L:C fragment" locates in this file; "path:L:C fragment" in a file below fixtures/.
        const auto space = error->value.find(' ');
        const std::string where = error->value.substr(0, space);
        const std::string fragment = trim(error->value.substr(space + 1));
        const std::string located = std::count(where.begin(), where.end(), ':') == 1
                                        ? file.string() + ":" + where + ": "
                                        : (fixtureDir / where).string() + ": ";
        try {
            Dictionary::read(file, options);
            FAIL() << "expected an error containing \"" << located << "\" and \"" << fragment << "\"";
        } catch (const InputError& e) {
            const std::string message = e.what();
            EXPECT_NE(message.find(located), std::string::npos) << message;
            EXPECT_NE(message.find(fragment), std::string::npos) << message;
        }
        return;
    }
    const Dictionary d = Dictionary::read(file, options);
    for (const auto& x : expectations) {
        SCOPED_TRACE(x.kind + ": " + x.path + " = " + x.value);
        if (x.kind == "expect") {
            EXPECT_EQ(valueString(scoped(d, x.path)), x.value);
        } else if (x.kind == "expect-real") {
            const Entry& e = scoped(d, x.path);
            ASSERT_EQ(e.tokens.size(), 1u);
            ASSERT_TRUE(e.tokens[0].isNumber());
            EXPECT_EQ(e.tokens[0].number(), std::stod(x.value));  // both read the same digits
        } else if (x.kind == "expect-int") {
            const Entry& e = scoped(d, x.path);
            ASSERT_EQ(e.tokens.size(), 1u);
            ASSERT_EQ(e.tokens[0].kind, Token::Kind::integer);
            EXPECT_EQ(e.tokens[0].integer, std::stoll(x.value));
        } else if (x.kind == "expect-kind") {
            const Entry& e = scoped(d, x.path);
            ASSERT_EQ(e.tokens.size(), 1u);
            static const char* names[] = {"word", "string", "integer", "real", "list", "dictionary"};
            EXPECT_EQ(names[int(e.tokens[0].kind)], x.value);
        } else if (x.kind == "expect-keys") {
            const Dictionary& sub = x.path == "." ? d : *scoped(d, x.path).dict;
            std::string keys;
            for (const auto& k : sub.keys()) keys += (keys.empty() ? "" : " ") + k;
            EXPECT_EQ(keys, x.value);
        } else if (x.kind == "expect-from-include") {
            EXPECT_EQ(scoped(d, x.path).fromInclude, x.value == "yes");
        } else if (x.kind != "etc") {
            ADD_FAILURE() << "unknown expectation " << x.kind;
        }
    }
    // Whatever parses must print to text that parses back to the same text.
    const std::string printed = d.str();
    EXPECT_EQ(Dictionary::parse(printed, "printed").str(), printed);
}

INSTANTIATE_TEST_SUITE_P(Fixtures, Fixture, ::testing::ValuesIn(fixtureNames()),
                         [](const ::testing::TestParamInfo<std::string>& info) {
                             return fs::path(info.param).stem().string();
                         });

TEST(DictionaryFixtures, areNumerousAndIncludeMalformedOnes) {
    int malformed = 0;
    for (const auto& name : fixtureNames())
        for (const auto& x : expectationsOf(readText(fixtureDir / name)))
            malformed += x.kind == "expect-error";
    EXPECT_GE(fixtureNames().size(), 40u);
    EXPECT_GE(malformed, 12);
}

// ------------------------------------------------------------------------------------------

const char* const sample = R"(
rho0    2785;
nu      0.33;
steps   100;
name    target;
label   "the target plate";
active  yes;
g       (0 -9.81 0);
ids     (1 2 3);
fields  (rho "p" U);
eos
{
    type mieGruneisen;
    c0   5330;
}
)";

TEST(DictionaryLookup, typedValues) {
    const Dictionary d = Dictionary::parse(sample, "sample");
    EXPECT_EQ(d.get<double>("rho0"), 2785.0);
    EXPECT_EQ(d.get<float>("nu"), 0.33f);
    EXPECT_EQ(d.get<int>("steps"), 100);
    EXPECT_EQ(d.get<long>("steps"), 100L);
    EXPECT_EQ(d.get<long long>("steps"), 100LL);
    EXPECT_EQ(d.get<unsigned long>("steps"), 100UL);
    EXPECT_EQ(d.get<std::string>("name"), "target");
    EXPECT_EQ(d.get<std::string>("label"), "the target plate");
    EXPECT_TRUE(d.get<bool>("active"));
    EXPECT_EQ(d.get<std::vector<double>>("g"), (std::vector<double>{0, -9.81, 0}));
    EXPECT_EQ(d.get<std::vector<double>>("ids"), (std::vector<double>{1, 2, 3}));
    EXPECT_EQ(d.get<std::vector<int>>("ids"), (std::vector<int>{1, 2, 3}));
    EXPECT_EQ(d.get<std::vector<std::string>>("fields"), (std::vector<std::string>{"rho", "p", "U"}));
    EXPECT_EQ(d.subDict("eos").get<double>("c0"), 5330.0);
    EXPECT_EQ(d.subDict("eos").scope(), "eos");
}

TEST(DictionaryLookup, switches) {
    const Dictionary d = Dictionary::parse("a yes; b no; c on; d off; e true; f false; g maybe;", "s");
    const std::vector<std::pair<const char*, bool>> expected{{"a", true},  {"b", false}, {"c", true},
                                                             {"d", false}, {"e", true},  {"f", false}};
    for (const auto& [key, value] : expected) EXPECT_EQ(d.get<bool>(key), value) << key;
    EXPECT_THROW(d.get<bool>("g"), InputError);
}

TEST(DictionaryLookup, defaultsAreUsedOnlyWhenMissingAndRecorded) {
    const Dictionary d = Dictionary::parse(sample, "sample");
    EXPECT_EQ(d.getOrDefault<double>("rho0", 1.0), 2785.0);
    EXPECT_EQ(d.getOrDefault<double>("cv", 900.0), 900.0);
    EXPECT_EQ(d.subDict("eos").getOrDefault<int>("order", 2), 2);
    ASSERT_EQ(d.defaultsUsed().size(), 1u);
    EXPECT_EQ(d.defaultsUsed()[0], "cv");
    ASSERT_EQ(d.subDict("eos").defaultsUsed().size(), 1u);
    EXPECT_EQ(d.subDict("eos").defaultsUsed()[0], "eos/order");
    EXPECT_EQ(d.getOptional<int>("steps"), std::optional<int>(100));
    EXPECT_EQ(d.getOptional<int>("nothing"), std::nullopt);
}

TEST(DictionaryLookup, missingKeyNamesScopeAndSuggests) {
    const Dictionary d = Dictionary::parse(sample, "sample");
    try {
        d.subDict("eos").get<double>("c00");
        FAIL();
    } catch (const InputError& e) {
        const std::string m = e.what();
        EXPECT_NE(m.find("sample:11:1: in 'eos': missing keyword 'c00'; did you mean 'c0'?"),
                  std::string::npos)
            << m;
    }
}

TEST(DictionaryLookup, typeErrorsNameLocationAndExpectation) {
    const Dictionary d = Dictionary::parse(sample, "sample");
    const auto message = [&](auto get) {
        try {
            get();
        } catch (const InputError& e) {
            return std::string(e.what());
        }
        return std::string("no error");
    };
    EXPECT_EQ(message([&] { d.get<double>("name"); }),
              "sample:5:9: keyword 'name': expected a real number, found the word 'target'");
    EXPECT_EQ(message([&] { d.get<int>("nu"); }),
              "sample:3:9: keyword 'nu': expected an integer, found the real 0.33");
    EXPECT_EQ(message([&] { d.subDict("eos").get<int>("type"); }),
              "sample:13:10: in 'eos': keyword 'type': expected an integer, found the word 'mieGruneisen'");
    EXPECT_EQ(message([&] { d.get<std::vector<int>>("g"); }),
              "sample:8:9: keyword 'g': expected a list of integers (...), found the item '-9.81'");
    EXPECT_EQ(message([&] { d.get<double>("eos"); }),
              "sample:11:1: keyword 'eos': expected a real number, found a dictionary");
    EXPECT_EQ(
        message([&] { d.get<bool>("steps"); }),
        "sample:4:9: keyword 'steps': expected a switch (yes/no, on/off, true/false), found the integer 100");
    const Dictionary n = Dictionary::parse("neg -1; big 5000000000;", "n");
    EXPECT_EQ(message([&] { n.get<unsigned long>("neg"); }),
              "n:1:5: keyword 'neg': expected a non-negative integer, found the integer -1");
    EXPECT_EQ(message([&] { n.get<int>("big"); }),
              "n:1:13: keyword 'big': expected an integer, found the integer 5000000000 (out of range)");
    EXPECT_EQ(n.get<long long>("big"), 5000000000LL);
}

TEST(DictionaryTracking, unusedEntriesWithSuggestion) {
    const Dictionary d = Dictionary::parse(R"(
eos { type mieGruneisen; c0 5330; gama0 2.0; }
strength { type vonMises; }
extra 1;
)",
                                           "case");
    const Dictionary& eos = d.subDict("eos");
    eos.get<std::string>("type");
    eos.get<double>("c0");
    eos.getOrDefault<double>("gamma0", 1.5);
    d.subDict("strength").get<std::string>("type");
    const auto unused = d.unusedEntries();
    ASSERT_EQ(unused.size(), 2u);
    EXPECT_EQ(unused[0].scopedKey, "eos/gama0");
    EXPECT_EQ(unused[0].suggestion, "gamma0");
    EXPECT_EQ(unused[0].where.str(), "case:2:35");
    EXPECT_EQ(unused[1].scopedKey, "extra");
    EXPECT_EQ(unused[1].suggestion, "");
    d.markAllRead();
    EXPECT_TRUE(d.unusedEntries().empty());
}

TEST(DictionaryTracking, macroSourcesCountAsUsed) {
    const Dictionary d = Dictionary::parse("rho 1000; rho0 $rho;", "m");
    EXPECT_EQ(d.get<double>("rho0"), 1000.0);
    EXPECT_TRUE(d.unusedEntries().empty());
}

TEST(DictionaryEditing, setThenPrintRoundTrips) {
    Dictionary d = Dictionary::parse("a 1;\nsub { x 2; }\n", "edit");
    d.set("a", "(1 2 3)");
    d.subDict("sub");
    d.addDict("sub").set("y", "\"text with \\\"quotes\\\"\"");
    d.addDict("new").set("z", "$a");
    d.set("b", "{ p 1; q (2 3); }");
    EXPECT_TRUE(d.remove("nothing") == false);
    const std::string expected =
        "a (1 2 3);\n"
        "sub\n{\n    x 2;\n    y \"text with \\\"quotes\\\"\";\n}\n"
        "new\n{\n    z (1 2 3);\n}\n"
        "b\n{\n    p 1;\n    q (2 3);\n}\n";
    EXPECT_EQ(d.str(), expected);
    const Dictionary back = Dictionary::parse(d.str(), "back");
    EXPECT_EQ(back.str(), expected);
    EXPECT_EQ(back.subDict("sub").get<std::string>("y"), "text with \"quotes\"");
    EXPECT_TRUE(d.remove("a"));
    EXPECT_FALSE(d.found("a"));
    EXPECT_EQ(d.keys(), (std::vector<std::string>{"sub", "new", "b"}));
    EXPECT_THROW(d.set("c", "1 2 )"), InputError);
}

TEST(DictionaryEditing, realsPrintAsReals) {
    Token t;
    t.kind = Token::Kind::real;
    t.real = 2.0;
    EXPECT_EQ(t.str(), "2.0");
    t.real = 1.5e-7;
    EXPECT_EQ(t.str(), "1.5e-07");
    t.kind = Token::Kind::integer;
    t.integer = -3;
    EXPECT_EQ(t.str(), "-3");
}

TEST(DictionaryOffsets, valueSpansAndBraces) {
    const std::string text = "a  1 2 ; // c\nsub\n{\n    x (3);\n}\n";
    const Dictionary d = Dictionary::parse(text, "o");
    const Entry& a = *d.peek("a");
    EXPECT_EQ(text.substr(a.valueBegin, a.valueEnd - a.valueBegin), "1 2");
    const Entry& sub = *d.peek("sub");
    EXPECT_EQ(text.substr(sub.valueBegin, sub.valueEnd - sub.valueBegin), "\n    x (3);\n");
    EXPECT_EQ(text[sub.dict->closeBraceOffset], '}');
    EXPECT_EQ(d.closeBraceOffset, text.size());
    const Entry& x = *sub.dict->peek("x");
    EXPECT_EQ(text.substr(x.valueBegin, x.valueEnd - x.valueBegin), "(3)");
    EXPECT_EQ(x.where.str(), "o:4:5");
    EXPECT_EQ(x.tokens[0].where.str(), "o:4:7");
    EXPECT_EQ(x.tokens[0].list[0].where.str(), "o:4:8");
}

TEST(DictionaryInclude, includeEtcFromTemporaryDirectory) {
    const fs::path etc = fs::temp_directory_path() / ("mfdynEtc" + std::to_string(::getpid()));
    fs::create_directories(etc / "materials");
    std::ofstream(etc / "materials" / "steel") << "rho0 7850;\nE 200e9;\n";
    ReadOptions options;
    options.etcDirectories = {etc / "missing", etc};
    const Dictionary d =
        Dictionary::parse("steel { #includeEtc \"materials/steel\"\n E 210e9; }\n", "case", options);
    EXPECT_EQ(d.subDict("steel").get<double>("rho0"), 7850.0);
    EXPECT_EQ(d.subDict("steel").get<double>("E"), 210e9);
    EXPECT_TRUE(d.subDict("steel").peek("rho0")->fromInclude);
    EXPECT_FALSE(d.subDict("steel").peek("E")->fromInclude);
    EXPECT_EQ(d.subDict("steel").peek("rho0")->where.str(), (etc / "materials" / "steel").string() + ":1:1");

    // Without explicit directories, $MFDYN_ETC comes first.
    ::setenv("MFDYN_ETC", (etc.string() + ":/nonexistent").c_str(), 1);
    const auto dirs = etcDirectories();
    ASSERT_GE(dirs.size(), 2u);
    EXPECT_EQ(dirs[0], etc);
    EXPECT_EQ(dirs[1], fs::path("/nonexistent"));
    EXPECT_EQ(Dictionary::parse("#includeEtc \"materials/steel\"", "case").get<double>("rho0"), 7850.0);
    ::unsetenv("MFDYN_ETC");
    fs::remove_all(etc);
}

TEST(DictionaryCopy, isDeepAndRepointsParents) {
    auto original =
        std::make_unique<Dictionary>(Dictionary::parse("top 1; a { b { c 2; } l ({ x 1; }); }", "copy"));
    Dictionary copy = *original;
    original->subDict("a").subDict("b");  // reading the original does not mark the copy
    original.reset();
    const Dictionary& b = copy.subDict("a").subDict("b");
    EXPECT_EQ(b.get<int>("c"), 2);
    EXPECT_EQ(b.parent(), &copy.subDict("a"));
    EXPECT_EQ(&b.topLevel(), &copy);
    EXPECT_EQ(b.scope(), "a/b");
    const Entry& l = copy.subDict("a").entry("l");
    ASSERT_TRUE(l.tokens[0].list[0].dict);
    EXPECT_EQ(l.tokens[0].list[0].dict->parent(), &copy.subDict("a"));

    Dictionary assigned;
    assigned = copy;
    copy.set("top", "5");
    EXPECT_EQ(assigned.get<int>("top"), 1);
    EXPECT_EQ(assigned.subDict("a").parent(), &assigned);

    Dictionary moved = std::move(assigned);
    EXPECT_EQ(moved.subDict("a").parent(), &moved);
    EXPECT_EQ(moved.subDict("a").subDict("b").get<int>("c"), 2);
}

TEST(DictionaryScoped, findScopedBothSeparators) {
    const Dictionary d = Dictionary::parse("a { b { c 3; } } x.y 4;", "s");
    ASSERT_NE(d.findScoped("a/b/c"), nullptr);
    EXPECT_EQ(d.findScoped("a.b.c")->tokens[0].integer, 3);
    EXPECT_EQ(d.findScoped("x.y")->tokens[0].integer, 4);
    EXPECT_EQ(d.findScoped("a/b/d"), nullptr);
    EXPECT_EQ(d.findScoped("a/q/c"), nullptr);
}

TEST(DictionarySuggestions, editDistanceAndClosestMatch) {
    EXPECT_EQ(editDistance("kitten", "sitting"), 3u);
    EXPECT_EQ(editDistance("", "abc"), 3u);
    EXPECT_EQ(editDistance("same", "same"), 0u);
    const std::vector<std::string> types{"mieGruneisen", "idealGas", "tait"};
    EXPECT_EQ(closestMatch("mieGrunesen", types), "mieGruneisen");
    EXPECT_EQ(closestMatch("tiat", types), "tait");  // 2 edits allowed for short words
    EXPECT_EQ(closestMatch("linear", types), "");
    // 12 letters allow 4 edits, not 5.
    EXPECT_EQ(closestMatch("mieXXXXeisen", types), "mieGruneisen");
    EXPECT_EQ(closestMatch("mieXXXXXisen", types), "");
}

TEST(DictionaryPerformance, parsesOneMegabyteQuickly) {
    std::string text;
    for (int i = 0; text.size() < (1u << 20); ++i) {
        text += "block" + std::to_string(i) + "\n{\n    rho0 " + std::to_string(1000 + i) +
                ";  // density\n    g (0 -9.81 1.5e-3);\n    name \"region " + std::to_string(i) +
                "\";\n    type mieGruneisen;\n}\n";
    }
    const auto start = std::chrono::steady_clock::now();
    const Dictionary d = Dictionary::parse(text, "big");
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    EXPECT_EQ(d.subDict("block7").get<int>("rho0"), 1007);
    std::cout << "parsed " << text.size() << " bytes in " << seconds << " s\n";
    // "Well under a second" in Release; the bound leaves room for a loaded machine or a debug build.
    EXPECT_LT(seconds, 3.0);
}

}  // namespace

namespace {

TEST(DictionaryLimits, deepNestingIsAnErrorNotACrash) {
    const std::string deep = "a " + std::string(100000, '(') + ";";
    try {
        Dictionary::parse(deep, "deep");
        FAIL();
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("deep:1:202: nesting deeper than 200 levels"), std::string::npos)
            << e.what();
    }
    const std::string fine = "a " + std::string(150, '(') + std::string(150, ')') + ";";
    EXPECT_EQ(Dictionary::parse(fine, "fine").entry("a").tokens.size(), 1u);
}

}  // namespace
