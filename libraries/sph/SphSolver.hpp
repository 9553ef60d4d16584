#pragma once
// impactSph: updated-Lagrangian SPH for shocks and impact through inhomogeneous media (Zisis 2017;
// the method as implemented is doc/methods/sph-impact.md). A step, in named phases:
//
//     updateNeighbours → computeEquationOfState → computeDensitySums (ω, ñ, ρ by summation)
//     → computeRates (dρ/dt, dv/dt, de/dt with dissipation) → integrate (leapfrog) → updateSmoothingLength
//
// constant/sphProperties:
//     kernel          { type gaussian; }                        // any registered kernel
//     densityScheme   { type number; form continuity; gradH yes; omegaMin 0.5; }  // ω floor at free surfaces
//     smoothingLength { type massDensity; eta 1.2; }
//     dissipation     { type riemann; velocity (1 2); density (0.5 2); energy (0.1 2); }
//     densityRateLimit 0.2;   // Δt ≤ ξ ρ/|dρ/dt| as well as the Courant limit (0: off)
//     neighbourSkin    0.2;   // Verlet skin as a fraction of the initial median support radius
//     mirrorGhosts     withList;      // or everyStep (the ghost layer and the list rebuilt each step)
//     momentum         variational;   // or difference (non-conservative, for comparison)
//     integrator       leapfrog;      // or predictorCorrector (midpoint rule, two rate evaluations)
//     courantSpeed     longitudinal;  // or bulk (the Courant limit on the equation of state's c alone)
//     artificialStress { epsilon 0.3; exponent 4; }   // against tensile instability (strength only)
//
// constant/materialProperties:  materials { name { equationOfState { type idealGas; gamma 1.4; }
//                                                  strength { type vonMises; } } }   // strength optional
//     (read by MaterialSet: an equation of state required, a strength law optional, a
//     constitutiveLaw refused)
// constant/boundaryConditions (optional; libraries/boundaryConditions): fixed, prescribedVelocity,
// symmetryPlane, rigidPlanarWall, mirrorPlane on regions or shapes; applied to accelerations after
// the rates, to velocities after each leapfrog update and to positions after the drift (mirrorPlane
// ghosts take part in every sum as read-only neighbours: positions mirrored, velocity and stress
// reflected, the rest copied from their source particle; the layer is built at neighbour-list
// rebuilds and re-placed from its sources in between, `mirrorGhosts withList`).
// Particles carry `material` (an index into the particle file's material names) or, without it,
// take the material named like their region, or the only material there is.
//
// Fields allocated: position, velocity, mass, density, pressure, soundSpeed, smoothingLength,
// material; specificInternalEnergy only when some equation of state needs it; omega when gradH;
// numberDensity when the smoothing-length law needs it; the leapfrog's half-step copies;
// deviatoricStress (and plasticStrain, temperature as the laws ask) only when a material has a
// strength law other than none: a hydrodynamic scene carries no stress and runs no stress terms.
//
// The health check (functionObjects/Health.hpp) sees: the time-step vote's particle (the argmin of
// the Courant or density-rate limit), the energy budget's D and W (measurePower in SphSolver.cpp:
// D the rates' loss from K + U, zero to round-off for this scheme, W the boundary conditions'
// work), and the indicators neighbourDeficiency, tensileInstability and hourglass (SphHealth.cpp).
#include "boundaryConditions/BoundaryConditionList.hpp"
#include "core/KeywordSchema.hpp"
#include "kernels/Kernel.hpp"
#include "kernels/KernelEvaluator.hpp"
#include "materials/MaterialSet.hpp"
#include "materials/equationOfState/EquationOfState.hpp"
#include "materials/strength/Strength.hpp"
#include "particles/NeighbourSearch.hpp"
#include "particles/VerletList.hpp"
#include "solver/Solver.hpp"
#include "sph/DensityScheme.hpp"
#include "sph/Dissipation.hpp"
#include "sph/SmoothingLengthLaw.hpp"
#include "sph/SphPairLoop.hpp"

#include <memory>
#include <vector>

namespace mfdyn {

class Decomposition;

template <int Dim>
class SphSolver final : public Solver {
public:
    // The keywords of constant/sphProperties (read through it; -describe, doc/models/solver).
    static KeywordSchema keywords();
    static constexpr const char* propertiesDictionary = "sphProperties";
    // Runs on several ranks (issue 21; SolverRun.hpp: runSolver).
    static constexpr bool runsOnSeveralRanks = true;

