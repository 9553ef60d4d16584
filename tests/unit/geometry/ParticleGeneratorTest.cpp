// ParticleGenerator features: equal-mass regions, rigid rotation, materials.
#include "geometry/ParticleGenerator.hpp"
#include "particles/ParticleSet.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>

using namespace mfdyn;

namespace {

// A light and a dense plate side by side, density ratio 4, both asked for spacing 0.01.
std::string twoPlates(const std::string& massMode) {
    return "dimension 2; regions {"
           " light { shape { type box; min (0 0); max (0.1 0.1); } lattice { type cubic; spacing 0.01; }"
           "         density 1000; " +
           massMode +
           " }"
           " dense { shape { type box; min (0.1 0); max (0.2 0.1); } lattice { type cubic; spacing 0.01; }"
           "         density 4000; " +
           massMode + " } }";
}

}  // namespace

TEST(ParticleGenerator, UniformSpacingIsTheDefault) {
    const auto dict = Dictionary::parse(twoPlates(""), "test");
    ParticleGenerator gen(dict);
    const auto set = gen.generate();
    const auto& rep = gen.report();
    ASSERT_EQ(rep.size(), 2u);
    EXPECT_EQ(rep[0].count, 100u);
    EXPECT_EQ(rep[1].count, 100u);
    // m = ρ Δx²: 0.1 and 0.4 kg per metre of depth.
    EXPECT_NEAR(rep[0].mass / 100, 1000 * 1e-4, 1e-12);
    EXPECT_NEAR(rep[1].mass / 100, 4000 * 1e-4, 1e-12);
}

TEST(ParticleGenerator, EqualMassRefinesTheDenseRegion) {
    const auto dict = Dictionary::parse(twoPlates("mass equalMass;"), "test");
    ParticleGenerator gen(dict);
    const auto set = gen.generate();
    auto& p = particleSetCast<2>(*set);
    const auto& mass = p.scalarField("mass");
    // The light plate sets the mass, ρ_L Δx² = 0.1; the dense one has spacing Δx (1/4)^(1/2).
    for (double m : mass) EXPECT_NEAR(m, 0.1, 1e-12);
    const auto& rep = gen.report();
    EXPECT_NEAR(rep[1].spacing, 0.005, 1e-15);
    EXPECT_EQ(rep[0].count, 100u);
    EXPECT_EQ(rep[1].count, 400u);
    // Both plates hold their exact mass: the boxes are whole numbers of cells.
    EXPECT_NEAR(rep[0].mass, 1000 * 0.01, 1e-9);
    EXPECT_NEAR(rep[1].mass, 4000 * 0.01, 1e-9);
}

TEST(ParticleGenerator, MassModeIsChecked) {
    const auto dict = Dictionary::parse(twoPlates("mass sameMass;"), "test");
    ParticleGenerator gen(dict);
    EXPECT_THROW(gen.generate(), InputError);
}

TEST(ParticleGenerator, AngularVelocityAddsRigidRotation) {
    const auto dict = Dictionary::parse(
        "dimension 3; regions { ball { shape { type sphere; centre (1 0 0); radius 0.1; }"
        " lattice { type cubic; spacing 0.02; } density 1000; fields { velocity (5 0 0); }"
        " angularVelocity { omega (0 0 10); centre (1 0 0); } } }",
        "test");
    ParticleGenerator gen(dict);
    auto set = gen.generate();
    auto& p = particleSetCast<3>(*set);
    const auto& x = p.position();
    const auto& v = p.vectorField("velocity");
    ASSERT_GT(p.size(), 100u);
    double largest = 0;
    for (std::size_t i = 0; i < p.size(); ++i) {
        // ω × (x − c) with ω = 10 ẑ: (−10 y, 10 (x − 1), 0), on top of the uniform 5 x̂.
        EXPECT_NEAR(v[i][0], 5 - 10 * x[i][1], 1e-12);
        EXPECT_NEAR(v[i][1], 10 * (x[i][0] - 1), 1e-12);
        EXPECT_NEAR(v[i][2], 0, 1e-12);
        largest = std::max(largest, std::abs(v[i][1]));
    }
    EXPECT_GT(largest, 0.5);  // the rim moves at about ωR = 1 m/s
}

TEST(ParticleGenerator, AngularVelocityIn2DIsAboutZ) {
    const auto dict = Dictionary::parse(
        "dimension 2; regions { disc { shape { type sphere; centre (0 0); radius 1; }"
        " lattice { type hexagonal; spacing 0.1; } density 1;"
        " angularVelocity { omega 2; } } }",
        "test");
    ParticleGenerator gen(dict);
    auto set = gen.generate();
    auto& p = particleSetCast<2>(*set);
    const auto& v = p.vectorField("velocity");
    for (std::size_t i = 0; i < p.size(); ++i) {
        EXPECT_NEAR(v[i][0], -2 * p.position()[i][1], 1e-12);
        EXPECT_NEAR(v[i][1], 2 * p.position()[i][0], 1e-12);
    }
}

TEST(ParticleGenerator, MaterialsAreCheckedAgainstMaterialProperties) {
    const auto root = std::filesystem::temp_directory_path() / "mfdynGeometryTestMaterialCase";
    std::filesystem::remove_all(root);
    std::filesystem::create_directories(root / "system");
    std::filesystem::create_directories(root / "constant");
    std::ofstream(root / "constant" / "materialProperties")
        << "materials { aluminium { rho0 2700; } epoxy { rho0 1200; } }\n";
    const auto write = [&](const std::string& second) {
        std::ofstream(root / "system" / "particleGenDict")
            << "dimension 1; regions {"
               " a { shape { type box; min (0); max (1); } lattice { type cubic; spacing 0.1; } density 2700;"
               " material aluminium; }"
               " b { shape { type box; min (1); max (2); } lattice { type cubic; spacing 0.1; } density 1200;"
               " material "
            << second << "; } }\n";
        return Dictionary::read(root / "system" / "particleGenDict");
    };
    {
        const Dictionary dict = write("epoxy");
        ParticleGenerator gen(dict);
        auto set = gen.generate();
        auto& p = particleSetCast<1>(*set);
        ASSERT_EQ(p.materialNames, (std::vector<std::string>{"aluminium", "epoxy"}));
        const auto& material = p.integerField("material");
        const auto& region = p.region();
        for (std::size_t i = 0; i < p.size(); ++i) EXPECT_EQ(material[i], region[i]);
    }
    {
        const Dictionary dict = write("epoxi");
        ParticleGenerator gen(dict);
        try {
            gen.generate();
            FAIL() << "an unknown material was accepted";
        } catch (const InputError& e) {
            const std::string message = e.what();
            EXPECT_NE(message.find("epoxi"), std::string::npos) << message;
            EXPECT_NE(message.find("aluminium epoxy"), std::string::npos) << message;
        }
    }
    std::filesystem::remove_all(root);
}

TEST(ParticleGenerator, MaterialOnSomeRegionsOnlyIsAnError) {
    const auto dict = Dictionary::parse(
        twoPlates("").replace(twoPlates("").find("density 1000;"), 13, "density 1000; material steel;"),
        "test");
    ParticleGenerator gen(dict);
    EXPECT_THROW(gen.generate(), InputError);
}
