// symmetryPlane: v·n = 0 and (dv/dt)·n = 0 for the selected particles on or behind the plane
// (signed distance d <= tolerance), tangential components untouched:
//     v <- v - (v·n) n,   a <- a - (a·n) n;
// after the drift a particle found behind the plane (d < 0, round-off) is put back on it.
//   Lee et al. 2016 section 2.7 (doc/methods/tl-jst-sph.md 2.7): "roller or symmetry plane: normal
//   component = 0", applied to p and dp/dt on the boundary particles (the direct method).
// For an SPH fluid this alone leaves the kernel truncated at the plane; mirrorPlane adds the
// ghost layer that completes it.
//
// Usage: name { type symmetryPlane; point (0 0 0); normal (1 0 0);  [tolerance 1e-9;]
//               [regions (...); | shape { ... }]  }        (default selection: all particles)
// The normal points into the material.
#include "boundaryConditions/SymmetryPlane.hpp"

#include "core/Parallel.hpp"

namespace mfdyn {

template <int Dim>
KeywordSchema SymmetryPlane<Dim>::keywords() {
    return KeywordSchema("boundaryCondition", "symmetryPlane")
        .append(planeKeywords())
        .append(commonBoundaryConditionKeywords());
}

template <int Dim>
SymmetryPlane<Dim>::SymmetryPlane(const Dictionary& dict, const ParticleSet<Dim>& particles)
    : SymmetryPlane(keywords().read(dict), particles) {}

template <int Dim>
SymmetryPlane<Dim>::SymmetryPlane(const KeywordValues& values, const ParticleSet<Dim>& particles)
    : BoundaryCondition<Dim>(values, particles, true), plane_(values, particles.position()) {}

template <int Dim>
void SymmetryPlane<Dim>::removeNormal(const ParticleSet<Dim>& particles,
                                      std::vector<VectorType>& values) const {
    const auto& x = particles.position();
    const auto& idx = this->selection_.indices();
    const VectorType& n = plane_.normal();
    parallelFor(idx.size(), [&](std::size_t k) {
        const std::size_t i = idx[k];
        if (plane_.onOrBehind(x[i])) values[i] -= values[i].dot(n) * n;
    });
}

template <int Dim>
void SymmetryPlane<Dim>::velocityConstraint(ParticleSet<Dim>& particles, std::vector<VectorType>& v, double) {
    removeNormal(particles, v);
}

template <int Dim>
void SymmetryPlane<Dim>::accelerationConstraint(ParticleSet<Dim>& particles, std::vector<VectorType>& a,
                                                double) {
    removeNormal(particles, a);
}

template <int Dim>
void SymmetryPlane<Dim>::positionConstraint(ParticleSet<Dim>& particles, double) {
    auto& x = particles.position();
    const auto& idx = this->selection_.indices();
    parallelFor(idx.size(), [&](std::size_t k) {
        const std::size_t i = idx[k];
        if (plane_.signedDistance(x[i]) < 0.0) x[i] = plane_.project(x[i]);
    });
}

template class SymmetryPlane<1>;
template class SymmetryPlane<2>;
template class SymmetryPlane<3>;

MFDYN_REGISTER_DIM(BoundaryCondition, SymmetryPlane, "symmetryPlane",
                   "normal velocity and acceleration = 0 on or behind a plane (symmetry, roller)");

}  // namespace mfdyn
