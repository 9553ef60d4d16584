// rigidRotation: v(X) = omega x (X - c), u = 0: a rigid spin about c.
//   Lee, Gil, Greto, Karim & Bonet 2016 section 8.3 (doc/methods/tl-jst-sph.md 8.3), the spinning cube.
//
//     keyword  meaning                                                       required  default
//     omega    angular velocity [rad/s]: (wx wy wz) in 3D; in 2D a scalar     yes
//              (about z) or (0 0 wz)
//     centre   c [m]                                                          no        0
// 2D and 3D only (a 1D case has no rotation: an InputError).
#include "solver/RigidRotation.hpp"

#include <Eigen/Geometry>

namespace mfdyn {

template <int Dim>
RigidRotation<Dim>::RigidRotation(const Dictionary& dict)
    : InitialState<Dim>(dict), centre_(dict.getOrDefault<Vector<Dim>>("centre", Vector<Dim>::Zero())) {
    if constexpr (Dim == 1) {
        throw dict.error("type", "rigidRotation needs a 2D or 3D case");
    } else if constexpr (Dim == 2) {
        const Entry& e = dict.entry("omega");
        if (e.tokens.size() == 1 && e.tokens[0].isNumber()) {
            omega_ = Eigen::Vector3d(0, 0, dict.get<double>("omega"));
        } else {
            const auto w = dict.get<std::vector<double>>("omega");
            if (w.size() != 3 || w[0] != 0 || w[1] != 0)
                throw dict.error("omega", "in 2D, expected a scalar (rotation about z) or (0 0 wz)");
            omega_ = Eigen::Vector3d(0, 0, w[2]);
        }
    } else {
        omega_ = dict.get<Eigen::Vector3d>("omega");
    }
}

template <int Dim>
Vector<Dim> RigidRotation<Dim>::velocity(const Vector<Dim>& X) const {
    Eigen::Vector3d r = Eigen::Vector3d::Zero();
    for (int k = 0; k < Dim; ++k) r(k) = X(k) - centre_(k);
    const Eigen::Vector3d v = omega_.cross(r);
    return v.template head<Dim>();
}

template class RigidRotation<1>;
template class RigidRotation<2>;
template class RigidRotation<3>;

MFDYN_REGISTER_DIM(InitialState, RigidRotation, "rigidRotation",
                   "v = omega x (X - centre): spinning cube (Lee et al. 2016 8.3)");

}  // namespace mfdyn
