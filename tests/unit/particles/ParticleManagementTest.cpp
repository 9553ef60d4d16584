// Particles that come and go (issue 15): append and keep on the particle set, global ids that are
// never reused (within a run and across a restart through the particle file), the owned/ghost
// range, and the topology version that tells a Verlet list to rebuild.
#include "TestFiles.hpp"
#include "particles/ParticleSet.hpp"
#include "particles/VerletList.hpp"
#include "particles/VtpReader.hpp"
#include "particles/VtpWriter.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>

using namespace mfdyn;
using mfdyn::test::readFile;
using mfdyn::test::ScratchDir;

namespace {

// n particles on a line, ids 10, 11, ... (not 0..n-1, so that an id taken from an index would
// show), a scalar `rho`, a vector `velocity`, a symmetric `tau` and an integer `material`, all
// distinct per particle and not round in binary.
ParticleSet<2> sample(std::size_t n) {
    ParticleSet<2> p(n);
    p.regionNames = {"body", "wall"};
    auto& rho = p.scalarField("rho");
    auto& v = p.vectorField("velocity");
    auto& tau = p.symmTensorField("tau");
    auto& material = p.integerField("material");
    for (std::size_t i = 0; i < n; ++i) {
        p.position()[i] = Vector<2>(0.1 * double(i), std::sin(double(i)));
        p.globalId()[i] = std::int64_t(10 + i);
        p.region()[i] = std::int64_t(i % 2);
        rho[i] = 1000.0 / 3.0 + double(i) / 7.0;
        v[i] = Vector<2>(std::exp(-double(i)), -1.0 / (1.0 + double(i)));
        tau[i](0, 0) = 1e-300 * double(i);  // subnormal-adjacent values must survive too
        tau[i](1, 1) = std::sqrt(2.0 + double(i));
        tau[i](0, 1) = -std::cbrt(double(i) + 0.5);
        material[i] = std::int64_t(3 * i);
    }
    return p;
}

bool sameBits(const FieldBase& a, const FieldBase& b) {
    return a.size() == b.size() && a.kind() == b.kind() &&
           std::memcmp(a.data(), b.data(), a.size() * a.elementBytes()) == 0;
}

std::int64_t maxId(const ParticleSetBase& p) {
    const auto& id = p.requireField<std::int64_t>("globalId");
    return id.empty() ? -1 : *std::max_element(id.begin(), id.end());
}

}  // namespace

TEST(ParticleManagement, AppendExtendsEveryFieldWithZerosAndIssuesNewIds) {
    ParticleSet<2> p = sample(5);
    const ParticleSet<2> before = p;
    const auto version = p.topologyVersion();

    EXPECT_EQ(p.append(3), 5u) << "the first new particle's index";
    ASSERT_EQ(p.size(), 8u);
    EXPECT_NE(p.topologyVersion(), version) << "an append must be visible to index lists";
    for (const auto& f : p.fields()) {
        ASSERT_EQ(f->size(), 8u) << f->name();
        // The old particles unchanged, bit for bit.
        EXPECT_EQ(std::memcmp(f->data(), before.field(f->name()).data(), 5 * f->elementBytes()), 0)
            << f->name();
    }
    // New ids follow the largest (14), whatever the indices; every other field starts at zero.
    EXPECT_EQ(p.globalId()[5], 15);
    EXPECT_EQ(p.globalId()[6], 16);
    EXPECT_EQ(p.globalId()[7], 17);
    for (std::size_t i = 5; i < 8; ++i) {
        EXPECT_EQ(p.region()[i], 0);
        EXPECT_EQ(p.scalarField("rho")[i], 0.0);
        EXPECT_EQ(p.vectorField("velocity")[i], Vector<2>::Zero());
        EXPECT_EQ(p.integerField("material")[i], 0);
    }
    // A field made after the append has the new size, zero-filled.
    EXPECT_EQ(p.scalarField("later"), std::vector<double>(8, 0.0));
    EXPECT_EQ(p.nextGlobalId(), 18);
}

