// The contact family of mpmFsi (mpm/contact/): multiField's correction on hand-made node state
// (Bardenhagen et al. 2001, MultiFieldContact.cpp), built from a dictionary through the family's
// selection as the solver does. Two bodies at one node: approaching, the normal velocities become
// equal (the centre-of-mass velocity's normal component) with momentum exact to round-off;
// separating, nothing changes; Coulomb friction moves the tangential velocity by mu times the
// normal change, or sticks; the position check; the volume check; the surface-gap check on
// particle clouds (touching, apart, at a waterline); the pair errors (a body with itself, an unknown
// body) naming the file, the line and the valid bodies.
#include "core/Dictionary.hpp"
#include "core/Error.hpp"
#include "grid/CartesianGrid.hpp"
#include "grid/shapeFunctions/ShapeFunction.hpp"
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

// Two bodies of particles (10 x 10 a cell) side by side, body 0 in x < xa and body 1 in
// x > xb, both below y = top, mapped with the quadratic B-spline as the solver maps them; the
// node (3, 3) at (0.3, 0.3) of a 6 x 6 grid of 0.1 cells is the probe. Body 0 moves at +1 in x,
// body 1 at -1 (approaching). Returns whether the probe's velocity of body 0 was corrected.
bool probeCorrected(const char* coeffs, double xa, double xb, double top) {
    const Dictionary dict = Dictionary::parse(
        std::string("contact multiField;\nmultiFieldCoeffs { ") + coeffs + " }\n", "mpmProperties");
    auto c = contactOf(dict);
    const CartesianGrid<2> grid(Vector<2>(0.0, 0.0), Vector<2>(0.1, 0.1), {6, 6});
    const auto shape = ShapeFunction<2>::New(Dictionary::parse("type quadraticBSpline;\n", "test"));
    std::vector<Vector<2>> x;
    std::vector<int> body;
    const double d = 0.01;
    for (double px = 0.5 * d; px < 0.6; px += d)
        for (double py = 0.5 * d; py < top; py += d)
            for (int b = 0; b < 2; ++b)  // a row in both bodies where they overlap
                if (b == 0 ? px < xa : px > xb) x.emplace_back(px, py), body.push_back(b);
    ParticleNodeList<2> list;
    shape->evaluate(grid, std::span<const Vector<2>>(x), {}, list);
    const std::size_t n = grid.nodeCount();
    std::vector<std::vector<double>> mass(2, std::vector<double>(n, 0.0)), volume = mass;
    std::vector<std::vector<Vector<2>>> gradient(2, std::vector<Vector<2>>(n, Vector<2>::Zero())),
        position = gradient, velocity = gradient, acceleration = gradient;
    const double mp = 1.0, Vp = d * d;
    for (std::size_t p = 0; p < x.size(); ++p)
        for (std::size_t k = 0; k < list.count[p]; ++k) {
            const std::size_t I = std::size_t(list.node[p * list.stride + k]);
            const double N = list.weight[p * list.stride + k];
            const int b = body[p];
            mass[b][I] += N * mp;
            volume[b][I] += N * Vp;
            position[b][I] += N * mp * x[p];
            gradient[b][I] += mp * list.gradient[p * list.stride + k];
        }
    for (std::size_t I = 0; I < n; ++I) velocity[0][I] = Vector<2>(1, 0), velocity[1][I] = Vector<2>(-1, 0);
    ContactNodes<2> nodes;
    nodes.mass = &mass;
    nodes.massGradient = &gradient;
    nodes.massPosition = &position;
    nodes.volume = &volume;
    nodes.velocity = &velocity;
    nodes.acceleration = &acceleration;
    nodes.grid = &grid;
    nodes.shape = shape.get();
    nodes.cellSize = 0.1;
    nodes.cellVolume = 0.01;
    c->correct(nodes, 1e-3);
    const std::size_t probe = std::size_t(grid.nodeIndex({3, 3}));
    return velocity[0][probe].x() < 1.0 - 1e-12;
}

TEST(MpmContact, SurfaceGapSeesAnOverlapAndAGapAndIsBlindToAWaterline) {
    // Exactly touching is the knife-edge of both checks (their sums meet the bound to rounding), so
    // the cases are an overlap of one particle row (0.1 cells: both bodies own the row at 0.325)
    // and a gap of three rows (0.3 cells: no particle in 0.29..0.32).
    // The support full: both checks see the overlap, neither the gap.
    EXPECT_TRUE(probeCorrected("surfaceGap yes;", 0.33, 0.32, 0.6));
    EXPECT_TRUE(probeCorrected("volumeFraction 1;", 0.33, 0.32, 0.6));
    EXPECT_FALSE(probeCorrected("surfaceGap yes;", 0.29, 0.32, 0.6));
    EXPECT_FALSE(probeCorrected("volumeFraction 1;", 0.29, 0.32, 0.6));
    // A free surface 0.5 cells above the probe (air in the top sixth of the support, the float's
    // waterline): the volume sum falls to about 1 + 0.07 - 0.17 and the volume check misses the
    // overlap; the surface gap, read from the centres along the normal, still sees it.
    EXPECT_TRUE(probeCorrected("surfaceGap yes;", 0.33, 0.32, 0.35));
    EXPECT_FALSE(probeCorrected("volumeFraction 1;", 0.33, 0.32, 0.35));
    EXPECT_FALSE(probeCorrected("surfaceGap yes;", 0.29, 0.32, 0.35));
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
