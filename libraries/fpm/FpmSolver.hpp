#pragma once
// fpmSolid: the finite pointset method for hypo-elastic solids (von Nida 2005; doc/methods/fpm.md).
// What is built, the step, constant/fpmProperties and the fields: the opening comment of FpmSolver.cpp.
#include "boundaryConditions/BoundaryConditionList.hpp"
#include "core/KeywordSchema.hpp"
#include "fpm/EulerPart.hpp"
#include "fpm/LinearFlowReference.hpp"
#include "fpm/ParticleManagement.hpp"
#include "fpm/ShearPart.hpp"
#include "fpm/splitting/Splitting.hpp"
#include "geometry/Shape.hpp"
#include "materials/MaterialSet.hpp"
#include "meshfreeOperators/LeastSquaresOperators.hpp"
#include "meshfreeOperators/SurfaceDetection.hpp"
#include "meshfreeOperators/fitWeights/FitWeight.hpp"
#include "particles/Decomposition.hpp"
#include "particles/NeighbourSearch.hpp"
#include "solver/Solver.hpp"

#include <array>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace mfdyn {

template <int Dim>
class FpmSolver final : public Solver {
public:
    explicit FpmSolver(SolverRun& run);
    ~FpmSolver() override;

    static KeywordSchema keywords();
    static KeywordSchema motionKeywords();
    static KeywordSchema initialStressKeywords();
    static KeywordSchema eulerKeywords();
    static KeywordSchema shearKeywords();
    static KeywordSchema freeSurfaceKeywords();
    static KeywordSchema instabilityKeywords();
    static KeywordSchema managementKeywords();
    static constexpr const char* propertiesDictionary = "fpmProperties";
    // Domain decomposition (issue 21): the halo and the rules that keep the serial bits are at
    // FpmSolver::updateDecomposition (FpmSolver.cpp).
    static constexpr bool runsOnSeveralRanks = true;

    TimeStepVote stableTimeStep() override;
    void step(double dt) override;
    ParticleSetBase& particles() override { return *owner_; }
    std::vector<ExtraFile> extraOutput() const override;
    std::vector<std::string> summary(double loopSeconds) const override;
    // sum m e where e is evolved (the work of both parts, sigma : grad v / rho), else the elastic
    // energy sum V (S : S / (4 mu) + p^2 / (2 K)), K = rho c^2 of the step's start, where the
    // shear or Euler part runs; none for the rotation part alone.
    std::optional<double> internalEnergy() const override;
    // The energy budget of the health check (FpmSolver.cpp, "the energy budget"): D, the loss of
    // each stage's rates at its start (the integrator's left-point quadrature: upwinding and the
    // central operators' error together), the free surface's resets and particle management; W, the
    // velocity conditions' kinetic jumps and the outer pressure's work -p_o sum dV.
    std::optional<double> schemeDissipation() const override;
    std::optional<double> externalWork() const override;
    // neighbourDeficiency and fitConditioning of the fit the next step makes (FpmSolver.cpp).
    std::vector<HealthIndicator> healthIndicators() const override;

    // The rotation-only reference (see the top of this file), measured after each step.
    struct RotationError {
        double stress = 0;      // max |S - S_exact| over particles and components
        double radius = 0;      // max | |x - c| - |x0 - c| |
        double zeroStress = 0;  // max |S| over the particles that started unstressed
    };

private:
    static KeywordValues readSettings(const Dictionary& properties);
    void readSubsystems();
    void readMotion();
    void readMaterials();
    void initialiseFields();
    SymmTensor<Dim> initialStressAt(const Vector<Dim>& X) const;
    Vector<Dim> prescribedVelocity(const Vector<Dim>& x) const;
    void measureRotationError(double t);
    void readFlowReference();
    void measureFlowError(double t);
    void readEuler();
    void readShear();
    typename LeastSquaresOperators<Dim>::Options shiftedFitBase() const;  // shiftedFitOrder applied
    // The stages of the split (fpm/splitting): each advances the state by its fraction of the step
    // on this step's fit and adds its share of the particles' velocity to motionVelocity_.
    void shearStage(double dt, double fraction);
    void eulerStage(double dt, double fraction);
    void rotationStage(double dt);
    // The rows of the shifted fits, within (1 + maxShift) h: searched once per step, when a part
    // first needs them.
    const NeighbourList& shiftedRows();
    void readFreeSurface();
    // The free-surface conditions on the particles detected this step: p = p_o, and with the shear
    // part S n = 0 (S <- P S P - tr(P S P)/(d - 1) P, P = I - n n^T), so that sigma n = -p_o n;
    // with velocity characteristic, after a stage, also v, rho, e (fpm/FreeSurfaceCondition.hpp).
    void applyFreeSurface(std::optional<fpm::Subsystem> stage);  // the stage just run, or none (step start)
    void markVelocityHeld(double t);  // velocityHeld_: the particles a velocity condition sets
    // particleManagement { ... }: merging and insertion after the motion (fpm/ParticleManagement.hpp),
    // the solver's per-particle arrays carried over to the new particles.
    void readManagement();
    void manageParticles();
    // Several ranks: migration when the particles may have outrun the halo (at a step's start),
    // the halo's refresh where a stage changed what the next fit reads, the rows of the owned
    // particles (in global-id order) within a radius, and the reach of the rows in h.
    void updateDecomposition();
    void refreshHalo();
    NeighbourList rowsWithin(double radius);
    double centralReach() const;
    double shiftedReach() const;
    void assignShearModuli();
    void carrySolverArrays(bool toFields);
    void gatherWholeSet();
    void redistribute();

