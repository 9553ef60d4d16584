#pragma once
// tlSph: total-Lagrangian mixed {p, F, H, J} SPH with JST stabilisation for large-strain solid
// dynamics (Lee, Gil, Greto, Kulasegaram, Bonet 2016; the method as implemented is
// doc/methods/tl-jst-sph.md). Every operator lives on the reference configuration X and
// its neighbours are found once (meshfreeOperators/ReferenceOperators.hpp). A step is the
// two-stage TVD Runge-Kutta of Algorithm 1, each stage in named phases:
//
//     computeStress (P from F, H, J) -> computeRates (G, T, L[p], L[J]) -> dissipation (L^2)
//     -> projections (momentum of T and D(p), mean of D(J)) -> boundary conditions -> update
//
// constant/tlSphProperties:
//     formulation pFJ;                           // pF | pFJ | pFHJ | displacement (a solver option)
//     kernel      { type wendlandC2; }           // any registered kernel (support 2h)
//     smoothingLengthRatio 1.3;                  // h = ratio x spacing (default 1.3)
//     spacing     0.05;                          // optional: particle spacing (default: largest V^(1/d))
//     gradient    corrected;                     // corrected | uncorrected | correctedKernel
//                                                // (default correctedKernel under lagrangeMultiplier)
//     dissipation { type jst; momentum (0 0.125); jacobian (0 0); }   // family dissipation (tlSph)
//     projection  { momentum yes; dissipation yes; jacobian yes; }    // the conservation projections
//     waveSpeed   current;                       // c_p scaled by the largest stretch of F, H (or reference)
//     bodyForce   { type uniformGravity; g (0 -9.81 0); }   // optional: E = rho0 a(x, t)
//     mirrorGhosts yes;                          // mirror the body across symmetry/skew planes
//     essentialBoundaryConditions direct;        // or lagrangeMultiplier (App. B; mirrorGhosts no)
//     initialState { type swingingCube; amplitude 5e-4; }   // optional, applied at a fresh start
//     energyGrowthLimit 1.5;                     // stop when the energy exceeds 1.5 x the energy put in
//
// system/controlDict: maxCo 0.3;                 // dt = maxCo h_min / c_p,max (default 0.3 here)
//
// constant/materialProperties: materials { name { rho0 ..; youngsModulus ..; poissonRatio ..;
//                                                 constitutiveLaw { type neoHookean; } } }
// constant/boundaryConditions (optional; libraries/boundaryConditions): fixed (clamped),
// symmetryPlane (roller), skewSymmetricPlane, prescribedVelocity (with releaseTime),
// prescribedTraction, free - imposed directly on the particles' momentum and its rate.
//
// Fields: position x, referencePosition X, velocity v (p = rho0 v), mass, density (rho0, never
// changed: V = m / rho0), material, smoothingLength (uniform, for sampling), deformationGradient F,
// firstPiolaStress P, pressure; jacobian J only when the formulation evolves it, cofactor H only for pFHJ;
// plasticDeformation, plasticStrain only when a material's law has plastic state. Dim < 3 is plane strain
// (2D) or uniaxial strain (1D): the laws see F embedded in 3x3 with unit out-of-plane stretch.
#include "boundaryConditions/BoundaryConditionList.hpp"
#include "kernels/Kernel.hpp"
#include "materials/MaterialSet.hpp"
#include "meshfreeOperators/ReferenceOperators.hpp"
#include "solver/BodyForce.hpp"
#include "solver/Solver.hpp"
#include "tlSph/LagrangeMultiplierProjection.hpp"
#include "tlSph/TlDissipation.hpp"

#include <memory>
#include <optional>
#include <vector>

namespace mfdyn {

class Decomposition;

template <int Dim>
class TlSphSolver final : public Solver {
public:
    explicit TlSphSolver(SolverRun& run);
    // Several ranks (issue 21): the body is cut once in the reference configuration and each rank
    // holds a halo two supports deep, planned once (TlSphSolver.cpp, "Several ranks").
    static constexpr bool runsOnSeveralRanks = true;
    // The keywords of constant/tlSphProperties (-describe, doc/models/solver/tlSph.md) and of its
    // `projection` sub-dictionary.
    static KeywordSchema keywords();
    static KeywordSchema projectionKeywords();
    static constexpr const char* propertiesDictionary = "tlSphProperties";

    // Which fields `formulation <name>;` evolves (TlSphSolver.cpp: why it is a solver option).
    struct Formulation {
        std::string name_;
        bool F, H, J;
        const std::string& name() const { return name_; }
        bool evolvesF() const { return F; }
        bool evolvesH() const { return H; }
        bool evolvesJ() const { return J; }
        bool displacementBased() const { return !F; }
    };
    static Formulation formulationNamed(const std::string& name);
    ~TlSphSolver() override;

