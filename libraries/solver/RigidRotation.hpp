#pragma once
// initialState rigidRotation: v = omega x (X - c). See RigidRotation.cpp.
#include "solver/InitialState.hpp"

namespace mfdyn {

template <int Dim>
class RigidRotation final : public InitialState<Dim> {
public:
    explicit RigidRotation(const Dictionary& dict);
    Vector<Dim> velocity(const Vector<Dim>& X) const override;

private:
    Eigen::Vector3d omega_;
    Vector<Dim> centre_;
};

extern template class RigidRotation<1>;
extern template class RigidRotation<2>;
extern template class RigidRotation<3>;

}  // namespace mfdyn
