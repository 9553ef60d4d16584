#pragma once
#include "solver/BodyForce.hpp"

#include <array>

namespace mfdyn {

class UniformGravity final : public BodyForce {
public:
    UniformGravity(const Dictionary& dict, int dimension);
    static KeywordSchema keywords();
    void acceleration(const double* x, double t, double* a) const override;
    double potential(const double* x) const override;
    bool exactTrajectory(const double* x0, const double* v0, double tau, double* x, double* v) const override;

private:
    std::array<double, 3> g_{};
};

}  // namespace mfdyn