    TimeStepVote stableTimeStep() override;
    void step(double dt) override;
    ParticleSetBase& particles() override { return *particles_; }
    std::optional<double> internalEnergy() const override;
    // The energy budget's two other terms, each since construction (TlSphSolver.cpp, the energy
    // budget): the energy the stabilisation and the projections removed from K + U, and the work
    // of the boundary conditions and body forces.
    // The stabilisation's and the plastic flow's (TlSphSolver.cpp, the energy budget).
    std::optional<double> schemeDissipation() const override { return schemeDissipation_ + plasticDissipation_; }
    std::optional<double> externalWork() const override { return externalWork_; }
    // hourglass, neighbourDeficiency, compression (TlSphSolver.cpp; TlSphHealth.hpp).
    std::vector<HealthIndicator> healthIndicators() const override;
    std::vector<std::string> summary(double loopSeconds) const override;

    // Sigma V |L[p]| h^2 / Sigma V |p| over the particles (p the pressure): the pressure
    // oscillation measure of the near-incompressible cases (checkerboarding raises it).
    double pressureOscillation() const;
    // max_a |F_a - I - grad~(x - X)_a| / max(1, |F|): how far the evolved F is from the discrete
    // gradient of the positions (round-off for pF without boundary conditions).
    double compatibilityError() const;

private:
    // keywords().read(), after refusing the old dictionary form of `formulation`.
    static KeywordValues readSettings(const Dictionary& properties);
    void readMaterials();
    void initialiseFields();
    void makeMirrorGhosts();
    // The mirror ghosts on the particle set's ghost range, their fields mapped (GhostBlock.hpp);
    // computeRates clears them after its pair loop.
    void placeGhosts();
    // Scratch `field` of the n owned particles extended by the halo (its owners' values, under
    // MPI) and its images at the ghosts, field[n + halo + g] = map(g, field[source of g]).
    // Collective under MPI.
    template <class T, class Map>
    void imagesOf(std::vector<T>& field, std::size_t n, Map&& map) const;
    void computeStress(bool updateState);
    void computeDisplacementGradient();
    void computeRates(const std::vector<Vector<Dim>>& xTilde, double t);
    void checkState(const char* phase) const;
    // Kinetic + internal energy of the whole body, and the energy-growth check (TlSphSolver.cpp).
    double totalEnergy() const;
    void checkEnergyGrowth() const;
    Tensor<3> cofactor3(std::size_t i) const;
    const ConstitutiveLaw& law(std::size_t material) const {
        return *(*materials_)[material].constitutiveLaw;
    }
    // controlDict's maxCo, or the method's 0.3 (Lee et al. 2016's alpha_CFL) when it gives none.
    double courant() const { return time().maxCo(0.3); }

