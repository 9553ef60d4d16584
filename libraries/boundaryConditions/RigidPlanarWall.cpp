// rigidPlanarWall: a rigid, frictionless, unilateral wall (a target anvil, a floor). For the
// selected particles on or behind the plane (d = (x - point)·n <= tolerance):
//     position:      d < 0  ->  x <- x - d n                 (back onto the plane)
//     velocity:      v·n < 0 (approaching)  ->  v <- v - (1 + e) (v·n) n
//     acceleration:  a·n < 0 (pushed into it)  ->  a <- a - (a·n) n   (the wall's reaction)
// Receding particles (v·n >= 0) are untouched, so contact can open again. e is the coefficient
// of restitution: 0 (default) removes the approaching normal velocity (perfectly inelastic),
// 1 reflects it. This is the kinematic contact of a rigid body with a penalty-free constraint
// (Monaghan 1994's repulsive walls replaced by a projection, as in the velocity-reset walls of
// Zisis 2017 section 5.4); tangential velocity is kept (no friction).
// The velocity hook also puts crossed particles back on the plane, so a solver that constrains
// velocity only still never leaves a particle behind the wall for more than a drift.
//
// Usage: name { type rigidPlanarWall; point (0 0 0); normal (0 1 0);  [restitution 0;]
//               [tolerance 1e-9;] [regions (...); | shape { ... }] }   (default: all particles)
// The normal points into the material.
#include "boundaryConditions/RigidPlanarWall.hpp"

#include "core/Parallel.hpp"

namespace mfdyn {

template <int Dim>
KeywordSchema RigidPlanarWall<Dim>::keywords() {
    return KeywordSchema("boundaryCondition", "rigidPlanarWall")
        .append(planeKeywords())
        .scalar("restitution", "-",
                "coefficient of restitution e: 0 stops the approaching normal velocity, "
                "1 reflects it")
        .atLeast(0)
        .atMost(1)
        .orDefault(0.0)
        .append(commonBoundaryConditionKeywords());
}

template <int Dim>
RigidPlanarWall<Dim>::RigidPlanarWall(const Dictionary& dict, const ParticleSet<Dim>& particles)
    : RigidPlanarWall(keywords().read(dict), particles) {}

template <int Dim>
RigidPlanarWall<Dim>::RigidPlanarWall(const KeywordValues& values, const ParticleSet<Dim>& particles)
    : BoundaryCondition<Dim>(values, particles, true),
      plane_(values, particles.position()),
      restitution_(values.scalar("restitution")) {}

template <int Dim>
void RigidPlanarWall<Dim>::velocityConstraint(ParticleSet<Dim>& particles, std::vector<VectorType>& v,
                                              double) {
    auto& x = particles.position();
    const auto& idx = this->selection_.indices();
    const VectorType& n = plane_.normal();
    const double factor = 1.0 + restitution_;
    parallelFor(idx.size(), [&](std::size_t k) {
        const std::size_t i = idx[k];
        const double d = plane_.signedDistance(x[i]);
        if (d > plane_.tolerance()) return;
        if (d < 0.0) x[i] -= d * n;
        const double vn = v[i].dot(n);
        if (vn < 0.0) v[i] -= factor * vn * n;
    });
}

template <int Dim>
void RigidPlanarWall<Dim>::accelerationConstraint(ParticleSet<Dim>& particles, std::vector<VectorType>& a,
                                                  double) {
    const auto& x = particles.position();
    const auto& idx = this->selection_.indices();
    const VectorType& n = plane_.normal();
    parallelFor(idx.size(), [&](std::size_t k) {
        const std::size_t i = idx[k];
        if (!plane_.onOrBehind(x[i])) return;
        const double an = a[i].dot(n);
        if (an < 0.0) a[i] -= an * n;
    });
}

template <int Dim>
void RigidPlanarWall<Dim>::positionConstraint(ParticleSet<Dim>& particles, double) {
    auto& x = particles.position();
    const auto& idx = this->selection_.indices();
    parallelFor(idx.size(), [&](std::size_t k) {
        const std::size_t i = idx[k];
        if (plane_.signedDistance(x[i]) < 0.0) x[i] = plane_.project(x[i]);
    });
}

template class RigidPlanarWall<1>;
template class RigidPlanarWall<2>;
template class RigidPlanarWall<3>;

MFDYN_REGISTER_DIM(BoundaryCondition, RigidPlanarWall, "rigidPlanarWall",
                   "unilateral frictionless plane: stops approaching normal velocity, projects crossings");

}  // namespace mfdyn