    std::unique_ptr<ParticleSet<Dim>> owner_;
    const Dictionary& properties_;
    const KeywordValues settings_;
    std::unique_ptr<FitWeight> fitWeight_;
    std::unique_ptr<MaterialSet<Dim>> materials_;  // null without constant/materialProperties
    std::unique_ptr<Shape> stressShape_;
    SymmTensor<Dim> stress0_{};
    bool hasInitialStress_ = false;

    bool prescribed_ = false;         // motion: prescribed rigid rotation, else frozen
    bool upwindMotion_ = false;       // motion: the Euler part's upwind velocity
    bool dimensionalMotion_ = false;  // motion: the shear part's v_D (+ the Euler part's correction)
    double omega_ = 0;
    Vector<3> axis_ = Vector<3>::UnitZ();
    Vector<Dim> centre_ = Vector<Dim>::Zero();

    double spacing_ = 0;
    double h_ = 0;
    bool reference_ = false;                                 // the rotation-only reference applies
    bool euler_ = false, rotation_ = false, shear_ = false;  // the subsystems that run
    std::vector<fpm::Subsystem> parts_;                      // in the thesis's order
    std::unique_ptr<fpm::Splitting> splitting_;
    bool literalSoundSpeed_ = false;  // the Euler part's c^2 = dp/drho|e (else the isentropic one)

    // The Euler part (fpm/EulerPart.hpp): null unless subsystems has euler.
    std::unique_ptr<fpm::EulerPart<Dim>> eulerPart_;
    std::vector<double>* e_ = nullptr;   // specificInternalEnergy, when an equation of state needs it
    std::vector<double> c_;              // the sound speed of the step's start
    std::size_t flat_ = 0, tooFew_ = 0;  // central evaluations of the Euler part, summed over the steps
    std::size_t eulerShortened_ = 0;     // and its shortened shifts
    double maxShift_ = 0;                // the largest shift length taken
    struct StateChange {
        double rho = 0, p = 0,
               v = 0;  // max over particles of |rho - rho_start|, |p - p_start|, |v - v_start|
    };
    std::vector<double> rhoStart_, pStart_;
    std::vector<Vector<Dim>> vStart_;
    StateChange lastChange_, worstChange_;

    // The shear part (fpm/ShearPart.hpp): null unless subsystems has shear.
    std::unique_ptr<fpm::ShearPart<Dim>> shearPart_;
    std::vector<double> mu_, g_;         // shear modulus and dp/de|rho per particle
    double deviatorWeight_ = 1.0 / Dim;  // alpha of S's rate (the materials' strength laws)
    bool plastic_ = false;               // a material's strength law yields
    std::vector<double>* plasticStrain_ = nullptr;
    std::size_t shearTooFew_ = 0, unstrained_ = 0, shortened_ = 0;  // central or shortened, shear part
    double maxShearShift_ = 0;

