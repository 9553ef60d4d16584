#pragma once
// `linearVelocity`: v = v0 + G (x - origin) on the selection, in the current positions x or the
// positions X of the run's start. Equations and usage in the .cpp.
#include "boundaryConditions/BoundaryCondition.hpp"

#include <vector>

namespace mfdyn {

template <int Dim>
class LinearVelocityCondition : public BoundaryCondition<Dim> {
public:
    using typename BoundaryCondition<Dim>::VectorType;
    LinearVelocityCondition(const Dictionary& dict, const ParticleSet<Dim>& particles);
    static KeywordSchema keywords();

    // The prescribed velocity at position p (current or start position, as `frame` says).
    VectorType velocityAt(const VectorType& p) const { return v0_ + gradient_ * (p - origin_); }
    std::string describe() const override;

protected:
    void velocityConstraint(ParticleSet<Dim>& particles, std::vector<VectorType>& v, double t) override;
    void accelerationConstraint(ParticleSet<Dim>& particles, std::vector<VectorType>& a, double t) override;
    void selectionUpdated(const ParticleSet<Dim>& particles) override;

private:
    LinearVelocityCondition(const Dictionary& dict, const KeywordValues& values,
                            const ParticleSet<Dim>& particles);

    VectorType v0_, origin_;
    Tensor<Dim> gradient_;
    bool initialFrame_ = false;
    std::vector<std::int64_t> ids_;          // the selection's global ids at the run's start (frame initial)
    std::vector<VectorType> startVelocity_;  // v0 + G (X - origin) of each, in the order of ids_
    std::vector<std::size_t> index_;         // their current indices
};

}  // namespace mfdyn
