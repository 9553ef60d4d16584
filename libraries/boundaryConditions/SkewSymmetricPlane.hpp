#pragma once
// `skewSymmetricPlane`: on the particles lying on a plane the tangential motion is zero and the
// normal motion free, v <- (v·n) n (the swinging cube's faces X = 1, Y = 1, Z = 1).
//
// The particles move off the plane along its normal, so they cannot be found again by a side
// test each step (as symmetryPlane does): they are picked ONCE, when the condition is built,
// as the selected particles with |signed distance| <= tolerance, and kept by globalId from then
// on (through reorders; see selectionUpdated). See SkewSymmetricPlane.cpp.
#include "boundaryConditions/BoundaryCondition.hpp"
#include "boundaryConditions/Plane.hpp"

#include <cstdint>
#include <string>
#include <vector>

namespace mfdyn {

template <int Dim>
class SkewSymmetricPlane : public BoundaryCondition<Dim> {
public:
    using typename BoundaryCondition<Dim>::VectorType;
    SkewSymmetricPlane(const Dictionary& dict, const ParticleSet<Dim>& particles);
    static KeywordSchema keywords();
    const Plane<Dim>& plane() const { return plane_; }
    // Mirrored by a total-Lagrangian method with parity -1 (the odd extension) (GhostBlock.hpp).
    const Plane<Dim>* referenceMirror(double& parity) const override {
        parity = -1.0;
        return &plane_;
    }
    // Current indices of the particles picked on the plane.
    const std::vector<std::size_t>& onPlane() const { return indices_; }
    std::string describe() const override;

protected:
    void velocityConstraint(ParticleSet<Dim>& particles, std::vector<VectorType>& v, double) override;
    void accelerationConstraint(ParticleSet<Dim>& particles, std::vector<VectorType>& a, double) override;
    void selectionUpdated(const ParticleSet<Dim>& particles) override;

private:
    SkewSymmetricPlane(const KeywordValues& values, const ParticleSet<Dim>& particles);

    void keepNormal(std::vector<VectorType>& values) const;
    Plane<Dim> plane_;
    std::vector<std::int64_t> ids_;     // globalId of the particles on the plane
    std::vector<std::size_t> indices_;  // their current indices
};

}  // namespace mfdyn
