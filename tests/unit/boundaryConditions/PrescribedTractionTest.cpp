// prescribedTraction: f_a = t A V_a / Σ V_b on the selection, through the addBoundaryForce hook.
// Σ f = t A is a sum of up to 121 terms of O(1): 1e-12 relative is round-off with a margin.
#include "BoundaryConditionTestTools.hpp"
#include "boundaryConditions/PrescribedTraction.hpp"

#include <gtest/gtest.h>

using namespace mfdyn;
using mfdyn::test::condition;
using mfdyn::test::conditions;
using mfdyn::test::inputErrorOf;
using mfdyn::test::lattice;

namespace {

// The unit cube at spacing 0.25 with nodal (tributary) volumes: Δx³ halved per face.
ParticleSet<3> nodalCube() {
    auto p = lattice<3>(5, 0.25);
    auto& m = p.scalarField("mass");
    auto& rho = p.scalarField("density");
    m.resize(p.size());
    rho.assign(p.size(), 2000.0);
    for (std::size_t i = 0; i < p.size(); ++i) {
        double v = 0.25 * 0.25 * 0.25;
        for (int d = 0; d < 3; ++d)
            if (p.position()[i][d] == 0.0 || p.position()[i][d] == 1.0) v *= 0.5;
        m[i] = rho[i] * v;
    }
    return p;
}

const std::string topFace = "shape { type box; min (-1 -1 0.99); max (2 2 2); }";  // z = 1

}  // namespace

TEST(PrescribedTraction, TotalForceIsTractionTimesAreaSharedByVolume) {
    const auto p = nodalCube();
    const auto bc =
        condition<3>("type prescribedTraction; " + topFace + " traction (1e5 0 -2e6); area 1;", p);
    EXPECT_EQ(bc->selection().size(), 25u);
    std::vector<Vector<3>> f(p.size(), Vector<3>::Zero());
    bc->addBoundaryForce(p, f, 0.0);
    Vector<3> total = Vector<3>::Zero();
    for (std::size_t i = 0; i < p.size(); ++i) {
        total += f[i];
        if (p.position()[i][2] != 1.0) {
            EXPECT_TRUE(f[i].isZero()) << i;
            continue;
        }
        // On a nodal face the share is the tributary face area: Δx² halved per edge of the face.
        double area = 0.25 * 0.25;
        for (int d = 0; d < 2; ++d)
            if (p.position()[i][d] == 0.0 || p.position()[i][d] == 1.0) area *= 0.5;
        EXPECT_NEAR((f[i] - area * Vector<3>(1e5, 0, -2e6)).norm(), 0.0, 1e-12 * 2e6 * area) << i;
    }
    EXPECT_NEAR(total[0], 1e5, 1e-12 * 1e5);
    EXPECT_EQ(total[1], 0.0);
    EXPECT_NEAR(total[2], -2e6, 1e-12 * 2e6);
}

TEST(PrescribedTraction, SharesFollowVolumesAndAddToForcesAlreadyThere) {
    auto p = lattice<2>(11, 0.1);
    auto& m = p.scalarField("mass");
    auto& rho = p.scalarField("density");
    for (std::size_t i = 0; i < p.size(); ++i) {
        m[i] = 1.0 + double(i % 3);  // volumes 1, 2, 3 (× 1e-3) in turn
        rho[i] = 1000.0;
    }
    const auto bc = condition<2>("type prescribedTraction; regions (wall); traction (0 -300); area 0.5;", p);
    double volumes = 0;
    for (auto i : bc->selection().indices()) volumes += m[i] / rho[i];
    std::vector<Vector<2>> f(p.size(), Vector<2>(1.0, 1.0));
    bc->addBoundaryForce(p, f, 0.0);
    double total = 0;
    for (std::size_t i = 0; i < p.size(); ++i) {
        if (p.region()[i] != 1) {
            EXPECT_EQ(f[i], Vector<2>(1.0, 1.0));
            continue;
        }
        EXPECT_EQ(f[i][0], 1.0);
        EXPECT_NEAR(f[i][1] - 1.0, -300 * 0.5 * (m[i] / rho[i]) / volumes, 1e-12) << i;
        total += f[i][1] - 1.0;
    }
    EXPECT_NEAR(total, -150.0, 1e-12 * 150);
}

