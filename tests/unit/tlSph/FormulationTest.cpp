// The formulation family: every type declares its (empty) keyword schema and evolves the fields
// its name says (Lee et al. 2016 eqs. 1, 6, 34).
#include "core/Dictionary.hpp"
#include "core/Registry.hpp"
#include "tlSph/DisplacementFormulation.hpp"
#include "tlSph/MixedFormulation.hpp"

#include <gtest/gtest.h>

#include <string>

using namespace mfdyn;

TEST(FormulationContract, EveryTypeDeclaresASchemaAndEvolvesWhatItsNameSays) {
    EXPECT_TRUE(DisplacementFormulation::keywords().empty());
    const RegistryFamily* family = RegistryIndex::global().findFamily(Formulation::familyName);
    ASSERT_NE(family, nullptr);
    struct Expected {
        const char* type;
        bool F, H, J;
    };
    for (const Expected& e :
         {Expected{"pF", true, false, false}, Expected{"pFJ", true, false, true},
          Expected{"pFHJ", true, true, true}, Expected{"displacement", false, false, false}}) {
        const RegistryItem* item = family->find(e.type);
        ASSERT_NE(item, nullptr) << e.type;
        ASSERT_NE(item->keywords, nullptr) << e.type;
        EXPECT_EQ(item->keywords().type(), e.type);
        const auto f =
            Formulation::New(Dictionary::parse(std::string("type ") + e.type + ";", "formulation"));
        EXPECT_EQ(f->name(), e.type);
        EXPECT_EQ(f->evolvesF(), e.F) << e.type;
        EXPECT_EQ(f->evolvesH(), e.H) << e.type;
        EXPECT_EQ(f->evolvesJ(), e.J) << e.type;
        EXPECT_EQ(f->displacementBased(), !e.F) << e.type;
    }
}