TEST(ParticleManagement, KeepCompactsEveryFieldInOrderWithoutReallocating) {
    ParticleSet<2> p = sample(10);
    const ParticleSet<2> before = p;
    const double* rhoData = p.scalarField("rho").data();
    const std::vector<std::size_t> kept = {1, 4, 5, 9};

    p.keep(kept);
    ASSERT_EQ(p.size(), 4u);
    EXPECT_EQ(p.scalarField("rho").data(), rhoData) << "compacted in place, not reallocated";
    for (const auto& f : p.fields()) {
        ASSERT_EQ(f->size(), 4u) << f->name();
        const FieldBase& old = before.field(f->name());
        for (std::size_t k = 0; k < kept.size(); ++k)
            for (int c = 0; c < f->components(); ++c)
                EXPECT_EQ(f->component(k, c), old.component(kept[k], c)) << f->name() << " particle " << k;
    }
    EXPECT_EQ(p.globalId(), (std::vector<std::int64_t>{11, 14, 15, 19}));
}

TEST(ParticleManagement, KeepRefusesABadIndexListAndChangesNothing) {
    ParticleSet<2> p = sample(6);
    const ParticleSet<2> before = p;
    const auto version = p.topologyVersion();
    auto message = [&](const std::vector<std::size_t>& indices) {
        try {
            p.keep(indices);
        } catch (const Error& e) {
            return std::string(e.what());
        }
        return std::string();
    };
    EXPECT_NE(message({0, 6}).find("index 6 of a set of 6"), std::string::npos);
    EXPECT_NE(message({3, 1}).find("strictly ascending (3 then 1"), std::string::npos);
    EXPECT_NE(message({2, 2}).find("strictly ascending"), std::string::npos)
        << "a duplicate would clone a particle";
    // Checked before anything moved.
    EXPECT_EQ(p.size(), 6u);
    EXPECT_EQ(p.topologyVersion(), version);
    for (const auto& f : p.fields()) EXPECT_TRUE(sameBits(*f, before.field(f->name()))) << f->name();
}

TEST(ParticleManagement, IdsAreNeverReusedAfterTheHighestIsRemoved) {
    ParticleSet<2> p = sample(4);  // ids 10..13
    std::vector<std::int64_t> issued(p.globalId().begin(), p.globalId().end());
    // Remove the particle of the highest id: max id + 1 would hand 13 out again.
    p.keep({0, 1, 2});
    EXPECT_EQ(p.nextGlobalId(), 14);
    p.append(1);
    EXPECT_EQ(p.globalId().back(), 14);
    // Remove everything, then append: still above every id ever held.
    const std::int64_t highest = 14;
    p.keep({});
    EXPECT_EQ(p.size(), 0u);
    p.append(2);
    EXPECT_GT(p.globalId()[0], highest);
    EXPECT_EQ(p.globalId()[0], 15);
    EXPECT_EQ(p.globalId()[1], 16);
    // A smaller set by resize (what a solver's own ghost scheme does) forgets no id either.
    p.resize(1);
    p.append(1);
    EXPECT_EQ(p.globalId()[1], 17);
    (void)issued;
}

TEST(ParticleManagement, AppendAndKeepSurviveARestartBitForBitWithTheNextId) {
    ScratchDir dir("management");
    ParticleSet<2> p = sample(7);  // ids 10..16
    p.append(2);                   // ids 17, 18
    p.scalarField("rho")[7] = 0.1;
    p.scalarField("rho")[8] = std::nextafter(0.2, 1.0);
    p.keep({0, 2, 3, 5, 7});  // drops 18, the highest id
    ASSERT_EQ(p.nextGlobalId(), 19);
    ASSERT_EQ(maxId(p), 17);

    const auto file = dir.path() / "particles.vtp";
    writeVtp(file, p, 0.25);
    EXPECT_NE(readFile(file).find("Name=\"nextGlobalId\""), std::string::npos)
        << "the ids alone say 18: the file must carry 19";
    ParticleFile read = readVtp(file);
    auto& back = particleSetCast<2>(*read.particles);
    ASSERT_EQ(back.size(), p.size());
    ASSERT_EQ(back.fieldNames(), p.fieldNames());
    for (const auto& f : p.fields()) EXPECT_TRUE(sameBits(*f, back.field(f->name()))) << f->name();
    EXPECT_EQ(back.nextGlobalId(), 19) << "the next id is part of the restart state";

    // The restarted run goes on exactly as the one that was not interrupted.
    p.append(1);
    back.append(1);
    EXPECT_EQ(back.globalId().back(), 19);
    EXPECT_EQ(back.globalId(), p.globalId());
}

