// tlSphProperties through a keyword schema (issue 15 item 5): every keyword the solver reads is
// declared (so -describe and doc/models know it), with the defaults the solver always had, and
// every keyword a tutorial writes is one of them.
#include "core/Dictionary.hpp"
#include "core/KeywordSchema.hpp"
#include "tlSph/TlSphSolver.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <set>

using namespace mfdyn;

TEST(SolverKeywords, everyKeywordIsDeclaredWithTheDefaultsTheSolverAlwaysHad) {
    const KeywordSchema schema = TlSphSolver<3>::keywords();
    EXPECT_EQ(schema.family(), "solver");
    EXPECT_EQ(schema.type(), "tlSph");
    const auto defaultOf = [&](const char* name) {
        const Keyword* k = schema.find(name);
        return k ? k->kindText() : std::string("undeclared");
    };
    EXPECT_EQ(defaultOf("smoothingLengthRatio"), "default 1.3");
    EXPECT_EQ(defaultOf("waveSpeed"), "default current");
    EXPECT_EQ(defaultOf("mirrorGhosts"), "default yes");
    EXPECT_EQ(defaultOf("essentialBoundaryConditions"), "default direct");
    for (const char* name : {"spacing", "gradient", "projection", "bodyForce", "initialState"})
        EXPECT_EQ(defaultOf(name), "optional") << name;
    for (const char* name : {"kernel", "dissipation", "formulation"})
        EXPECT_EQ(defaultOf(name), "required") << name;
    ASSERT_NE(schema.find("projection"), nullptr);
    ASSERT_NE(schema.find("projection")->nested, nullptr);
    const KeywordSchema projection = schema.find("projection")->nested();
    for (const char* name : {"momentum", "dissipation", "jacobian"}) {
        ASSERT_NE(projection.find(name), nullptr) << name;
        EXPECT_EQ(projection.find(name)->kindText(), "default yes") << name;
    }
    // The moved keywords are not declared: they are refused at their lines (tlSph.keywords).
    EXPECT_EQ(schema.find("alphaCFL"), nullptr);
    EXPECT_EQ(schema.find("gravity"), nullptr);
}

TEST(SolverKeywords, everyTutorialWritesOnlyDeclaredKeywords) {
    const KeywordSchema schema = TlSphSolver<3>::keywords();
    const KeywordSchema projection = TlSphSolver<3>::projectionKeywords();
    std::size_t files = 0;
    for (const auto& entry : std::filesystem::directory_iterator(MFDYN_TUTORIALS_DIR)) {
        const auto path = entry.path() / "constant" / "tlSphProperties";
        if (!std::filesystem::exists(path)) continue;
        ++files;
        const Dictionary dict = Dictionary::read(path);
        for (const auto& key : dict.keys()) {
            if (key == "FoamFile") continue;
            EXPECT_NE(schema.find(key), nullptr) << path << ": " << key;
        }
        if (const Dictionary* p = dict.findDict("projection"))
            for (const auto& key : p->keys())
                EXPECT_NE(projection.find(key), nullptr) << path << ": projection/" << key;
    }
    EXPECT_GE(files, 11u);  // the eleven tutorials of tutorials/tlSph
}

// The formulation is a word of tlSphProperties (a solver option: it selects the conservation laws
// the solver integrates, Lee et al. 2016 eqs. 1, 6, 34), each evolving what its name says.
TEST(SolverKeywords, theFormulationIsAWordAndEvolvesWhatItsNameSays) {
    const KeywordSchema schema = TlSphSolver<3>::keywords();
    const Keyword* k = schema.find("formulation");
    ASSERT_NE(k, nullptr);
    EXPECT_EQ(k->type, Keyword::Type::word);
    EXPECT_EQ(k->words, (std::vector<std::string>{"pF", "pFJ", "pFHJ", "displacement"}));
    struct Expected {
        const char* name;
        bool F, H, J;
    };
    for (const Expected& e :
         {Expected{"pF", true, false, false}, Expected{"pFJ", true, false, true},
          Expected{"pFHJ", true, true, true}, Expected{"displacement", false, false, false}}) {
        const auto f = TlSphSolver<3>::formulationNamed(e.name);
        EXPECT_EQ(f.name(), e.name);
        EXPECT_EQ(f.evolvesF(), e.F) << e.name;
        EXPECT_EQ(f.evolvesH(), e.H) << e.name;
        EXPECT_EQ(f.evolvesJ(), e.J) << e.name;
        EXPECT_EQ(f.displacementBased(), !e.F) << e.name;
    }
}
