#pragma once
// particleFlight: particles in free flight under a body force, integrated by velocity Verlet.
// The framework's proving ground: its answer is known exactly for uniformGravity (and for
// harmonicTrap of the user-library template to second order in dt), so time control, writes,
// restart, function objects and user libraries can all be checked against a number.
//
// constant/particleFlightProperties:
//     bodyForce   { type uniformGravity; g (0 -9.81 0); }
//     lengthScale 0.01;    // m: Courant number Co = |v| dt / lengthScale
//
// Fields: position, velocity, mass (read), acceleration (made). Nothing else is allocated.
#include "solver/BodyForce.hpp"
#include "solver/Solver.hpp"

namespace mfdyn {

// The solver-independent face trajectoryError uses.
class BodyForceSolver {
public:
    virtual ~BodyForceSolver() = default;
    virtual const BodyForce& bodyForce() const = 0;
};

template <int Dim>
class ParticleFlightSolver final : public Solver, public BodyForceSolver {
public:
    explicit ParticleFlightSolver(SolverRun& run);

    // The keywords of constant/particleFlightProperties (solver/SolverRegistry.hpp).
    static constexpr const char* propertiesDictionary = "particleFlightProperties";
    static KeywordSchema keywords();

    TimeStepVote stableTimeStep() override;
    void step(double dt) override;
    ParticleSetBase& particles() override { return *particles_; }
    std::optional<double> potentialEnergy() const override;
    const BodyForce& bodyForce() const override { return *bodyForce_; }

private:
    void computeAcceleration(double t);
    void checkFinite() const;

    std::unique_ptr<ParticleSet<Dim>> particlesOwner_;
    ParticleSet<Dim>* particles_;
    const Dictionary& properties_;
    std::unique_ptr<BodyForce> bodyForce_;
    double lengthScale_;
    std::vector<Vector<Dim>>& x_;
    std::vector<Vector<Dim>>& v_;
    std::vector<Vector<Dim>>& a_;
};

extern template class ParticleFlightSolver<1>;
extern template class ParticleFlightSolver<2>;
extern template class ParticleFlightSolver<3>;

}  // namespace mfdyn