TEST(ParticleManagement, FilesOfRunsThatRemoveNothingCarryNoNextId) {
    ScratchDir dir("managementPlain");
    ParticleSet<2> p = sample(3);
    p.append(2);  // ids 10..14: the next id, 15, follows from them
    const auto file = dir.path() / "particles.vtp";
    writeVtp(file, p, 0.0);
    EXPECT_EQ(readFile(file).find("nextGlobalId"), std::string::npos);
    EXPECT_EQ(readVtp(file).particles->nextGlobalId(), 15);
}

TEST(ParticleManagement, ANextIdBeyondWhatTheReaderCanTrustIsAnInputErrorNamingTheFile) {
    ScratchDir dir("managementBadId");
    ParticleSet<2> p = sample(2);
    // Beyond 2^53 consecutive ids are no longer distinct doubles (FieldBase::component).
    p.reserveGlobalIdsBelow(std::int64_t(1) << 60);
    const auto file = dir.path() / "particles.vtp";
    writeVtp(file, p, 0.0);
    try {
        readVtp(file);
        FAIL() << "accepted nextGlobalId 2^60";
    } catch (const InputError& e) {
        const std::string what = e.what();
        EXPECT_NE(what.find(file.string()), std::string::npos) << what;
        EXPECT_NE(what.find("nextGlobalId is 1.15292150460684"), std::string::npos) << what;
        EXPECT_NE(what.find("not a whole number from 0 to 2^53"), std::string::npos) << what;
    }
}

TEST(ParticleManagement, GhostsFollowTheOwnedParticlesAndAreNeverWritten) {
    ScratchDir dir("managementGhosts");
    ParticleSet<2> p = sample(4);
    const ParticleSet<2> before = p;
    // Mirror across the plane x = 0: R = I - 2 n n^T with n = (1, 0).
    Tensor<2> R = Tensor<2>::Identity();
    R(0, 0) = -1.0;
    const auto version = p.topologyVersion();
    EXPECT_EQ(p.addGhosts({1, 3}, {R, R}), 4u);
    EXPECT_NE(p.topologyVersion(), version);
    EXPECT_EQ(p.size(), 6u);
    EXPECT_EQ(p.ownedCount(), 4u);
    EXPECT_EQ(p.ghostCount(), 2u);
    EXPECT_EQ(p.ghostSource(), (std::vector<std::size_t>{1, 3}));
    // Every field copied from the source, the id too (a ghost is its source seen elsewhere).
    EXPECT_EQ(p.globalId()[4], 11);
    EXPECT_EQ(p.globalId()[5], 13);
    EXPECT_EQ(p.scalarField("rho")[5], p.scalarField("rho")[3]);
    // Vectors and tensors reflected on request: Q a and Q T Q^T.
    auto& v = p.vectorField("velocity");
    p.reflectVectorsToGhosts(v);
    EXPECT_EQ(v[4], Vector<2>(-v[1][0], v[1][1]));
    auto& tau = p.symmTensorField("tau");
    p.reflectTensorsToGhosts(tau);
    EXPECT_EQ(tau[5](0, 1), -tau[3](0, 1));
    EXPECT_EQ(tau[5](1, 1), tau[3](1, 1));
    // A changed owned value reaches its ghosts again.
    p.scalarField("rho")[1] = -5.0;
    p.copyToGhosts(p.scalarField("rho"));
    EXPECT_EQ(p.scalarField("rho")[4], -5.0);

    // Topology changes of owned particles wait until the ghosts are gone.
    EXPECT_THROW(p.append(1), Error);
    EXPECT_THROW(p.keep({0}), Error);
    EXPECT_THROW(p.addGhosts({4}, {R}), Error) << "a ghost of a ghost names its owned source instead";

    // Only the owned particles go to the file.
    const auto file = dir.path() / "particles.vtp";
    writeVtp(file, p, 0.0);
    EXPECT_EQ(readVtp(file).particles->size(), 4u);

    p.clearGhosts();
    EXPECT_EQ(p.size(), 4u);
    EXPECT_EQ(p.ghostCount(), 0u);
    EXPECT_TRUE(p.ghostMap().empty());
    EXPECT_TRUE(sameBits(p.field("globalId"), before.field("globalId")));
    p.append(1);
    EXPECT_EQ(p.globalId().back(), 14) << "ghost copies of ids are not ids issued";
}