    explicit SphSolver(SolverRun& run);
    ~SphSolver() override;

    TimeStepVote stableTimeStep() override;
    void step(double dt) override;

    ParticleSetBase& particles() override { return *particles_; }
    std::optional<double> internalEnergy() const override;
    std::optional<double> schemeDissipation() const override;
    std::optional<double> externalWork() const override;
    // D and W as measured (SphSolver.cpp) close the budget to the time error: the imbalance is
    // O(dt^2) (doc/architecture.md, the health check), so health's energy-growth stop is on.
    bool energyBudgetCloses() const override { return true; }
    std::vector<HealthIndicator> healthIndicators() const override;
    std::string solverState() const override;
    void restoreSolverState(const Dictionary& state) override;
    std::vector<std::pair<std::string, double>> phaseTimes() const override;
    std::vector<std::string> summary(double loopSeconds) const override;

private:
    void readMaterials();
    void initialiseFields();
    void ensureRates();
    void addGhosts();
    void buildGhostLayer(double hMax, double t);
    void updateDecomposition();
    double medianSupport(const std::vector<double>& radius) const;
    bool placeKeptGhosts(const GhostBlock<Dim>& layer);
    void removeGhosts();
    void updateNeighbours();
    void computeEquationOfState();
    void computeKernelFactors();
    void selectNeighbours();
    void computeDensitySums();
    void solveSmoothingLength();
    void computeVelocityGradient();
    void computeStressRate();
    void returnToYieldSurface(std::vector<SymmTensor<Dim>>& tau, double dt);
    typename Strength<Dim>::Fields strengthFields(std::size_t i, SymmTensor<Dim>* tau);
    void computeRates();
    void updateSmoothingLength();
    void stepPredictorCorrector(double dt);
    void checkState(const char* phase) const;
    void measurePower(const std::vector<Vector<Dim>>& freeRates);
    double constrainVelocityWork(std::vector<Vector<Dim>>& v, double t);

    std::unique_ptr<ParticleSet<Dim>> owner_;
    ParticleSet<Dim>* particles_;
    const Dictionary& properties_;
    const Dictionary& materialProperties_;
    KeywordValues settings_;  // sphProperties through keywords()
    std::unique_ptr<Kernel> kernel_;
    KernelEvaluator<Dim> W_;
    std::unique_ptr<DensityScheme> scheme_;
    std::unique_ptr<SmoothingLengthLaw> hLaw_;
    std::unique_ptr<Dissipation> dissipation_;  // its pair terms run inside computeRates' loop
    double densityRateLimit_;
    // Per material, M of the Courant speed sqrt(c^2 + M/rho) (empty: c alone; SphSolver.cpp's head).
    std::vector<double> longitudinalStiffness_;
    double neighbourSkin_;
    double omegaMin_;
    bool differenceForm_;
    bool predictorCorrector_;
    bool ghostsEveryStep_;  // mirrorGhosts everyStep (see keptGhosts_)
    // Per material its equation of state (required) and strength law (optional; null when none or
    // one without stress); a constitutive law is refused (MaterialSet.hpp).
    MaterialSet<Dim> materials_;
    // Monaghan's artificial stress (Monaghan 2000; Gray, Monaghan & Swift 2001): ε, n; ε = 0 off.
    double artificialStressEpsilon_ = 0, artificialStressExponent_ = 4;
    std::vector<Tensor<Dim>> artificialStress_;

    std::vector<Vector<Dim>>& x_;
    std::vector<Vector<Dim>>& v_;
    std::vector<double>& m_;
    std::vector<double>& rho_;
    std::vector<double>& p_;
    std::vector<double>& c_;
    std::vector<double>& h_;
    std::vector<std::int64_t>& material_;
    std::vector<double>* e_ = nullptr;
    std::vector<double>* omega_ = nullptr;
    std::vector<double>* number_ = nullptr;
    // Leapfrog half-step state U^{k+1/2} (kept as fields: restart reads them back exactly).
    std::vector<Vector<Dim>>* vHalf_ = nullptr;
    std::vector<double>* rhoHalf_ = nullptr;
    std::vector<double>* eHalf_ = nullptr;
    // Strength (allocated only when some material has one): deviatoric stress τ, its half step,
    // and the history the laws ask for.
    std::vector<SymmTensor<Dim>>* tau_ = nullptr;
    std::vector<SymmTensor<Dim>>* tauHalf_ = nullptr;
    std::vector<double>* plasticStrain_ = nullptr;
    std::vector<double>* temperature_ = nullptr;
    std::vector<Tensor<Dim>> velocityGradient_;
    std::vector<SymmTensor<Dim>> dtaudt_;

