#pragma once
// The exact essential boundary conditions of Lee et al. 2016 App. B (doc/methods/tl-jst-sph.md 2.7, optional
// step (9) of Algorithm 1): SPH kernels do not interpolate, so setting dp/dt on the boundary
// particles (the direct method) does not make the kernel interpolant of the rate take the
// prescribed value there. This projection changes ALL rates in the V-weighted least-squares sense,
//
//   minimise 1/2 sum_a V_a |pdot~_a - pdot_a|^2  subject to, for every constrained particle B,
//   C_B [ sum_a V_a pdot~_a W~_a(X_B) - pdot_B^pres ] = 0                                   (B.1)
//   [and, projectConservingMomentum: sum_a V_a pdot~_a, sum_a V_a x~_a x pdot~_a unchanged]  (B.2)
//
// with W~ the corrected kernel (doc/methods/tl-jst-sph.md 2.2 (b)), the sum over B itself and its neighbours,
// and C_B the orthogonal projector onto B's constrained directions:
//   fixed (clamped), prescribedVelocity      I
//   symmetryPlane (roller)                   n n^T
//   skewSymmetricPlane                       I - n n^T
// (a particle in two conditions: the projector onto the span of both ranges).
// The solution is pdot~_a = pdot_a + sum_B W~_a(X_B) C_B lambda_B [+ lambda_lin + lambda_ang x x~_a]
// with the multipliers from a sparse symmetric positive definite system that depends only on the
// reference configuration and the constrained set: it is assembled and factorised (sparse LDL^T)
// once, at construction; a call costs one right-hand side and one back-substitution (plus 1, 3
// or 6 more in 1D, 2D, 3D for the momentum variant). The derivation is at the top of the .cpp.
//
// Rates are dp/dt per unit reference volume (force densities). For prescribedVelocity the
// prescribed rate is rho0 d v_pres/dt (zero for a constant velocity, the paper's dp/dt = 0); for
// the other conditions it is zero (prescribedRates() builds the list).
//
// Mirror ghosts: the operators may hold them after the real particles; they are never
// constrained or modified, and every sum here runs over the real particles only (a ghost
// neighbour of B is left out of its interpolant).
//
// Usage (in the solver, once after the operators are built with options.correctedKernel = true):
//     LagrangeMultiplierProjection<Dim> lm(*operators_, V_, constraintsFrom(boundaries_, *particles_), n);
//     ... per stage, after the direct constraints on dp/dt:
//     lm.project(pdot, prescribedRates(boundaries_, lm.constraints(), rho0_, t));
// Single process: the constrained set is assumed to be on this process (no MPI reduction).
#include "boundaryConditions/BoundaryConditionList.hpp"
#include "core/Tensor.hpp"
#include "meshfreeOperators/ReferenceOperators.hpp"
#include "particles/ParticleSet.hpp"

#include <cstddef>
#include <limits>
#include <memory>
#include <vector>

namespace mfdyn {

template <int Dim>
class LagrangeMultiplierProjection {
public:
    // C_B: a symmetric projector (C^2 = C); its rank is the number of constrained directions.
    struct Constraint {
        std::size_t particle;
        Tensor<Dim> projector;
    };
    static constexpr std::size_t allParticles = std::size_t(-1);

    // operators: built with options.correctedKernel = true; volume: V (size >= operators.size()).
    // realParticles: how many of the operators' particles are real (the rest are mirror ghosts);
    // default all. Every rate array passed later must have exactly this size. Constraints on the
    // same particle twice, on a ghost, or with a projector that is not one are an Error, as is a
    // set whose interpolation conditions are linearly dependent (singular system).
    LagrangeMultiplierProjection(const ReferenceOperators<Dim>& operators, const std::vector<double>& volume,
                                 std::vector<Constraint> constraints,
                                 std::size_t realParticles = allParticles);
    ~LagrangeMultiplierProjection();
    LagrangeMultiplierProjection(LagrangeMultiplierProjection&&) noexcept;
    LagrangeMultiplierProjection& operator=(LagrangeMultiplierProjection&&) noexcept;

    // Number of constrained particles, and of multipliers (the sum of the projectors' ranks).
    std::size_t size() const { return constraints_.size(); }
    std::size_t unknowns() const { return unknowns_; }
    std::size_t realParticles() const { return n_; }
    const std::vector<Constraint>& constraints() const { return constraints_; }

