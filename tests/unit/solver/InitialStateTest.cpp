// The initialState family: every model built through New from a dictionary, as a case does, and
// checked against its formula; apply() on a small particle set.
#include "solver/CantileverMode.hpp"
#include "solver/InitialState.hpp"
#include "verification/CantileverModeShape.hpp"
#include "verification/SwingingCube.hpp"
#include "verification/TwistingColumnMotion.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

using namespace mfdyn;

namespace {

template <int Dim>
std::unique_ptr<InitialState<Dim>> make(const std::string& text) {
    return InitialState<Dim>::New(Dictionary::parse(text, "initialState"));
}

}  // namespace

TEST(InitialState, everyModelIsRegisteredInEveryDimension) {
    const auto names = InitialState<3>::Selector::names();
    for (const char* type : {"uniformVelocity", "linearVelocity", "rigidRotation", "twistingColumn",
                             "swingingCube", "cantileverMode"})
        EXPECT_NE(std::find(names.begin(), names.end(), type), names.end()) << type;
    EXPECT_NO_THROW(make<1>("type uniformVelocity; velocity (5 0 0);"));
    EXPECT_THROW(make<3>("type uniformVelocty; velocity (5 0 0);"), InputError);
}

TEST(InitialState, uniformAndLinearVelocity) {
    const auto uniform = make<3>("type uniformVelocity; velocity (1 2 3);");
    EXPECT_EQ(uniform->velocity(Vector<3>(7, 8, 9)), Vector<3>(1, 2, 3));
    EXPECT_FALSE(uniform->hasDisplacement());
    EXPECT_EQ(uniform->displacement(Vector<3>(7, 8, 9)), Vector<3>::Zero());
    // Bending column: v = V [Y/L, 0, 0], V = 10, L = 6.
    const auto bending = make<3>("type linearVelocity; gradient ((0 1.6666666666666667 0) (0 0 0) (0 0 0));");
    EXPECT_NEAR(bending->velocity(Vector<3>(0.3, 6, -0.2))(0), 10.0, 1e-12);
    EXPECT_NEAR(bending->velocity(Vector<3>(0.3, 3, -0.2))(0), 5.0, 1e-12);
    EXPECT_EQ(bending->velocity(Vector<3>(0.3, 3, -0.2))(1), 0.0);
    // Flat form, an origin and a base velocity; a 3x3 gradient in 2D keeps its leading block.
    const auto flat =
        make<2>("type linearVelocity; velocity (1 0 0); gradient (0 0 0 0 2 0 0 0 0); origin (0 1);");
    EXPECT_EQ(flat->velocity(Vector<2>(5, 3)), Vector<2>(1, 4));
    EXPECT_THROW(make<2>("type linearVelocity; gradient ((0 0 1) (0 0 0) (0 0 0));"), InputError);
    EXPECT_THROW(make<3>("type linearVelocity; gradient (1 2 3);"), InputError);
    EXPECT_THROW(make<3>("type linearVelocity;"), InputError);
}

TEST(InitialState, rigidRotation) {
    const auto spin = make<3>("type rigidRotation; omega (0 0 2); centre (0.5 0.5 0.5);");
    EXPECT_TRUE(spin->velocity(Vector<3>(1.5, 0.5, 0.9)).isApprox(Vector<3>(0, 2, 0)));
    const auto spin2 = make<2>("type rigidRotation; omega 2;");
    EXPECT_TRUE(spin2->velocity(Vector<2>(0, 1)).isApprox(Vector<2>(-2, 0)));
    EXPECT_TRUE(
        make<2>("type rigidRotation; omega (0 0 2);")->velocity(Vector<2>(0, 1)).isApprox(Vector<2>(-2, 0)));
    EXPECT_THROW(make<2>("type rigidRotation; omega (1 0 2);"), InputError);
    EXPECT_THROW(make<1>("type rigidRotation; omega 2;"), InputError);
}

// Lee et al. 2016 8.9: omega = (0, Omega sin(pi Y/(2L)), 0), v = omega x X.
TEST(InitialState, twistingColumn) {
    const auto twist = make<3>("type twistingColumn; Omega 105; length 6;");
    const Vector<3> X(0.5, 6.0, 0.0);  // top: omega = (0, 105, 0), v = omega x X = (0, 0, -52.5)
    EXPECT_TRUE(twist->velocity(X).isApprox(Vector<3>(0, 0, -52.5)));
    const Vector<3> mid(0.0, 3.0, 0.5);
    const double w = 105 * std::sin(std::numbers::pi / 4);
    EXPECT_TRUE(twist->velocity(mid).isApprox(Vector<3>(w * 0.5, 0, 0)));
    EXPECT_EQ(twist->velocity(Vector<3>(0.5, 0, 0.5)), Vector<3>::Zero());  // clamped base
    EXPECT_THROW(make<2>("type twistingColumn; Omega 105; length 6;"), InputError);
    EXPECT_THROW(make<3>("type twistingColumn; Omega 105;"), InputError);
    EXPECT_THROW(make<3>("type twistingColumn; Omega 105; length 6; axis W;"), InputError);
}

