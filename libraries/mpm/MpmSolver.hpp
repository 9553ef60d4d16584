#pragma once
// mpmFsi: the explicit material point method for solids (doc/methods/mpm.md; Sulsky, Chen &
// Schreyer 1994; the thesis of the seed, Muthukumar 2021), in 1, 2 and 3 dimensions (plane
// strain below 3D). Particles carry the state (x, v, m, V0, F, sigma); each step maps them to a
// Cartesian background grid, solves the momentum balance on its nodes and maps back:
//
//     shapeFunctions (N, grad N once per step) -> particleToGrid (m, mv, f) -> gridSolve
//     (damping, mass cut-off, grid boundary conditions) -> gridToParticle (x, v) -> stress (L, F,
//     sigma), in the order of the `scheme` (USL, USF, MUSL)
//
// constant/mpmProperties:
//     grid            { origin (0 0); cellSize (0.05 0.05); cells (20 20); }   // grid/CartesianGrid.hpp
//     shapeFunction   linear;          // linear | uGIMP | quadraticBSpline | cubicBSpline
//     scheme          USL;             // USL | USF | MUSL (MpmModels.hpp)
//     velocityUpdate  FLIP;            // FLIP | PIC | flipPic (flipFraction r) | APIC
//     gridDamping     none;            // none | massProportional (dampingCoefficient alpha_d, 1/s)
//     pressureSmoothing none;          // fluids' pressure checkerboard (PressureSmoothing.hpp)
//     contact         singleField;     // singleField | multiField (multiFieldCoeffs { friction 0; }):
//                                      // one node field for all bodies, or one per body (contact/)
//     massCutoff      1e-10;           // kg: nodes lighter than this get v = a = 0
//     outsideGrid     stop;            // stop | remove (a particle leaving the grid)
//     isolatedParticles stop;          // stop | allow (extension instability: below)
//     bodyForce       { type uniformGravity; g (0 -9.81); }              // optional
//     gridBoundaryConditions { top { type slip; faces (yMax); } }        // optional
//     writeGrid       no;              // grid.vti beside particles.vtp at each write (on
//                                      // several ranks grid.pvti and a slab grid_<r>.vti a rank)
//
// system/controlDict: the CFL vote dt = maxCo min(dx) / (c + |v|) (maxCo default 0.3; c the
// material's p-wave speed); `adjustTimeStep no;` keeps deltaT fixed (the thesis's way), checked
// against the vote.
//
// constant/materialProperties: a constitutive law per material (stVenantKirchhoff, neoHookean,
// linearElastic, mooneyRivlin, j2Plasticity, ...), as for tlSph, or the updated-Lagrangian pair of
// impactSph, an equationOfState with an optional strength law (UpdatedLagrangianStress.hpp).
//
// Fields: position, velocity, mass, density (rho0; V0 = mass / density), region (the body),
// material, deformationGradient F (I at a fresh start; only where a constitutiveLaw reads it: the
// equation-of-state path of fluids and strength laws carries J alone, J <- det(I + dt L) J),
// cauchyStress (SymmTensor<Dim>: particle fields have the set's dimension) and below 3D
// cauchyStressZZ (the out-of-plane sigma_zz of plane strain), jacobian (det F, 1 at a fresh start),
// storedEnergyDensity (W per reference volume);
// affineVelocity C_p with APIC; plasticDeformation, plasticStrain with a plastic law.
//
// With `contact multiField;` each body (particleGen region) has its own node mass, momentum,
// mass gradient, force, velocity and acceleration; each body's grid is solved and given the grid
// conditions on its own, the contact model corrects the velocities where bodies meet, and each
// particle takes x, v and L from its own body's field. The contact force of each body pair is
// written every step to postProcessing/contact/<startTime>/contactForces.csv; its peak is in
// the summary.
//
// Diagnoses, never NaN: a particle outside the grid stops the run naming it, its body, the time
// and the remedies (or, with `outsideGrid remove;`, is removed with the mass lost logged); a
// particle whose grid nodes carry no mass of any other particle (separated from its body by more
// than the support: numerical fracture, the extension instability of note 6.2) stops the run.
//
// The health check (functionObjects/Health.hpp) sees the CFL vote's particle, the energy budget's
// transfer loss D and the grid conditions' and damping's work W (MpmSolver.cpp), and the
// small-mass indicator. It is not given the grid as its domain (RunContext::domain): the
// solver's own check in preStep stops a particle outside the grid before it is mapped, naming it,
// its body, the grid's span and the remedies (outsideGrid remove among them), and it runs after
// the function objects, so that one that ends the run at a boundary (damBarrier's planeCrossing at
// the open top y = 8) ends it cleanly; the health check's end-of-step test would stop it first.
// A health { domainMin; domainMax; } box still applies.
#include "functionObjects/CsvFile.hpp"
#include "grid/CartesianGrid.hpp"
#include "grid/gridBoundaryConditions/GridBoundaryCondition.hpp"
#include "grid/shapeFunctions/ShapeFunction.hpp"
#include "materials/MaterialSet.hpp"
#include "mpm/MpmModels.hpp"
#include "mpm/ParticleColouring.hpp"
#include "mpm/PressureSmoothing.hpp"
#include "mpm/UpdatedLagrangianStress.hpp"
#include "mpm/contact/Contact.hpp"
#include "solver/BodyForce.hpp"
#include "solver/Solver.hpp"

