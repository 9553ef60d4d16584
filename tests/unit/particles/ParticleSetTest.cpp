#include "particles/ParticleSet.hpp"

#include <gtest/gtest.h>

using namespace mfdyn;

namespace {

std::vector<std::string> names(const FieldStore& store) {
    return store.fieldNames();
}

}  // namespace

TEST(ParticleSet, StartsWithOnlyPositionGlobalIdAndRegion) {
    ParticleSet<3> particles(10);
    EXPECT_EQ(names(particles), (std::vector<std::string>{"position", "globalId", "region"}));
    EXPECT_EQ(particles.size(), 10u);
    EXPECT_EQ(particles.dimension(), 3);
    // 3 doubles of position + two int64.
    EXPECT_EQ(particles.bytesPerParticle(), 24u + 8u + 8u);
}

TEST(ParticleSet, FieldsAreCreatedOnFirstRequestOnly) {
    ParticleSet<2> particles(5);
    EXPECT_FALSE(particles.hasField("rho"));
    EXPECT_EQ(particles.findField<double>("rho"), nullptr);
    EXPECT_THROW(particles.requireField<double>("rho"), Error);
    EXPECT_FALSE(particles.hasField("rho")) << "look-ups that do not create must not create";

    std::vector<double>& rho = particles.scalarField("rho");
    EXPECT_TRUE(particles.hasField("rho"));
    ASSERT_EQ(rho.size(), 5u);
    for (double r : rho) EXPECT_EQ(r, 0.0);
    rho[3] = 7.0;
    // A second request returns the same storage.
    EXPECT_EQ(&particles.field<double>("rho"), &rho);
    EXPECT_EQ(particles.requireField<double>("rho")[3], 7.0);
    EXPECT_EQ(particles.fieldNames().size(), 4u);
}

TEST(ParticleSet, BytesPerParticleFollowFieldKinds) {
    // 2D: vector 2, tensor 4, symmTensor 3 doubles; position 2 doubles, ids 2 int64.
    ParticleSet<2> p2;
    const std::size_t base2 = 16 + 16;
    EXPECT_EQ(p2.bytesPerParticle(), base2);
    p2.vectorField("velocity");
    p2.tensorField("F");
    p2.symmTensorField("sigma");
    p2.integerField("material");
    p2.scalarField("p");
    EXPECT_EQ(p2.bytesPerParticle(), base2 + 16 + 32 + 24 + 8 + 8);

    ParticleSet<1> p1;
    p1.tensorField("F");
    EXPECT_EQ(p1.field("F").kind(), FieldKind::tensor)
        << "1D tensors keep their kind though the type is a vector's";
    EXPECT_EQ(p1.bytesPerParticle(), 8u + 16u + 8u);

    ParticleSet<3> p3;
    p3.tensorField("F");
    p3.symmTensorField("sigma");
    EXPECT_EQ(p3.bytesPerParticle(), 40u + 72u + 48u);
    EXPECT_NE(p3.fieldSummary().find("symmTensor"), std::string::npos);
    EXPECT_NE(p3.fieldSummary().find("sigma"), std::string::npos);
}

TEST(ParticleSet, TypeClashNamesBothTypes) {
    ParticleSet<3> particles(2);
    particles.vectorField("velocity");
    try {
        particles.field<double>("velocity");
        FAIL() << "expected a type clash";
    } catch (const Error& e) {
        const std::string what = e.what();
        EXPECT_NE(what.find("velocity"), std::string::npos) << what;
        EXPECT_NE(what.find("vector<3>"), std::string::npos) << what;
        EXPECT_NE(what.find("scalar"), std::string::npos) << what;
    }
    EXPECT_THROW(particles.field<std::int64_t>("position"), Error);
    EXPECT_THROW(particles.findField<SymmTensor<3>>("velocity"), Error);
    // A type of another dimension is refused even for a new field.
    EXPECT_THROW(particles.field<Vector<2>>("u"), Error);
}

TEST(ParticleSet, ResizeResizesEveryField) {
    ParticleSet<3> particles(3);
    particles.scalarField("rho");
    particles.symmTensorField("sigma");
    particles.resize(8);
    for (const auto& f : particles.fields()) EXPECT_EQ(f->size(), 8u) << f->name();
    EXPECT_EQ(particles.size(), 8u);
    // Fields made after a resize have the new size.
    EXPECT_EQ(particles.scalarField("e").size(), 8u);
}

TEST(ParticleSet, TypeErasedViewMatchesTypedData) {
    ParticleSet<2> particles(2);
    auto& F = particles.tensorField("F");
    F[1] << 1, 2, 3, 4;  // rows (1 2) (3 4)
    const FieldBase& f = particles.field("F");
    EXPECT_EQ(f.components(), 4);
    EXPECT_EQ(f.elementBytes(), 32u);
    // Memory order is Eigen's column-major: xx, yx, xy, yy.
    EXPECT_EQ(componentNames(FieldKind::tensor, 2), (std::vector<std::string>{"xx", "yx", "xy", "yy"}));
    EXPECT_EQ(f.component(1, 0), 1.0);
    EXPECT_EQ(f.component(1, 1), 3.0);
    EXPECT_EQ(f.component(1, 2), 2.0);
    EXPECT_EQ(f.data(), static_cast<const void*>(F.data()));
}

TEST(ParticleSet, WithDimensionDispatchesAndRejectsOthers) {
    for (int dim = 1; dim <= 3; ++dim) {
        std::unique_ptr<ParticleSetBase> base =
            withDimension(dim, [](auto d) -> std::unique_ptr<ParticleSetBase> {
                return std::make_unique<ParticleSet<decltype(d)::value>>(4);
            });
        EXPECT_EQ(base->dimension(), dim);
        EXPECT_EQ(base->field("position").components(), dim);
        int seen = withDimension(dim, [&](auto d) {
            constexpr int Dim = decltype(d)::value;
            return int(particleSetCast<Dim>(*base).position().size()) * 10 + Dim;
        });
        EXPECT_EQ(seen, 40 + dim);
    }
    EXPECT_THROW(withDimension(4, [](auto) { return 0; }), InputError);
    EXPECT_THROW(withDimension(0, [](auto) { return 0; }), InputError);
    ParticleSet<2> p;
    EXPECT_THROW(particleSetCast<3>(p), Error);
}

TEST(ParticleSet, CloneIsDeepAndReorderPermutesAllFields) {
    ParticleSet<3> particles(3);
    auto& rho = particles.scalarField("rho");
    rho = {1, 2, 3};
    particles.globalId() = {10, 11, 12};
    auto copy = particles.clone();
    rho[0] = 99;
    EXPECT_EQ(copy->requireField<double>("rho")[0], 1.0);

    particles.reorder({2, 0, 1});
    EXPECT_EQ(rho, (std::vector<double>{3, 99, 2}));
    EXPECT_EQ(particles.globalId(), (std::vector<std::int64_t>{12, 10, 11}));
}

TEST(ParticleSet, RegionCounts) {
    ParticleSet<1> particles(5);
    particles.regionNames = {"projectile", "target"};
    particles.region() = {0, 1, 1, 1, 0};
    EXPECT_EQ(particles.regionCounts(), (std::vector<std::size_t>{2, 3}));
}
