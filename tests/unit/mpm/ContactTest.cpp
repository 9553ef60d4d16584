// The contact family of mpmFsi (mpm/contact/): multiField's correction on hand-made node state
// (Bardenhagen et al. 2001, MultiFieldContact.cpp), built from a dictionary through the family's
// selection as the solver does. Two bodies at one node: approaching, the normal velocities become
// equal (the centre-of-mass velocity's normal component) with momentum exact to round-off;
// separating, nothing changes; Coulomb friction moves the tangential velocity by mu times the
// normal change, or sticks; the position check; the pair errors (a body with itself, an unknown
// body) naming the file, the line and the valid bodies.
#include "core/Dictionary.hpp"
#include "core/Error.hpp"
#include "mpm/MpmModels.hpp"
#include "mpm/contact/Contact.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

namespace mfdyn {
namespace {

std::unique_ptr<Contact<2>> contactOf(const Dictionary& dict) {
    auto c = selectByWord<Contact<2>>(dict, "contact", "singleField");
    c->bind({"left", "right"});
    return c;
}

// One node shared by body 0 (mass 2, on the -n side) and body 1 (mass 1, on the +n side): body
// 0's outward normal is n = (cos q, sin q), body 1's -n (the mass gradients point out of each
// body: MultiFieldContact.cpp). Velocities are given in the (n, t) frame.
struct Node {
    std::vector<std::vector<double>> mass{{2.0}, {1.0}};
    std::vector<std::vector<Vector<2>>> gradient, position, velocity, acceleration;
    Vector<2> n, t;
    ContactNodes<2> nodes;
    Node(double vn0, double vt0, double vn1, double vt1, double q = 0.3) {
        n = Vector<2>(std::cos(q), std::sin(q));
        t = Vector<2>(-std::sin(q), std::cos(q));
        gradient = {{0.7 * n}, {-3.0 * n}};  // magnitudes differ: only the directions count
        velocity = {{vn0 * n + vt0 * t}, {vn1 * n + vt1 * t}};
        acceleration = {{Vector<2>::Zero()}, {Vector<2>::Zero()}};
        nodes.mass = &mass;
        nodes.massGradient = &gradient;
        nodes.velocity = &velocity;
        nodes.acceleration = &acceleration;
        nodes.cellSize = 0.1;
    }
    Vector<2> momentum() const { return mass[0][0] * velocity[0][0] + mass[1][0] * velocity[1][0]; }
};

const char* multiField = "contact multiField;\n";

TEST(MpmContact, SingleFieldIsTheDefaultAndCorrectsNothing) {
    const Dictionary dict = Dictionary::parse("shapeFunction linear;\n", "mpmProperties");
    auto c = contactOf(dict);
    EXPECT_EQ(c->type(), "singleField");
    EXPECT_FALSE(c->multiField());
    EXPECT_EQ(c->pairs(), 0u);
}

TEST(MpmContact, ApproachingBodiesGetEqualNormalVelocitiesAndMomentumIsExact) {
    const Dictionary dict = Dictionary::parse(multiField, "mpmProperties");
    auto c = contactOf(dict);
    ASSERT_TRUE(c->multiField());
    ASSERT_EQ(c->pairs(), 1u);
    // Body 0 moves at +1 along n towards body 1 (-1): approaching. v_cm . n = (2 - 1) / 3.
    Node s(1.0, 0.5, -1.0, -0.2);
    const Vector<2> P0 = s.momentum();
    const double dt = 1e-3;
    const auto F = c->correct(s.nodes, dt);
    const double vn = 1.0 / 3.0;
    // Normal velocities equalised at v_cm . n; frictionless: tangential ones untouched. The
    // tolerances are round-off of O(1) numbers through a normalisation and a few products.
    EXPECT_NEAR(s.velocity[0][0].dot(s.n), vn, 1e-15);
    EXPECT_NEAR(s.velocity[1][0].dot(s.n), vn, 1e-15);
    EXPECT_NEAR(s.velocity[0][0].dot(s.t), 0.5, 1e-15);
    EXPECT_NEAR(s.velocity[1][0].dot(s.t), -0.2, 1e-15);
    // Momentum exact: the two corrections are equal and opposite, to a few ulps of |P| ~ 1.
    EXPECT_LT((s.momentum() - P0).norm(), 1e-15);
    // The FLIP acceleration carries the same change, dv / dt, and F = m_0 dv_0 / dt on body 0.
    const Vector<2> dv0 = (vn - 1.0) * s.n;
    EXPECT_LT((s.acceleration[0][0] - dv0 / dt).norm(), 1e-12 * (1.0 / dt));
    EXPECT_LT((s.acceleration[1][0] - (vn + 1.0) * s.n / dt).norm(), 1e-12 * (1.0 / dt));
    ASSERT_EQ(F.size(), 1u);
    EXPECT_LT((F[0] - 2.0 * dv0 / dt).norm(), 1e-12 * (2.0 / dt));
}

TEST(MpmContact, SeparatingBodiesAreLeftAlone) {
    const Dictionary dict = Dictionary::parse(multiField, "mpmProperties");
    auto c = contactOf(dict);
    Node s(-1.0, 0.5, 0.5, -0.2);
    const auto v0 = s.velocity;
    const auto F = c->correct(s.nodes, 1e-3);
    EXPECT_EQ(s.velocity[0][0], v0[0][0]);
    EXPECT_EQ(s.velocity[1][0], v0[1][0]);
    EXPECT_EQ(s.acceleration[0][0], Vector<2>::Zero());
    EXPECT_EQ(F[0], Vector<2>::Zero());
}

TEST(MpmContact, CoulombFrictionLimitsTheTangentialCorrection) {
    // mu 0.1, given per pair: body 0's normal change is 2/3, so its tangential velocity relative
    // to the centre of mass (0.5 - (2 0.5 - 0.2) / 3 = 0.2333) drops by mu 2/3 = 0.0667; body 1's
    // by mu 4/3 in the opposite sense (the same momentum).
    const Dictionary dict = Dictionary::parse(
        "contact multiField;\nmultiFieldCoeffs\n{\n    friction 0;\n    pairs { lr { bodies (left right); "
        "friction 0.1; } }\n}\n",
        "mpmProperties");
    auto c = contactOf(dict);
    Node s(1.0, 0.5, -1.0, -0.2);
    const Vector<2> P0 = s.momentum();
    c->correct(s.nodes, 1e-3);
    EXPECT_NEAR(s.velocity[0][0].dot(s.t), 0.5 - 0.1 * (2.0 / 3.0), 1e-15);
    EXPECT_NEAR(s.velocity[1][0].dot(s.t), -0.2 + 0.1 * (4.0 / 3.0), 1e-15);
    EXPECT_LT((s.momentum() - P0).norm(), 1e-15);
    // mu 10: mu |dv_n| exceeds the tangential slip, so the bodies stick: both at v_cm.
    const Dictionary sticky =
        Dictionary::parse("contact multiField;\nmultiFieldCoeffs { friction 10; }\n", "mpmProperties");
    auto k = contactOf(sticky);
    Node u(1.0, 0.5, -1.0, -0.2);
    const Vector<2> vcm = u.momentum() / 3.0;
    k->correct(u.nodes, 1e-3);
    EXPECT_LT((u.velocity[0][0] - vcm).norm(), 1e-15);
    EXPECT_LT((u.velocity[1][0] - vcm).norm(), 1e-15);
}

TEST(MpmContact, PositionCheckWaitsUntilTheBodiesAreClose) {
    // separation 0.5 cells (0.05 m here): nodal centres of mass 0.08 m apart along n are not in
    // contact, 0.02 m apart are.
    const Dictionary dict =
        Dictionary::parse("contact multiField;\nmultiFieldCoeffs { separation 0.5; }\n", "mpmProperties");
    auto c = contactOf(dict);
    for (const double gap : {0.08, 0.02}) {
        Node s(1.0, 0.0, -1.0, 0.0);
        const Vector<2> before = s.velocity[0][0];
        // massPosition = m x: body 0's centre at -gap/2 n, body 1's at +gap/2 n.
        s.position = {{s.mass[0][0] * (-0.5 * gap) * s.n}, {s.mass[1][0] * (0.5 * gap) * s.n}};
        s.nodes.massPosition = &s.position;
        c->correct(s.nodes, 1e-3);
        if (gap > 0.05)
            EXPECT_EQ(s.velocity[0][0], before);
        else
            EXPECT_NEAR(s.velocity[0][0].dot(s.n), 1.0 / 3.0, 1e-15);
    }
}

TEST(MpmContact, VolumeCheckWaitsUntilTheBodiesFillTheNode) {
    // volumeFraction 1 on a 0.1 m cell (dx^2 = 0.01): nodal volumes summing to 0.009 leave a gap
    // (no contact), to 0.01 the bodies touch (contact), to 0.011 they overlap (contact).
    const Dictionary dict =
        Dictionary::parse("contact multiField;\nmultiFieldCoeffs { volumeFraction 1; }\n", "mpmProperties");
    auto c = contactOf(dict);
    EXPECT_NE(c->describe().find("volumeFraction 1"), std::string::npos) << c->describe();
    for (const double filled : {0.009, 0.01, 0.011}) {
        Node s(1.0, 0.0, -1.0, 0.0);
        s.nodes.cellVolume = 0.01;
        const Vector<2> before = s.velocity[0][0];
        const std::vector<std::vector<double>> volume{{0.6 * filled}, {0.4 * filled}};
        s.nodes.volume = &volume;
        const Vector<2> p0 = s.momentum();
        c->correct(s.nodes, 1e-3);
        if (filled < 0.01) {
            EXPECT_EQ(s.velocity[0][0], before) << "filled " << filled;
        } else {
            // Both normal velocities become the centre of mass's, (2 - 1) / 3, momentum exact.
            EXPECT_NEAR(s.velocity[0][0].dot(s.n), 1.0 / 3.0, 1e-15) << "filled " << filled;
            EXPECT_NEAR(s.velocity[1][0].dot(s.n), 1.0 / 3.0, 1e-15) << "filled " << filled;
            EXPECT_LT((s.momentum() - p0).norm(), 1e-15);
        }
    }
}

std::string bindError(const std::string& pairs) {
    const Dictionary dict = Dictionary::parse(
        "contact multiField;\nmultiFieldCoeffs\n{\n    pairs\n    {\n" + pairs + "\n    }\n}\n",
        "mpmProperties");
    try {
        contactOf(dict);
    } catch (const InputError& e) {
        return e.what();
    }
    return "";
}

TEST(MpmContact, PairErrorsNameTheFileLineAndBodies) {
    // A contact law between a body and itself (issue 18's acceptance), on line 6.
    const std::string self = bindError("        a { bodies (left left); friction 0.2; }");
    EXPECT_NE(self.find("itself"), std::string::npos) << self;
    EXPECT_NE(self.find("mpmProperties:6"), std::string::npos) << self;
    EXPECT_NE(self.find("left right"), std::string::npos) << self;
    const std::string unknown = bindError("        a { bodies (left middle); friction 0.2; }");
    EXPECT_NE(unknown.find("unknown body 'middle'"), std::string::npos) << unknown;
    EXPECT_NE(unknown.find("left right"), std::string::npos) << unknown;
    EXPECT_NE(unknown.find("mpmProperties:6"), std::string::npos) << unknown;
    const std::string three = bindError("        a { bodies (left right left); friction 0.2; }");
    EXPECT_NE(three.find("two bodies"), std::string::npos) << three;
    const std::string twice = bindError(
        "        a { bodies (left right); friction 0.2; }\n        b { bodies (right left); friction 0.1; }");
    EXPECT_NE(twice.find("given once"), std::string::npos) << twice;
}

}  // namespace
}  // namespace mfdyn
