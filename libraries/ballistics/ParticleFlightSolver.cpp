// Velocity Verlet (kick-drift-kick), second order, symplectic:
//
//   v_{n+1/2} = v_n + ½ a(x_n, t_n) dt
//   x_{n+1}   = x_n + v_{n+1/2} dt
//   v_{n+1}   = v_{n+1/2} + ½ a(x_{n+1}, t_{n+1}) dt
//
// (Verlet 1967; Swope, Andersen, Berens & Wilson 1982.) Exact for constant a.
#include "ballistics/ParticleFlightSolver.hpp"

#include "core/Log.hpp"
#include "core/Parallel.hpp"
#include "solver/SolverRegistry.hpp"
#include "solver/SolverRun.hpp"

#include <cmath>
#include <limits>

namespace mfdyn {

template <int Dim>
KeywordSchema ParticleFlightSolver<Dim>::keywords() {
    return KeywordSchema("solver", "particleFlight")
        .dictionary("bodyForce", "the body force on every particle (a bodyForce type)")
        .scalar("lengthScale", "m", "the length in the Courant number Co = |v| dt / lengthScale")
        .greaterThan(0);
}

template <int Dim>
ParticleFlightSolver<Dim>::ParticleFlightSolver(SolverRun& run)
    : Solver(run),
      particlesOwner_(adoptParticleSet<Dim>(run.takeParticles())),
      particles_(particlesOwner_.get()),
      properties_(openConstant("particleFlightProperties")),
      bodyForce_(BodyForce::New(keywords().read(properties_).dictionary("bodyForce"), Dim)),
      lengthScale_(properties_.get<double>("lengthScale")),
      x_(particles_->position()),
      v_(particles_->vectorField("velocity")),
      a_(particles_->vectorField("acceleration")) {
    declarePhases({"kickDrift", "bodyForce"});
    particles_->scalarField("mass");
    computeAcceleration(run.time().value());
}

template <int Dim>
void ParticleFlightSolver<Dim>::computeAcceleration(double t) {
    auto timed = phase("bodyForce");
    parallelFor(x_.size(), [&](std::size_t i) { bodyForce_->acceleration(x_[i].data(), t, a_[i].data()); });
}

template <int Dim>
TimeStepVote ParticleFlightSolver<Dim>::stableTimeStep() {
    // Global: the time-step vote every rank must agree on.
    const double vmax =
        std::sqrt(GlobalReduce::max(v_.size(), [&](std::size_t i) { return v_[i].squaredNorm(); }));
    TimeStepVote vote{std::numeric_limits<double>::infinity(), "Courant"};
    if (vmax > 0) vote.deltaT = time().maxCo() * lengthScale_ / vmax;
    if (auto force = bodyForce_->stableTimeStep(); force.deltaT < vote.deltaT) vote = force;
    return vote;
}

template <int Dim>
void ParticleFlightSolver<Dim>::step(double dt) {
    const double t = time().value();
    {
        auto timed = phase("kickDrift");
        parallelFor(x_.size(), [&](std::size_t i) {
            v_[i] += 0.5 * dt * a_[i];
            x_[i] += dt * v_[i];
        });
    }
    computeAcceleration(t + dt);
    {
        auto timed = phase("kickDrift");
        parallelFor(x_.size(), [&](std::size_t i) { v_[i] += 0.5 * dt * a_[i]; });
    }
    checkFinite();
}

template <int Dim>
void ParticleFlightSolver<Dim>::checkFinite() const {
    checkState(
        "integrate", x_.size(), [&](std::size_t i) { return !x_[i].allFinite() || !v_[i].allFinite(); },
        [&](std::size_t i, double count) {
            return "particle " + std::to_string(particles_->globalId()[i]) + " (region " +
                   std::to_string(particles_->region()[i]) + ") has a non-finite position or velocity; " +
                   std::to_string(std::int64_t(count)) + " particles affected";
        });
}

template <int Dim>
std::optional<double> ParticleFlightSolver<Dim>::potentialEnergy() const {
    const auto& m = particles_->template requireField<double>("mass");
    return GlobalReduce::sum<double>(
        x_.size(),  // a conservation sum: over every rank
        [&](std::size_t i) { return m[i] * bodyForce_->potential(x_[i].data()); });
}

template class ParticleFlightSolver<1>;
template class ParticleFlightSolver<2>;
template class ParticleFlightSolver<3>;

MFDYN_REGISTER_SOLVER(ParticleFlightSolver, "particleFlight",
                      "Particles in free flight under a body force, velocity Verlet");

}  // namespace mfdyn