TEST(ParticleManagement, AVerletListIsRebuiltAfterParticlesComeAndGo) {
    // Four particles 0.1 apart on a line; candidates are the pairs within 0.15 + skin.
    ParticleSet<1> p(4);
    for (std::size_t i = 0; i < 4; ++i) p.position()[i] = Vector<1>(0.1 * double(i));
    VerletList<1> list(0.02);
    EXPECT_TRUE(list.update(p.position(), 0.15));
    EXPECT_FALSE(list.update(p.position(), 0.15)) << "nothing changed: no rebuild";
    // An append changes the count: rebuilt, and the new particle has its neighbour.
    p.append(1);
    p.position()[4] = Vector<1>(0.4);
    EXPECT_TRUE(list.update(p.position(), 0.15));
    EXPECT_EQ(list.candidates().size(), 5u);
    auto row = list.candidates()[4];
    EXPECT_NE(std::find(row.begin(), row.end(), 3u), row.end());
    // Particle 0 removed and one appended: the same count, every index now 0.1 further on.
    p.keep({1, 2, 3, 4});
    p.append(1);
    p.position()[4] = Vector<1>(0.5);
    EXPECT_TRUE(list.update(p.position(), 0.15));
    row = list.candidates()[0];  // x = 0.1 now: its neighbour is index 1 (x = 0.2)
    EXPECT_NE(std::find(row.begin(), row.end(), 1u), row.end());
    EXPECT_EQ(list.rebuildCount(), 3u);
}

TEST(ParticleManagement, AVerletListTrackingTheTopologyRebuildsOnEveryChange) {
    // The displacement test above keeps a list whose positions are still within the skin, which
    // is right for candidates but not for a user that keeps data per pair by index (bond
    // histories): track() rebuilds on every append, keep or reorder.
    ParticleSet<1> p(4);
    for (std::size_t i = 0; i < 4; ++i) p.position()[i] = Vector<1>(0.1 * double(i));
    VerletList<1> tracked(0.02), untracked(0.02);
    tracked.track(p.topologyVersion());
    EXPECT_TRUE(tracked.update(p.position(), 0.15));
    EXPECT_TRUE(untracked.update(p.position(), 0.15));
    tracked.track(p.topologyVersion());
    EXPECT_FALSE(tracked.update(p.position(), 0.15)) << "nothing changed: no rebuild";

    // The last particle replaced by a new one 0.005 from it: another particle at index 3.
    p.keep({0, 1, 2});
    p.append(1);
    p.position()[3] = Vector<1>(0.3 + 0.005);
    EXPECT_FALSE(untracked.update(p.position(), 0.15)) << "positions alone see a small move";
    tracked.track(p.topologyVersion());
    EXPECT_TRUE(tracked.update(p.position(), 0.15));
    EXPECT_EQ(tracked.rebuildCount(), 2u);
}