#include <memory>
#include <optional>
#include <vector>

namespace mfdyn {

class Decomposition;

template <int Dim>
class MpmSolver final : public Solver {
public:
    explicit MpmSolver(SolverRun& run);
    ~MpmSolver() override;
    static constexpr const char* propertiesDictionary = "mpmProperties";
    static KeywordSchema keywords();
    // Runs on several ranks (issue 21; "Several ranks" in MpmSolver.cpp).
    static constexpr bool runsOnSeveralRanks = true;

    void preStep() override;
    TimeStepVote stableTimeStep() override;
    void step(double dt) override;
    ParticleSetBase& particles() override { return *particles_; }
    std::optional<double> internalEnergy() const override;
    std::optional<double> potentialEnergy() const override;
    // The energy budget's transfer and boundary terms, summed over the steps (MpmSolver.cpp, step()).
    std::optional<double> schemeDissipation() const override { return dissipated_; }
    std::optional<double> externalWork() const override { return externalWork_; }
    std::vector<HealthIndicator> healthIndicators() const override;
    std::vector<ExtraFile> extraOutput() const override;
    std::vector<ExtraFile> pieceOutput() const override;
    std::vector<std::string> summary(double loopSeconds) const override;

    const CartesianGrid<Dim>& grid() const { return grid_; }

private:
    void readMaterials();
    void initialiseFields();
    void evaluateShapeFunctions();
    // P2G of mass and momentum (with the affine term under APIC).
    void mapMassAndMomentum();
    // P2G of the internal and body forces, f_I = sum_p N_Ip m_p b_p - V_p sigma_p grad N_Ip.
    void mapForces(double t);
    // v_I = (mv)_I / m_I where m_I >= massCutoff, else 0; the grid conditions at time t.
    void nodeVelocityFromMomentum(double t);
    void solveGrid(double dt, double t);
    void gridToParticles(double dt);
    // L = sum_I v_I (x) grad N_Ip from the node velocity, F <- (I + dt L) F, sigma and W.
    void updateStress(double dt, bool advanceState);
    // After the stress update: the `pressureSmoothing` model on the fluid particles (none: nothing).
    void smoothPressure();
    // The particles outside the grid (preStep), and the isolated ones (after the mass map).
    void checkInsideGrid();
    void checkIsolated();
    // A body torn into pieces that share no grid node (a whole row letting go): checkIsolated
    // sees a piece of one particle only. Union-find over the nodes (pieceParent_), rank-local.
    void checkTorn();
    void checkFinite(const char* phaseName) const;
    // Several ranks (MpmSolver.cpp, "Several ranks"): the particles migrate to their owners and the
    // halo is planned again when they have moved far enough (at a step's start); the nodes this
    // rank counts in the grid sums (ownedNode_) are marked after the shape functions.
    void updateDecomposition();
    void markOwnedNodes();
    bool countsNode(std::size_t node) const { return ownedNode_.empty() || ownedNode_[node] != 0; }
    std::size_t ownedCount() const { return particles_->ownedCount(); }
    // The grid's node fields as the serial run has them, every node from the rank that counts it
    // (collective; writeGrid on several ranks).
    CartesianGrid<Dim> gatheredGrid(const std::vector<std::string>& fields) const;
    // The p-wave speed of particle i's material (an equation of state's: the particle's own).
    double waveSpeed(std::size_t i) const;
    std::vector<double> materialWaveSpeed_;  // per material (0 for an equation of state's)
    // multiField: the per-body node fields, sized once; the contact correction of the velocity
    // (and acceleration, with the pair forces recorded, after the grid solve).
    void allocateBodyFields();
    void correctContact(double dt, bool afterForce, double t);
    // The node velocity array particle p reads: its body's under multiField, else the shared one.
    const Vector<Dim>* velocityOf(std::size_t p) const {
        return multi_ ? bodyVelocity_[std::size_t((*region_)[p])].data() : nodeVelocity_->data();
    }
    std::string bodyName(std::size_t i) const;
    const ConstitutiveLaw& law(std::size_t i) const {
        return *(*materials_)[(*material_)[i]].constitutiveLaw;
    }

    std::unique_ptr<ParticleSet<Dim>> owner_;
    ParticleSet<Dim>* particles_;
    const Dictionary& properties_;
    const Dictionary& materialProperties_;
    const KeywordValues settings_;
    CartesianGrid<Dim> grid_;
    std::unique_ptr<ShapeFunction<Dim>> shape_;
    std::unique_ptr<MpmScheme> scheme_;
    std::unique_ptr<VelocityUpdate> velocityUpdate_;
    std::unique_ptr<GridDamping> damping_;
    std::unique_ptr<PressureSmoothing<Dim>> smoothing_;
    std::unique_ptr<Contact<Dim>> contact_;
    std::unique_ptr<BodyForce> bodyForce_;
    std::unique_ptr<MaterialSet<Dim>> materials_;
    std::unique_ptr<UpdatedLagrangianStress<Dim>> ul_;  // equation of state + strength materials
    GridBoundaryConditionList<Dim> gridConditions_;
    double massCutoff_ = 1e-10;
    bool removeOutside_ = false;
    bool stopIsolated_ = true;
    bool writeGrid_ = false;
    bool linearHats_ = false;
    bool plastic_ = false;
    double removedMass_ = 0;
    std::size_t removedParticles_ = 0;
    double initialMass_ = 0;