    // Rates f^k and per-particle scheme coefficients (solver scratch, not fields).
    std::vector<Vector<Dim>> dvdt_;
    std::vector<double> drhodt_, dedt_, a_, b_, cc_;
    // Per-particle kernel factors of this step's h, so that a pair evaluates the kernel's shape
    // once per smoothing length and divides by nothing: with H = κh the kernel's support,
    // u = r/H = r·invH, W = wNorm·w(u), ∂W/∂h = dhNorm·(d·w + u·w'), dW/dr = gradNorm·w'(u).
    // The same products as KernelEvaluator's, so the values are bit-identical to its members.
    // volume_ = m/ρ. Ghosts included.
    std::vector<double> invH_, wNorm_, dhNorm_, gradNorm_, volume_;
    std::vector<double> pressureTerm_;  // a_j P_j/ω_j, scratch of computeRates
    std::vector<double> radius_;        // scratch of updateNeighbours
    bool gradientWithSums_ = false;     // the velocity gradient was computed in the density-sum loop
    // Candidate pairs within the support plus a skin, rebuilt only when particles have moved (or h
    // grown) by more than the skin allows; pairs beyond the support cost a kernel evaluation
    // that returns zero. neighbours_ points at the current list.
    std::unique_ptr<VerletList<Dim>> verlet_;
    BoundaryConditionList<Dim> boundaries_;
    // Mirror ghosts of this step live in the particle set's ghost range [ownedCount(), size())
    // while the rates are computed, and are cleared before anything else sees the particles.
    // With `mirrorGhosts withList` the same layer (keptGhosts_, built one support plus the skin
    // thick) is put back each step, so that the candidate list survives: ghostActive_ marks,
    // per particle, the owned ones and the kept ghosts this step's own layer has (the others are
    // left out of every sum); ghostOffset_ re-places a ghost the layer of this step lacks by the
    // affine image Q x_source + offset (a mirror keeps distances, so the skin test stays exact).
    GhostBlock<Dim> keptGhosts_;
    std::vector<Vector<Dim>> ghostOffset_;
    std::vector<char> ghostActive_;
    bool filterGhosts_ = false;  // some kept ghost is not in this step's layer
    bool ghostLayerKept_ = false;
    std::uint64_t topologyAfterGhosts_ = 0;  // the particle set's version after removeGhosts()
    std::size_t ghostLayerBuilds_ = 0;
    // Rows of the candidate list or, once selectNeighbours() has run this step, of the pairs
    // within either support (SphPairLoop.hpp).
    SphNeighbourRows neighbours_;
    std::vector<NeighbourList::Index> selected_, selectedCount_;
    std::size_t rebuilds_ = 0, neighbourUpdates_ = 0;
    double pairInteractions_ = 0;  // candidate pairs visited by the force loop, summed over steps
    bool ratesValid_ = false;
    // Several ranks (issue 21): the decomposition (SolverRun's), the fields its halo carries,
    // the owned positions at the last migration, the halo's width and the Verlet skin (global).
    Decomposition* decomposition_ = nullptr;
    std::vector<std::string> haloFields_;
    std::vector<Vector<Dim>> xAtMigration_;
    double haloWidth_ = 0, skin_ = -1;
    bool midStep_ = false;
    bool started_ = false;
    // The energy budget of the health check (SphSolver.cpp, measurePower): D and W since the
    // solver was constructed, the powers of the latest rate evaluation, and the leapfrog's step
    // whose trapezoid awaits the next evaluation's powers (pendingDt_ 0: none).
    double dissipated_ = 0, externalWork_ = 0;
    double dissipationPower_ = 0, constraintPower_ = 0;
    double pendingDt_ = 0, pendingDissipationPower_ = 0, pendingConstraintPower_ = 0;
    double previousDeltaT_ = 0;
};

extern template class SphSolver<1>;
extern template class SphSolver<2>;
extern template class SphSolver<3>;

}  // namespace mfdyn