TEST(PrescribedTraction, TableAndReleaseTime) {
    const auto p = nodalCube();
    auto bcs = conditions<3>("boundaryConditions { load { type prescribedTraction; " + topFace +
                                 " table ((0 (0 0 0)) (1 (0 0 -4))); area 1; releaseTime 2; } }",
                             p);
    const auto totalAt = [&](double t) {
        std::vector<Vector<3>> f(p.size(), Vector<3>::Zero());
        bcs.addBoundaryForces(p, f, t);
        Vector<3> s = Vector<3>::Zero();
        for (const auto& x : f) s += x;
        return s;
    };
    EXPECT_NEAR(totalAt(0.25)[2], -1.0, 1e-12);
    EXPECT_NEAR(totalAt(1.5)[2], -4.0, 1e-12);  // held after the last time
    EXPECT_TRUE(totalAt(2.0).isZero());         // released: nothing from t = releaseTime on
    EXPECT_TRUE(totalAt(3.0).isZero());
    const auto& load = dynamic_cast<const PrescribedTraction<3>&>(bcs[0]);
    EXPECT_EQ(load.traction(0.5), Vector<3>(0, 0, -2));
    EXPECT_EQ(load.area(), 1.0);
}

TEST(PrescribedTraction, KeepsItsParticlesThroughAReorder) {
    auto p = nodalCube();
    auto bcs = conditions<3>(
        "boundaryConditions { load { type prescribedTraction; " + topFace + " traction (0 0 -1); area 1; } }",
        p);
    std::vector<std::size_t> order(p.size());
    for (std::size_t i = 0; i < order.size(); ++i) order[i] = (i * 7) % order.size();  // 7 and 125 coprime
    p.reorder(order);
    for (auto& x : p.position()) x[2] += 0.5;  // the face moves away: the loaded particles do not change
    bcs.updateSelections(p);
    std::vector<Vector<3>> f(p.size(), Vector<3>::Zero());
    bcs.addBoundaryForces(p, f, 0.0);
    double total = 0;
    for (std::size_t i = 0; i < p.size(); ++i) {
        total += f[i][2];
        EXPECT_EQ(f[i][2] != 0.0, p.position()[i][2] == 1.5) << i;
    }
    EXPECT_NEAR(total, -1.0, 1e-12);
}

TEST(PrescribedTraction, InputErrors) {
    const auto p = nodalCube();
    std::string message =
        inputErrorOf([&] { condition<3>("type prescribedTraction; " + topFace + " traction (0 0 -1);", p); });
    EXPECT_NE(message.find("area"), std::string::npos) << message;
    EXPECT_THROW(condition<3>("type prescribedTraction; " + topFace + " traction (0 0 -1); area 0;", p),
                 InputError);
    EXPECT_THROW(condition<3>("type prescribedTraction; " + topFace + " area 1;", p), InputError);
    EXPECT_THROW(
        condition<3>(
            "type prescribedTraction; " + topFace + " traction (0 0 -1); table ((0 (0 0 1))); area 1;", p),
        InputError);
    EXPECT_THROW(condition<3>("type prescribedTraction; traction (0 0 -1); area 1;", p),
                 InputError);              // no selection
    const auto bare = lattice<3>(3, 0.5);  // no mass or density fields
    message = inputErrorOf(
        [&] { condition<3>("type prescribedTraction; all yes; traction (0 0 -1); area 1;", bare); });
    EXPECT_NE(message.find("density"), std::string::npos) << message;
}