    std::vector<Vector<Dim>>& x_;
    std::vector<Vector<Dim>>& v_;
    std::vector<double>& m_;
    std::vector<double>& rho0_;
    std::vector<std::int64_t>* material_ = nullptr;
    std::vector<Tensor<Dim>>* F_ = nullptr;  // null where no law reads F (J alone)
    bool givenJacobian_ = false;             // the particle file or the state gave J
    std::vector<SymmTensor<Dim>>* sigma_ = nullptr;
    std::vector<double>* sigmaZZ_ = nullptr;  // below 3D: sigma_zz of plane strain
    std::vector<double>* J_ = nullptr;
    std::vector<double>* W_ = nullptr;
    std::vector<Tensor<Dim>>* C_ = nullptr;  // APIC's affine velocity
    std::vector<SymmTensor<Dim>>* plasticDeformation_ = nullptr;
    std::vector<double>* plasticOutOfPlane_ = nullptr;
    std::vector<double>* plasticStrain_ = nullptr;

    // Node fields (grid_.nodes()): mass, momentum, force, velocity, acceleration.
    std::vector<double>* nodeMass_ = nullptr;
    std::vector<Vector<Dim>>* nodeMomentum_ = nullptr;
    std::vector<Vector<Dim>>* nodeForce_ = nullptr;
    std::vector<Vector<Dim>>* nodeVelocity_ = nullptr;
    std::vector<Vector<Dim>>* nodeAcceleration_ = nullptr;

    ParticleNodeList<Dim> list_;
    ParticleColouring<Dim> colouring_;
    std::vector<Vector<Dim>> halfSize_;                 // uGIMP: half the particle's extent, 0.5 V0^(1/Dim)
    std::vector<Vector<Dim>> nodeX_;                    // the node positions (APIC's x_I - x_p), made once
    std::vector<std::size_t> pieceParent_, pieceRoot_;  // checkTorn: union-find over nodes, roots
    std::vector<std::int64_t> pieceLabel_;              // checkTorn: per root node, the lowest id
    std::int64_t particleSteps_ = 0;

    // Several ranks: the decomposition (SolverRun's; null on one), the fields a halo particle
    // brings to the particle-to-grid sums, the halo's width (two supports plus the skin), the
    // owned positions at the last migration, a re-plan owed after outsideGrid remove, and per node
    // whether this rank counts it (the owner of its lowest-id particle does).
    Decomposition* decomposition_ = nullptr;
    std::vector<std::string> haloFields_;
    double haloWidth_ = 0, skin_ = 0;
    std::vector<Vector<Dim>> xAtMigration_;
    bool replan_ = false;
    std::vector<char> ownedNode_;
    std::vector<std::int64_t> nodeFirstId_;
    std::int64_t steps_ = 0;

    // The energy budget (step()): the kinetic energy the transfers lose, and the work of the grid
    // conditions and the damping, summed since construction; the grid kinetic energies of the step.
    double particleKinetic() const;
    double gridKinetic() const;  // sum 1/2 m_I |v_I|^2 of the velocity the particles will read
    double dissipated_ = 0, externalWork_ = 0;
    std::vector<double> plasticLoss_;  // per particle, the latest return's dissipation density
    double gridKineticStart_ = 0, gridKineticSolved_ = 0;
    // v* after the solve and v^c after the contact correction, per node field (W's test of which
    // components a condition set), kept only with grid conditions or damping.
    std::vector<std::vector<Vector<Dim>>> solvedVelocity_, contactedVelocity_;
    // The largest c + |v| of the last vote (the small-mass indicator's Courant number).
    double lastSpeed_ = 0;

    // multiField (empty under singleField): per body b the node arrays, b = the region id.
    bool multi_ = false;
    const std::vector<std::int64_t>* region_ = nullptr;
    std::vector<std::string> bodyNames_;
    std::vector<std::vector<double>> bodyMass_, bodyVolume_;  // sum N m_p, sum N V_p per body
    std::vector<std::vector<Vector<Dim>>> bodyMomentum_, bodyGradient_, bodyPosition_, bodyNodeForce_,
        bodyVelocity_, bodyAcceleration_;
    std::unique_ptr<CsvFile> contactCsv_;
    std::vector<double> contactRow_;
    double peakContactForce_ = 0, peakContactTime_ = 0;
    std::string peakContactPair_;
};

extern template class MpmSolver<1>;
extern template class MpmSolver<2>;
extern template class MpmSolver<3>;

}  // namespace mfdyn