    std::unique_ptr<ParticleSet<Dim>> owner_;
    ParticleSet<Dim>* particles_;
    // Several ranks: SolverRun's decomposition (null on one process), the halo's size (0 on one
    // process: every index below then reads as in a serial run), the fields each stage's halo
    // carries, and the operators' order keys of [owned][halo][images] (ReferenceOperators::Options).
    Decomposition* decomposition_ = nullptr;
    std::size_t haloSize_ = 0;
    std::vector<std::string> haloFields_;
    std::vector<std::int64_t> order_;
    const Dictionary& properties_;
    const Dictionary& materialProperties_;
    const KeywordValues settings_;  // tlSphProperties read through keywords()
    std::unique_ptr<Kernel> kernel_;
    Formulation formulation_;
    std::unique_ptr<TlDissipation> dissipationModel_;
    std::unique_ptr<MaterialSet<Dim>> materials_;  // a constitutive law per material
    std::unique_ptr<ReferenceOperators<Dim>> operators_;
    BoundaryConditionList<Dim> boundaries_;
    // `essentialBoundaryConditions lagrangeMultiplier`: step 9 of Algorithm 1, built for the
    // conditions active at essentialTime_.
    std::unique_ptr<LagrangeMultiplierProjection<Dim>> essential_;
    double essentialTime_ = 0;
    // The particles of the active fixed conditions (the clamp): their J follows their F (no
    // D(J)), as of kinematicTime_ (updateKinematic: why).
    std::vector<char> kinematic_;
    bool kinematicBuilt_ = false;
    // The operators of D(J) on the body without those particles (real and ghost, free[s] their
    // index in n + ghosts), so that L[J] is exact on linear J at the clamp's face as at a free
    // surface. Null without kinematic particles (D(J) then uses operators_).
    std::unique_ptr<ReferenceOperators<Dim>> freeOperators_;
    std::vector<std::size_t> free_;
    // Per material, {p,F,J} only: the law is evaluated at J = det F and P += (p(J) - p(det F)) H
    // (readMaterials: why and which laws).
    std::vector<char> splitJacobian_;
    double kinematicTime_ = 0;
    void updateKinematic(double t);
    void freeJacobianLaplacians();
    bool projectMomentum_ = true, projectDissipation_ = true, projectJacobian_ = true;
    bool currentWaveSpeed_ = true;
    std::optional<double> deformedCourant_;  // tlSphProperties' deformedCourant, when given
    // The energy-growth check: tlSphProperties' energyGrowthLimit, the energy at this run's first
    // step, the work put in since, the largest energy put in so far (initial + work), the power
    // of the last stage's external forces, the fastest particle's speed at the start.
    double energyGrowthLimit_ = 1.5;
    std::optional<double> energyStart_;
    double externalWork_ = 0, energyInput_ = 0, stagePower_ = 0, startSpeed_ = 0;
    // The energy budget (TlSphSolver.cpp): the energy the scheme removed since construction, the
    // last stage's dissipation power, per particle of a stage V_a (v_a . (-T_a) - Sigma_J,a D(J)_a),
    // and per material how D(J) changes its stored energy (1: at dU/dJ, the law's pressure; 0: the
    // law's energy does not read the evolved J; -1: neither, D(J)'s work left out of the budget).
    double schemeDissipation_ = 0, stageDissipation_ = 0;
    double plasticDissipation_ = 0;    // summed returns' loss W_trial - W (J)
    std::vector<double> plasticLoss_;  // per particle, the latest return's loss
    std::vector<double> stageWork_;
    std::vector<int> jacobianWork_;
    // neighbourDeficiency is of the reference configuration: computed at the first call, kept.
    mutable std::optional<HealthIndicator> neighbourDeficiency_;
    std::vector<double> stretch_;  // per particle, the time-step vote's scratch
    int stepsSinceEnergyCheck_ = 0;
    double spacing_ = 0, h_ = 0, cpMax_ = 0;
    double csMax_ = 0;  // the largest shear-wave speed sqrt(mu/rho0), for the JST momentumSpeed shear
    std::unique_ptr<BodyForce> bodyForce_;  // null without a bodyForce sub-dictionary
    bool plastic_ = false;

    std::vector<Vector<Dim>>& x_;
    std::vector<Vector<Dim>>& v_;
    std::vector<double>& m_;
    std::vector<double>& rho0_;
    std::vector<Vector<Dim>>* X_ = nullptr;
    std::vector<Tensor<Dim>>* F_ = nullptr;
    std::vector<Tensor<Dim>>* H_ = nullptr;
    std::vector<double>* J_ = nullptr;
    std::vector<Tensor<Dim>>* P_ = nullptr;
    std::vector<double>* pressure_ = nullptr;
    std::vector<std::int64_t>* material_ = nullptr;
    std::vector<SymmTensor<Dim>>* plasticDeformation_ = nullptr;
    std::vector<double>* plasticOutOfPlane_ = nullptr;
    std::vector<double>* plasticStrain_ = nullptr;

    // Mirror ghosts of the symmetryPlane (parity +1) and skewSymmetricPlane (parity -1)
    // conditions, made once in the reference configuration (BoundaryConditionList::
    // referenceImages): ghost g images real particle ghosts_.source[g] (owned or halo) at
    // ghosts_.position[g], placed on the particle set's ghost range, after the halo, for each
    // stage's pair loop.
    GhostBlock<Dim> ghosts_;

    // Scratch: volumes (of [owned][halo][images]), the rates of a stage, Laplacians, the state at
    // the start of a step.
    std::vector<double> V_;
    std::vector<Vector<Dim>> acceleration_, lapP_, lap2P_, boundaryForce_;
    std::vector<Tensor<Dim>> dFdt_, dHdt_;
    std::vector<double> dJdt_, lapJ_, lap2J_;
    std::vector<Vector<Dim>> x0_, v0_;
    std::vector<Tensor<Dim>> F0_, H0_;
    std::vector<double> J0_;

    bool stressCurrent_ = false;  // P belongs to the present F, H, J (no stage has moved them since)
    double pairInteractions_ = 0;
};

extern template class TlSphSolver<1>;
extern template class TlSphSolver<2>;
extern template class TlSphSolver<3>;

}  // namespace mfdyn