TEST(InitialState, swingingCubeAppliesDisplacementAndF) {
    ParticleSet<3> particles(2);
    particles.regionNames = {"cube", "other"};
    particles.region()[1] = 1;
    const std::vector<Vector<3>> X{Vector<3>(0.2, 0.3, 0.4), Vector<3>(0.5, 0.5, 0.5)};
    particles.position() = X;
    const auto cube = make<3>("type swingingCube; amplitude 5e-4; regions (cube);");
    EXPECT_TRUE(cube->hasDisplacement());
    cube->apply(particles, X);
    const Vector<3> u = SwingingCube<3>::modeShape(X[0], 5e-4);
    const double k = std::numbers::pi / 2;
    EXPECT_NEAR(u(0), 5e-4 * std::sin(k * 0.2) * std::cos(k * 0.3) * std::cos(k * 0.4), 1e-18);
    EXPECT_TRUE(particles.position()[0].isApprox(X[0] + u));
    EXPECT_EQ(particles.position()[1], X[1]);  // not in the region
    const auto& F = particles.tensorField("deformationGradient");
    // F = I + grad u, grad u by central differences.
    for (int J = 0; J < 3; ++J) {
        Vector<3> e = Vector<3>::Zero();
        e(J) = 1e-6;
        const Vector<3> dudX =
            (SwingingCube<3>::modeShape(X[0] + e, 5e-4) - SwingingCube<3>::modeShape(X[0] - e, 5e-4)) / 2e-6;
        for (int i = 0; i < 3; ++i) EXPECT_NEAR(F[0](i, J), (i == J) + dudX(i), 1e-12);
    }
    EXPECT_EQ(F[1], Tensor<3>::Zero());  // untouched: the solver's own initialisation
    EXPECT_EQ(particles.vectorField("velocity")[0], Vector<3>::Zero());
    EXPECT_THROW(make<3>("type swingingCube; amplitude 5e-4; regions (cub);")->apply(particles, X),
                 InputError);
}

// Gray, Monaghan & Swift 2001 / PySPH oscillating_plate: v_y(L) = V_f, v_y(0) = 0, and the shape
// is PySPH's (M (cos - cosh) - N (sin - sinh)) / Q with Q = 2 (cos kL sinh kL - sin kL cosh kL).
// The states are thin adapters over the references in libraries/verification: what a case gets
// is the reference's value to the last bit (the formulas moved there in issue 15, results unchanged).
TEST(InitialState, analyticStatesAreTheVerificationReferencesBitForBit) {
    const auto twist = make<3>("type twistingColumn; Omega 105; length 6; centre (0.1 0 -0.2);");
    const TwistingColumnMotion motion(105, 6, 1, Vector<3>(0.1, 0, -0.2));
    const auto plate = make<3>("type cantileverMode; length 0.2; velocity 0.05; clampX -0.1;");
    const CantileverModeShape mode(0.2, 0.05);
    for (int i = 0; i <= 40; ++i) {
        const Vector<3> X(0.37 - 0.013 * i, 0.15 * i, 0.011 * i - 0.2);
        EXPECT_EQ(twist->velocity(X), motion.velocity(X)) << i;
        EXPECT_EQ(plate->velocity(X)(1), mode.transverseVelocity(X(0) + 0.1)) << i;
        const Vector<3> Xc(0.025 * i, 0.5, 0.5);
        EXPECT_EQ(make<3>("type swingingCube; amplitude 5e-4;")->displacement(Xc),
                  SwingingCube<3>::modeShape(Xc, 5e-4))
            << i;
    }
}

