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
#include "solver/SolverRun.hpp"

#include <cmath>
#include <limits>

namespace mfdyn {

namespace {
template <int Dim>
std::unique_ptr<ParticleSet<Dim>> adopt(std::unique_ptr<ParticleSetBase> base) {
    particleSetCast<Dim>(*base);  // checks the dimension
    return std::unique_ptr<ParticleSet<Dim>>(static_cast<ParticleSet<Dim>*>(base.release()));
}
}  // namespace

template <int Dim>
ParticleFlightSolver<Dim>::ParticleFlightSolver(SolverRun& run)
    : Solver(run),
      particlesOwner_(adopt<Dim>(run.takeParticles())),
      particles_(particlesOwner_.get()),
      properties_(run.runCase().readConstant("particleFlightProperties")),
      bodyForce_(BodyForce::New(properties_.subDict("bodyForce"), Dim)),
      lengthScale_(properties_.get<double>("lengthScale")),
      x_(particles_->position()),
      v_(particles_->vectorField("velocity")),
      a_(particles_->vectorField("acceleration")) {
    if (!(lengthScale_ > 0)) throw properties_.error("lengthScale", "lengthScale must be positive");
    particles_->scalarField("mass");
    computeAcceleration(run.time().value());
}

template <int Dim>
void ParticleFlightSolver<Dim>::computeAcceleration(double t) {
    Stopwatch watch;
    parallelFor(x_.size(), [&](std::size_t i) { bodyForce_->acceleration(x_[i].data(), t, a_[i].data()); });
    forceSeconds_ += watch.seconds();
}

template <int Dim>
TimeStepVote ParticleFlightSolver<Dim>::stableTimeStep() {
    const double vmax = std::sqrt(Reduce::max(v_.size(), [&](std::size_t i) { return v_[i].squaredNorm(); }));
    TimeStepVote vote{std::numeric_limits<double>::infinity(), "Courant"};
    if (vmax > 0) vote.deltaT = time().maxCo() * lengthScale_ / vmax;
    if (auto force = bodyForce_->stableTimeStep(); force.deltaT < vote.deltaT) vote = force;
    return vote;
}

template <int Dim>
void ParticleFlightSolver<Dim>::step(double dt) {
    Stopwatch watch;
    const double t = time().value();
    parallelFor(x_.size(), [&](std::size_t i) {
        v_[i] += 0.5 * dt * a_[i];
        x_[i] += dt * v_[i];
    });
    kickDriftSeconds_ += watch.seconds();
    computeAcceleration(t + dt);
    watch.restart();
    parallelFor(x_.size(), [&](std::size_t i) { v_[i] += 0.5 * dt * a_[i]; });
    kickDriftSeconds_ += watch.seconds();
    checkFinite(t + dt);
}

template <int Dim>
void ParticleFlightSolver<Dim>::checkFinite(double t) const {
    const double bad = Reduce::sum<double>(
        x_.size(), [&](std::size_t i) { return (x_[i].allFinite() && v_[i].allFinite()) ? 0.0 : 1.0; });
    if (bad == 0) return;
    for (std::size_t i = 0; i < x_.size(); ++i) {
        if (x_[i].allFinite() && v_[i].allFinite()) continue;
        throw RunError("phase integrate, step " + std::to_string(time().timeIndex() + 1) +
                       ", t = " + std::to_string(t) + ": particle " +
                       std::to_string(particles_->globalId()[i]) + " (region " +
                       std::to_string(particles_->region()[i]) + ") has a non-finite position or velocity; " +
                       std::to_string(std::int64_t(bad)) + " particles affected");
    }
}

template <int Dim>
std::optional<double> ParticleFlightSolver<Dim>::potentialEnergy() const {
    const auto& m = particles_->template requireField<double>("mass");
    return Reduce::sum<double>(x_.size(),
                               [&](std::size_t i) { return m[i] * bodyForce_->potential(x_[i].data()); });
}

template <int Dim>
std::vector<std::pair<std::string, double>> ParticleFlightSolver<Dim>::phaseTimes() const {
    return {{"kickDrift", kickDriftSeconds_}, {"bodyForce", forceSeconds_}};
}

template class ParticleFlightSolver<1>;
template class ParticleFlightSolver<2>;
template class ParticleFlightSolver<3>;

}  // namespace mfdyn
