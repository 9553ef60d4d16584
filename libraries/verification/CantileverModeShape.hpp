#pragma once
// The first bending mode of an Euler-Bernoulli cantilever, the initial velocity of the oscillating
// plate (Gray, Monaghan & Swift 2001). Formula and sources in CantileverModeShape.cpp; the
// initialState cantileverMode (libraries/solver) applies it.

namespace mfdyn {

class CantileverModeShape {
public:
    // length L [m] (> 0), tipVelocity V_f [m/s] (finite), mode number kL (> 0; 1.875 is the first).
    // Throws Error otherwise.
    CantileverModeShape(double length, double tipVelocity, double kL = 1.875);

    // The transverse velocity at distance s from the clamp: V_f f(s)/f(L), 0 for s <= 0.
    double transverseVelocity(double s) const;
    // Its slope d v_y/ds = V_f f'(s)/f(L), 0 for s <= 0: the rate of rotation of the cross-section
    // at s in the Euler-Bernoulli kinematics (plane sections normal to the axis).
    double transverseVelocitySlope(double s) const;
    // The unnormalised shape f(s) and its derivative f'(s).
    double shape(double s) const;
    double shapeSlope(double s) const;

private:
    double length_, velocity_, kL_;
};

}  // namespace mfdyn
