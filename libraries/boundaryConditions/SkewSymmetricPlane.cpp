// skewSymmetricPlane: the tangential components of the velocity and of its rate are zero on the
// particles lying on a plane, the normal component is free:
//     v <- (v·n) n,   a <- (a·n) n.
//   Lee, Gil, Greto, Karim & Bonet 2016 section 2.7 (doc/methods/tl-jst-sph.md 2.7, "skew-symmetric:
//   tangential components = 0"), applied to p and dp/dt by the direct method; section 8.2, the
//   swinging cube, has it on the faces X = 1, Y = 1, Z = 1 (rollers, symmetryPlane, on the others).
//
// The particles on the plane are picked once, when the condition is built: the selected ones
// (default: all) with |(x − point)·n| <= tolerance, x being the vector field
// `referencePosition` when the particle set has one (a total-Lagrangian solver's reference
// configuration, so that a restart picks the same particles) and `position` otherwise. They are
// kept by globalId: they move off the plane along n, so a side test each step would lose them.
// A particle the solver removes drops out. No particle on the plane is an input error.
//
// Usage: name { type skewSymmetricPlane; point (1 0 0); normal (-1 0 0);  [tolerance 1e-9;]
//               [regions (...); | shape { ... }]  [releaseTime t;] }
// `tolerance` [m]: default 1e-9 times the extent of the particle set (Plane.hpp). The normal's
// sense does not matter here.
#include "boundaryConditions/SkewSymmetricPlane.hpp"

#include "core/Parallel.hpp"

#include <cmath>

namespace mfdyn {

template <int Dim>
KeywordSchema SkewSymmetricPlane<Dim>::keywords() {
    return KeywordSchema("boundaryCondition", "skewSymmetricPlane")
        .append(planeKeywords())
        .append(commonBoundaryConditionKeywords());
}

template <int Dim>
SkewSymmetricPlane<Dim>::SkewSymmetricPlane(const Dictionary& dict, const ParticleSet<Dim>& particles)
    : SkewSymmetricPlane(keywords().read(dict), particles) {}

template <int Dim>
SkewSymmetricPlane<Dim>::SkewSymmetricPlane(const KeywordValues& values, const ParticleSet<Dim>& particles)
    : BoundaryCondition<Dim>(values, particles, true),
      plane_(values, particles.referenceOrCurrentPosition()) {
    const auto& x = particles.referenceOrCurrentPosition();
    const auto& id = particles.globalId();
    for (const std::size_t i : this->selection_.indices())
        if (std::abs(plane_.signedDistance(x[i])) <= plane_.tolerance()) {
            indices_.push_back(i);
            ids_.push_back(id[i]);
        }
    // On any rank: the plane may lie in another rank's part of the body.
    if (globalSum(double(indices_.size())) == 0 && globalSum(double(this->selection_.indices().size())) > 0)
        throw values.error("point",
                           "no selected particle lies on the plane (|signed distance| <= tolerance " +
                               std::to_string(plane_.tolerance()) +
                               " m); check `point` and `normal`, or give a larger `tolerance`");
}

template <int Dim>
std::string SkewSymmetricPlane<Dim>::describe() const {
    return BoundaryCondition<Dim>::describe() + ", " +
           std::to_string(globalSum(std::size_t(indices_.size()))) + " on the plane";
}

template <int Dim>
void SkewSymmetricPlane<Dim>::selectionUpdated(const ParticleSet<Dim>& particles) {
    const auto index = this->indicesOf(particles, ids_);
    std::vector<std::int64_t> ids;
    indices_.clear();
    for (std::size_t k = 0; k < ids_.size(); ++k)
        if (index[k] != this->npos) {
            indices_.push_back(index[k]);
            ids.push_back(ids_[k]);
        }
    ids_ = std::move(ids);
}

template <int Dim>
void SkewSymmetricPlane<Dim>::keepNormal(std::vector<VectorType>& values) const {
    const VectorType& n = plane_.normal();
    parallelFor(indices_.size(), [&](std::size_t k) {
        const std::size_t i = indices_[k];
        values[i] = values[i].dot(n) * n;
    });
}

template <int Dim>
void SkewSymmetricPlane<Dim>::velocityConstraint(ParticleSet<Dim>&, std::vector<VectorType>& v, double) {
    keepNormal(v);
}

template <int Dim>
void SkewSymmetricPlane<Dim>::accelerationConstraint(ParticleSet<Dim>&, std::vector<VectorType>& a, double) {
    keepNormal(a);
}

template class SkewSymmetricPlane<1>;
template class SkewSymmetricPlane<2>;
template class SkewSymmetricPlane<3>;

MFDYN_REGISTER_DIM(BoundaryCondition, SkewSymmetricPlane, "skewSymmetricPlane",
                   "tangential velocity and acceleration = 0 on the particles lying on a plane at start");

}  // namespace mfdyn
