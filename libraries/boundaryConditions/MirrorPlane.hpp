#pragma once
// `mirrorPlane`: a layer of mirror-image ghost particles behind a plane, made from the current
// state whenever the solver asks (impactSph: at its list rebuilds, or each step with
// `mirrorGhosts everyStep`).
#include "boundaryConditions/BoundaryCondition.hpp"
#include "boundaryConditions/Plane.hpp"

#include <optional>

namespace mfdyn {

template <int Dim>
class MirrorPlane : public BoundaryCondition<Dim> {
public:
    using typename BoundaryCondition<Dim>::VectorType;
    MirrorPlane(const Dictionary& dict, const ParticleSet<Dim>& particles);
    static KeywordSchema keywords();
    const Plane<Dim>& plane() const { return plane_; }
    bool noSlip() const { return noSlip_; }
    // The layer mirrored: `thickness`, else thicknessFactor * hMax.
    double thickness(double hMax) const { return thickness_ ? *thickness_ : thicknessFactor_ * hMax; }
    bool makesGhosts() const override { return true; }

    // The ghosts of the current state: one per selected particle with 0 < d < thickness(hMax)
    // (beyond the tolerance), in ascending source order.
    GhostBlock<Dim> ghosts(const ParticleSet<Dim>& particles, const std::vector<VectorType>& velocity,
                           double hMax) const;

protected:
    void ghostLayer(const ParticleSet<Dim>& particles, const std::vector<VectorType>& velocity, double hMax,
                    GhostBlock<Dim>& block) const override;

private:
    MirrorPlane(const KeywordValues& values, const ParticleSet<Dim>& particles);

    Plane<Dim> plane_;
    bool noSlip_;
    double thicknessFactor_;
    std::optional<double> thickness_;
};

}  // namespace mfdyn
