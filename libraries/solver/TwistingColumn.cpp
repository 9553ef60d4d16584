// twistingColumn: v(X) = omega(X) x (X - c), omega = Omega sin(pi s/(2L)) e_axis, s = (X - c).e_axis,
// u = 0: a column twisted by an angular velocity that grows from 0 at its clamped base (s = 0) to
// Omega at its free end (s = L). The formula lives with the references, in
// verification/TwistingColumnMotion; this adapter reads its dictionary.
//   Lee, Gil, Greto, Karim & Bonet 2016 section 8.9, Figs 24-28 (doc/methods/tl-jst-sph.md 8.9):
//   Omega = 105 rad/s, L = 6 m, axis Y, about the origin (the Fig 26 caption's Z is a typo).
//
//     keyword  meaning                                           required  default
//     Omega    angular velocity at s = L [rad/s]                 yes
//     length   L [m], > 0                                        yes
//     axis     X | Y | Z                                         no        Y
//     centre   c [m], a point of the axis (the base centre)      no        (0 0 0)
// 3D only.
#include "solver/TwistingColumn.hpp"

#include <string>

namespace mfdyn {

template <int Dim>
TwistingColumn<Dim>::TwistingColumn(const Dictionary& dict) : InitialState<Dim>(dict) {
    const double Omega = dict.get<double>("Omega");
    const double length = dict.get<double>("length");
    const Vector<Dim> centre = dict.getOrDefault<Vector<Dim>>("centre", Vector<Dim>::Zero());
    if (Dim != 3)
        throw dict.error("type",
                         "twistingColumn is a 3D initial state; this case is " + std::to_string(Dim) + "D");
    if (!(length > 0)) throw dict.error("length", "expected a positive length [m]");
    const std::string axisName = dict.getOrDefault<std::string>("axis", "Y");
    int axis = 1;
    if (axisName == "X" || axisName == "x")
        axis = 0;
    else if (axisName == "Y" || axisName == "y")
        axis = 1;
    else if (axisName == "Z" || axisName == "z")
        axis = 2;
    else
        throw dict.error("axis", "expected X, Y or Z, found '" + axisName + "'");
    if constexpr (Dim == 3) motion_.emplace(Omega, length, axis, centre);
}

template <int Dim>
Vector<Dim> TwistingColumn<Dim>::velocity(const Vector<Dim>& X) const {
    if constexpr (Dim != 3) {
        return Vector<Dim>::Zero();  // not constructible
    } else {
        return motion_->velocity(X);
    }
}

template class TwistingColumn<1>;
template class TwistingColumn<2>;
template class TwistingColumn<3>;

MFDYN_REGISTER_DIM(InitialState, TwistingColumn, "twistingColumn",
                   "v = Omega sin(pi Y/(2L)) e_Y x X: twisting column (Lee et al. 2016 8.9), 3D");

}  // namespace mfdyn