TEST(InitialState, cantileverMode) {
    const auto plate = make<2>("type cantileverMode; length 0.2; thickness 0.02; velocity 0.05;");
    EXPECT_NEAR(plate->velocity(Vector<2>(0.2, 0.0))(1), 0.05, 1e-14);
    EXPECT_EQ(plate->velocity(Vector<2>(0.0, 0.0))(1), 0.0);
    EXPECT_EQ(plate->velocity(Vector<2>(-0.03, 0.01))(1), 0.0);  // inside the clamp
    EXPECT_EQ(plate->velocity(Vector<2>(0.1, 0.01))(0), 0.0);
    const double kL = 1.875, k = kL / 0.2, x = 0.13;
    const double M = std::sin(kL) + std::sinh(kL), N = std::cos(kL) + std::cosh(kL);
    const double Q = 2 * (std::cos(kL) * std::sinh(kL) - std::sin(kL) * std::cosh(kL));
    const double pysph =
        0.05 * (M * (std::cos(k * x) - std::cosh(k * x)) - N * (std::sin(k * x) - std::sinh(k * x))) / Q;
    EXPECT_NEAR(plate->velocity(Vector<2>(x, 0.005))(1), pysph, 1e-14);
    // The clamp: zero slope at s = 0 (v_y ~ s^2 there).
    EXPECT_LT(std::abs(plate->velocity(Vector<2>(1e-4, 0))(1)), 0.05 * 1e-5);
    // Monotone from the clamp to the free end.
    double previous = 0;
    for (int i = 1; i <= 20; ++i) {
        const double v = plate->velocity(Vector<2>(0.01 * i, 0))(1);
        EXPECT_GT(v, previous);
        previous = v;
    }
    const auto shifted = make<3>("type cantileverMode; length 0.2; velocity 0.05; clampX -0.1;");
    EXPECT_NEAR(shifted->velocity(Vector<3>(0.1, 0, 0))(1), 0.05, 1e-14);
    EXPECT_THROW(make<1>("type cantileverMode; length 0.2; velocity 0.05;"), InputError);
    EXPECT_THROW(make<2>("type cantileverMode; length 0.2; velocity 0.05; thickness 0.3;"), InputError);
}

// `sections plane`: the mode in the beam's own kinematics, v_x = -(Y - Y0) v_y'(s) (the rotation of
// the cross-section), v_y as before; the slope against a central difference of v_y, zero inside the
// clamp and at its face, and the velocity gradient's symmetric part without the shear strain rate
// dv_y/dX + dv_x/dY that `transverse` leaves (the rigid rotation of each section).
TEST(InitialState, cantileverModePlaneSections) {
    const auto plane =
        make<2>("type cantileverMode; length 0.2; velocity 0.05; sections plane; neutralAxis 0.001;");
    const auto transverse = make<2>("type cantileverMode; length 0.2; velocity 0.05;");
    const CantileverModeShape mode(0.2, 0.05);
    for (int i = 1; i <= 19; ++i) {
        const double s = 0.01 * i, d = 1e-6;
        const double slope = (mode.transverseVelocity(s + d) - mode.transverseVelocity(s - d)) / (2 * d);
        EXPECT_NEAR(mode.transverseVelocitySlope(s), slope, 1e-8 * 0.05 / 0.2) << s;
        const Vector<2> X(s, 0.009);
        EXPECT_EQ(plane->velocity(X)(1), transverse->velocity(X)(1));
        EXPECT_NEAR(plane->velocity(X)(0), -(0.009 - 0.001) * mode.transverseVelocitySlope(s), 1e-17);
        // Shear strain rate dv_y/dX + dv_x/dY: v_y' - v_y' = 0 with plane sections, v_y' without.
        const double dvxdY =
            (plane->velocity(Vector<2>(s, 0.009 + d))(0) - plane->velocity(Vector<2>(s, 0.009 - d))(0)) /
            (2 * d);
        EXPECT_NEAR(slope + dvxdY, 0.0, 1e-8 * 0.05 / 0.2) << s;
    }
    EXPECT_EQ(plane->velocity(Vector<2>(-0.02, 0.01))(0), 0.0);   // inside the clamp
    // Clamped: the rotation vanishes at the face, linearly (v_y' = v_y''(0) s, v_y''(0) = 4.39 1/s).
    EXPECT_NEAR(mode.transverseVelocitySlope(1e-9), 0.0, 1e-8);
    EXPECT_THROW(make<2>("type cantileverMode; length 0.2; velocity 0.05; sections curved;"), InputError);
    EXPECT_THROW(make<2>("type cantileverMode; length 0.2; velocity 0.05; neutralAxis 0.01;"), InputError);
}

TEST(InitialState, applyVelocityToAllParticles) {
    ParticleSet<2> particles(3);
    std::vector<Vector<2>> X{Vector<2>(0, 0), Vector<2>(1, 0), Vector<2>(0, 1)};
    const auto spin = make<2>("type rigidRotation; omega 3;");
    spin->apply(particles, X);
    EXPECT_TRUE(particles.vectorField("velocity")[1].isApprox(Vector<2>(0, 3)));
    EXPECT_EQ(particles.position()[2], X[2]);
    EXPECT_FALSE(particles.hasField("deformationGradient"));
    X.pop_back();
    EXPECT_THROW(spin->apply(particles, X), Error);
}
