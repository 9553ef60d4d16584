// cantileverMode: the oscillating plate of Gray, Monaghan & Swift 2001 ("SPH elastic dynamics",
// Comput. Methods Appl. Mech. Engrg. 190:6641, section 6.2), as set up by PySPH's
// oscillating_plate example: a plate along X, clamped at X = clampX, free at clampX + L, given
// the velocity of the first bending mode of an Euler-Bernoulli cantilever,
//
//     v_y(s) = V_f f(s)/f(L),   f(s) = M (cos ks - cosh ks) - N (sin ks - sinh ks),
//     M = sin kL + sinh kL,  N = cos kL + cosh kL,  f(L) = 2 (cos kL sinh kL - sin kL cosh kL),
//
// s = X - clampX, k = kL/L with kL = 1.875 (the root of 1 + cos kL cosh kL = 0), so v_y(L) = V_f
// at the free end, v_y = v_y' = 0 at the clamp; v_y = 0 for s <= 0 (inside the clamp), v_x = 0.
// PySPH's Vf is a fraction of the sound speed (tip velocity Vf c0); here `velocity` is the tip
// velocity itself in m/s. Thin plates (thickness << length) only: the shape ignores shear. The
// formula lives with the references, in verification/CantileverModeShape; this adapter reads its
// dictionary and places the clamp.
//
// `sections plane` gives the mode's whole velocity in the beam's own kinematics (Euler-Bernoulli:
// plane sections stay normal to the axis), v_x = -(Y - Y0) v_y'(s), Y0 the neutral axis; the default
// `transverse` (v_x = 0, as Gray, Monaghan & Swift and PySPH) adds to the mode a shear-strain rate
// v_y'(s) across the whole thickness, which is no bending mode: at nu = 0.499 the {p,F,J} plate of
// tlSph (4 mm, jacobian (0 0.125)) damps that part at once, losing 0.50% of its energy in the first
// 0.02 s, against 0.10% with plane sections (issue 16; tutorials/tlSph/oscillatingPlate/README.md).
// The Poisson term of the thickness (v_y += nu/(1 - nu) (Y - Y0)^2/2 v_y'', plane strain) is left
// out: it changes that loss by less than 1e-5 of the energy.
//
//     keyword    meaning                                         required  default
//     length     L [m], > 0                                      yes
//     velocity   V_f, transverse velocity at the free end [m/s]  yes
//     thickness  plate thickness [m], 0 < thickness < length     no        (only checked)
//     kL         mode number k L                                 no        1.875
//     clampX     X of the clamped end [m]                        no        0
//     sections   transverse (v_x = 0) | plane (v_x = -(Y - Y0) v_y')  no        transverse
//     neutralAxis  Y0, the plate's mid-plane [m] (sections plane)  no        0
// 2D and 3D (transverse direction y).
#include "solver/CantileverMode.hpp"

#include <cmath>

namespace mfdyn {

template <int Dim>
CantileverMode<Dim>::CantileverMode(const Dictionary& dict) : InitialState<Dim>(dict) {
    // read in the order of the keyword table, as before the formula moved to verification/
    const double length = dict.get<double>("length");
    const double velocity = dict.get<double>("velocity");
    const double kL = dict.getOrDefault<double>("kL", 1.875);
    clampX_ = dict.getOrDefault<double>("clampX", 0.0);
    const std::string sections = dict.getOrDefault<std::string>("sections", "transverse");
    if (sections != "transverse" && sections != "plane")
        throw dict.error("sections",
                         "unknown sections '" + sections + "': valid are transverse (v_x = 0) and " +
                             "plane (the cross-sections rotate with the mode, v_x = -(Y - Y0) v_y')");
    planeSections_ = sections == "plane";
    neutralAxis_ = dict.getOrDefault<double>("neutralAxis", 0.0);
    if (!planeSections_ && dict.found("neutralAxis"))
        throw dict.error("neutralAxis", "neutralAxis is read with `sections plane` only");
    if (Dim < 2) throw dict.error("type", "cantileverMode needs a 2D or 3D case (the plate bends in y)");
    if (!(length > 0)) throw dict.error("length", "expected a positive length [m]");
    if (!(kL > 0)) throw dict.error("kL", "expected a positive mode number");
    if (auto thickness = dict.getOptional<double>("thickness"))
        if (!(*thickness > 0 && *thickness < length))
            throw dict.error("thickness", "expected 0 < thickness < length");
    if (!std::isfinite(velocity)) throw dict.error("velocity", "expected a finite velocity [m/s]");
    mode_.emplace(length, velocity, kL);
}

template <int Dim>
double CantileverMode<Dim>::transverseVelocity(double s) const {
    return mode_->transverseVelocity(s);
}

template <int Dim>
Vector<Dim> CantileverMode<Dim>::velocity(const Vector<Dim>& X) const {
    Vector<Dim> v = Vector<Dim>::Zero();
    if constexpr (Dim >= 2) {
        const double s = X(0) - clampX_;
        v(1) = transverseVelocity(s);
        if (planeSections_) v(0) = -(X(1) - neutralAxis_) * mode_->transverseVelocitySlope(s);
    }
    return v;
}

template class CantileverMode<1>;
template class CantileverMode<2>;
template class CantileverMode<3>;

MFDYN_REGISTER_DIM(
    InitialState, CantileverMode, "cantileverMode",
    "first bending mode velocity of a clamped plate (Gray, Monaghan & Swift 2001; PySPH oscillating_plate)");

}  // namespace mfdyn