    // The academic validations' exact uniform state (fpm/LinearFlowReference.hpp), with `reference`.
    std::unique_ptr<fpm::LinearFlowReference<Dim>> flowReference_;
    fpm::UniformState<Dim> flowState_;
    double flowTime_ = 0;
    struct FlowError {
        double rho = 0, p = 0,
               S = 0;  // max over particles of |rho - rho_ex|, |p - p_ex|, max_k |S_k - S_ex,k|
    };
    // absolute now; relative now; the largest absolute error and the largest |exact| over the run (their
    // ratio is the run's relative error: a quantity that starts at 0 has no meaningful pointwise ratio early)
    FlowError flowError_, flowRelative_, worstFlowError_, largestExact_;
    FlowError flowRunRelative() const;

    // constant/boundaryConditions (the shared family): velocity conditions after every stage that
    // changes v, position conditions after the motion.
    BoundaryConditionList<Dim> boundaryConditions_;
    // freeSurface { pressure p_o; }: detected every step (meshfreeOperators/SurfaceDetection).
    std::unique_ptr<SurfaceDetection<Dim>> surface_;
    double outerPressure_ = 0;
    bool surfaceTraction_ = true;
    bool characteristicSurface_ = false;  // freeSurface { velocity characteristic; }
    bool totalStressSurface_ = false;     // freeSurface { condition traction; }
    std::vector<char> velocityHeld_;      // per particle: a boundary condition sets its velocity
    double edgeAngle_ = 0;                // freeSurface { edgeAngle; } in radians (0: none)
    std::vector<unsigned char> edge_;     // the surface particles at edges (SurfaceDetection::edges)
    std::size_t edgeParticles_ = 0;       // summed over the steps
    // instabilityCheck { pressure (lo hi); stress s; }: a state outside is stopped as an instability.
    bool checkPressure_ = false;
    double pressureLow_ = 0, pressureHigh_ = 0, stressBound_ = 0;
    std::size_t surfaceParticles_ = 0;                          // detected, summed over the steps
    std::unique_ptr<fpm::ParticleManagement<Dim>> management_;  // null without particleManagement
    long managementInterval_ = 1;                               // applied every this many steps

    std::vector<Vector<Dim>> motionVelocity_;  // x <- x + dt motionVelocity_ (upwind, dimensional)
    std::vector<double> divergence_;           // the step's div v for V (the Euler part's div v_uw)
    bool wideBuilt_ = false;

    Decomposition* decomposition_ = nullptr;  // null on one rank
    std::vector<std::string> haloFields_;
    double haloWidth_ = 0;
    std::vector<Vector<Dim>> xAtMigration_;
    std::vector<Vector<Dim>> points_;  // the fits' points: the owned particles' positions

    std::vector<Vector<Dim>>& x_;
    std::vector<Vector<Dim>>& v_;
    std::vector<double>& rho_;
    std::vector<double>* p_ = nullptr;
    std::vector<double>* V_ = nullptr;
    std::vector<SymmTensor<Dim>>* S_ = nullptr;  // null where no part needs a deviator
    SymmTensor<Dim> stressOf(std::size_t i) const { return S_ ? (*S_)[i] : SymmTensor<Dim>{}; }
    std::vector<SymmTensor<Dim>> noStress_;  // applyFreeSurface's zero deviator where S_ is null

    // The energy budget (FpmSolver.cpp, "the energy budget"): measured where U is (euler or shear).
    // the particle's share of internalEnergy(); m the particles' masses
    double internalEnergyOf(std::size_t i, const std::vector<double>& m) const;
    double ownedEnergy(std::size_t n) const;  // sum over the first n of 1/2 m |v|^2 + its U
    double ownedKinetic(std::size_t n) const;
    void rememberStageStart(std::size_t n);
    double stageStartPower(
        std::size_t n) const;  // sum_i of the stage's change dotted with its start's gradient of K + U
    struct StageStart {
        std::vector<Vector<Dim>> v;
        std::vector<double> rho, p, e;
        std::vector<SymmTensor<Dim>> S;
    } stageStart_;
    bool budget_ = false;
    double schemeDissipation_ = 0, externalWork_ = 0;

    NeighbourSearch<Dim> search_;
    NeighbourList rows_;
    NeighbourList wideRows_;  // the Euler part's shifted fits: within (1 + maxShift) h
    LeastSquaresOperators<Dim> fit_;
    std::vector<double> hField_;
    std::vector<Tensor<Dim>> gradV_;
    std::vector<double> radius0_;  // |x - c| at this run's start

    RotationError last_, worst_;
    double neighboursPerParticle_ = 0;
    std::size_t grown_ = 0, shepard_ = 0;  // fallbacks taken, summed over the steps
};

}  // namespace mfdyn