    // rate: dp/dt per reference volume of the n real particles, modified in place; prescribed:
    // pdot^pres at each constraint, in the order of constraints() (only C_B pdot^pres matters).
    // Particles outside the support of every constrained particle are not touched.
    void project(std::vector<Vector<Dim>>& rate, const std::vector<Vector<Dim>>& prescribed) const;
    // The same with (B.2): the total force sum V rate and the total moment sum V x~ x rate are kept
    // (x~: the positions of the stage, doc/methods/tl-jst-sph.md 2.5). Every particle changes.
    void projectConservingMomentum(std::vector<Vector<Dim>>& rate, const std::vector<Vector<Dim>>& prescribed,
                                   const std::vector<Vector<Dim>>& xTilde) const;

    // sum_a V_a rate_a W~_a(X_B) for each constraint B (the kernel interpolant at X_B).
    std::vector<Vector<Dim>> interpolate(const std::vector<Vector<Dim>>& rate) const;
    // max_B |C_B (interpolate(rate)_B - prescribed_B)| / max(1, max_B |prescribed_B|, max_a |rate_a|).
    double residual(const std::vector<Vector<Dim>>& rate, const std::vector<Vector<Dim>>& prescribed) const;

private:
    struct Factorisation;
    void checkSizes(const std::vector<Vector<Dim>>& rate, const std::vector<Vector<Dim>>& prescribed) const;
    // r_i = Q_i^T (prescribed_i - interpolant_i), stacked.
    std::vector<double> rightHandSide(const std::vector<Vector<Dim>>& rate,
                                      const std::vector<Vector<Dim>>& prescribed) const;
    // rate_a += sum_i w_ia Q_i mu_i over the particles in some constraint's stencil.
    void addMultipliers(std::vector<Vector<Dim>>& rate, const std::vector<double>& mu) const;

    std::size_t n_ = 0;
    std::size_t unknowns_ = 0;
    std::vector<Constraint> constraints_;
    std::vector<double> V_;  // of the real particles
    // Per constraint i: orthonormal basis Q_i of range(C_i) (first rank_[i] columns), offset of
    // its multipliers, and its stencil (a, w_ia = W~_a(X_B)) over the real particles, CSR.
    std::vector<Tensor<Dim>> basis_;
    std::vector<int> rank_;
    std::vector<std::size_t> offset_;
    std::vector<std::size_t> stencilStart_;
    std::vector<std::size_t> stencilParticle_;
    std::vector<double> stencilWeight_;
    // The transposed stencils, CSR over the real particles: the constraints (i, w_ia) reaching a;
    // touched_ lists the particles with at least one.
    std::vector<std::size_t> touched_;
    std::vector<std::size_t> reachStart_;
    std::vector<std::size_t> reachConstraint_;
    std::vector<double> reachWeight_;
    std::unique_ptr<Factorisation> factorisation_;
};

// The constraints of the essential conditions of `bcs` active at time t (default: all), sorted by
// particle: fixed and prescribedVelocity (projector I) on their selection, symmetryPlane (n n^T) on
// the selected particles with |signed distance| <= the plane's tolerance, skewSymmetricPlane
// (I - n n^T) on its onPlane() particles. Positions are `referencePosition` when the set has it,
// else `position`. A particle in several conditions gets the projector onto the span of their
// ranges (eigenvectors of the sum of the projectors with eigenvalue > 1e-6: two rollers at
// right angles make n1 n1^T + n2 n2^T, a roller and a clamp make I). The constrained set changes
// when a condition's releaseTime passes: the solver then builds the projection again.
template <int Dim>
std::vector<typename LagrangeMultiplierProjection<Dim>::Constraint> constraintsFrom(
    const BoundaryConditionList<Dim>& bcs, const ParticleSet<Dim>& particles,
    double t = -std::numeric_limits<double>::infinity());

// pdot^pres for each constraint at time t: rho0_B d v_pres/dt (t) for a particle of an active
// prescribedVelocity condition (the last one in the list when several), zero otherwise.
template <int Dim>
std::vector<Vector<Dim>> prescribedRates(
    const BoundaryConditionList<Dim>& bcs,
    const std::vector<typename LagrangeMultiplierProjection<Dim>::Constraint>& constraints,
    const std::vector<double>& rho0, double t);

// The orthogonal projector onto range(A) + range(B) of two projectors.
template <int Dim>
Tensor<Dim> projectorUnion(const Tensor<Dim>& a, const Tensor<Dim>& b);

extern template class LagrangeMultiplierProjection<1>;
extern template class LagrangeMultiplierProjection<2>;
extern template class LagrangeMultiplierProjection<3>;

}  // namespace mfdyn
