#pragma once
// A user model: the body force of an isotropic harmonic trap, added to mfdyn's bodyForce family
// from outside the toolkit.
#include <solver/BodyForce.hpp>

#include <array>

namespace myModels {

class HarmonicTrap final : public mfdyn::BodyForce {
public:
    HarmonicTrap(const mfdyn::Dictionary& dict, int dimension);
    void acceleration(const double* x, double t, double* a) const override;
    double potential(const double* x) const override;
    bool exactTrajectory(const double* x0, const double* v0, double tau, double* x, double* v) const override;
    mfdyn::TimeStepVote stableTimeStep() const override;

private:
    double omega_;
    std::array<double, 3> centre_{};
};

}  // namespace myModels
