// mpmFsi: the explicit material point method (doc/methods/mpm.md; Sulsky, Chen & Schreyer 1994;
// Muthukumar 2021, the seed thesis). With N_Ip = N_I(x_p) and grad N_Ip evaluated once per step
// at the start-of-step positions (note 2.2, 2.8) and used by every transfer of the step:
//
//   P2G (note 2.3)   m_I  = sum_p N_Ip m_p
//                    (mv)_I = sum_p N_Ip m_p [v_p + C_p (x_I - x_p)]          (C_p = 0 but for APIC)
//                    f_I  = sum_p [N_Ip m_p b_p - V_p sigma_p grad N_Ip],   V_p = J_p V0_p (once)
//   grid (note 2.4, the code's signs; m_I >= massCutoff, else a = v = 0)
//                    a_I = (f_I - alpha_d (mv)_I) / m_I,   v_I^{n+1} = (mv)_I / m_I + dt a_I
//                    then the grid boundary conditions on v_I^{n+1} and a_I (note 2.5)
//   G2P (note 2.6)   x_p += dt sum_I N_Ip v_I^{n+1}
//                    v_p  = r (v_p + dt sum_I N_Ip a_I) + (1 - r) sum_I N_Ip v_I^{n+1}   (FLIP r = 1)
//   stress           L_p = sum_I v_I (x) grad N_Ip,  F_p <- (I + dt L_p) F_p (multiplicative,
//                    note 2.6: eq. 81's "+ F^t" is a misprint), J_p = det F_p,
//                    P_p from the law (3x3, plane strain F_zz = 1 below 3D: materials/Embedding.hpp),
//                    sigma_p = P_p F_p^T / J_p (note 1, eq. 19), W_p from the law (its exact energy)
//
// in the order of the scheme (MpmModels.cpp: USL, USF, MUSL). This is symplectic Euler: v from
// the force at x^n, x from v^{n+1} (note 2.7). Linear and angular momentum: the internal forces
// sum to zero on the grid (sum_I grad N_Ip = 0 for each particle); P2G conserves mass and momentum
// exactly (sum_I N_Ip = 1); FLIP and PIC lose angular momentum in the transfers, APIC keeps it.
// The P2G sums are deterministic for any thread count (ParticleColouring.hpp).
//
// contact multiField (contact/MultiFieldContact.cpp; Bardenhagen et al. 2001): the P2G above per
// body b (m_bI, (mv)_bI, f_bI, and the mass gradient g_bI = sum_p m_p grad N_Ip that gives the
// body's normal), the grid solve per body, then the contact correction of v_bI and a_bI where
// bodies meet, then each body's grid conditions; particle p takes x, v (G2P) and L from its own
// body's v_bI and a_bI. USF and MUSL correct the velocity they take L from in the same way. With
// linear hats and one body this is the single field exactly; singleField allocates none of it.
//
// The health check's energy budget (functionObjects/Health.cpp: K + U + Phi + D - W constant for a
// scheme that loses nothing unaccounted). With K_p = sum_p 1/2 m_p |v_p|^2 and, over the solved
// nodes (m_I >= massCutoff), K = sum_I 1/2 m_I |v_I|^2, a step takes the kinetic energy through
//
//     K_p^n --P2G--> K^n (v^n = (mv)/m) --solve--> K* (v*) [--contact--> K^c] --grid conditions-->
//     K+ (v+) --G2P--> K_p^{n+1}
//
// and the budget's two measured terms are, summed over the steps:
//   D (schemeDissipation)  the transfers' loss, which is no physics: (K_p^n - K^n) + (K+ - K_p^{n+1})
//                          (PIC's averaging loses, >= 0 by Jensen; FLIP's noise either sign; APIC's
//                          affine velocity is outside K_p, so its share shows here), plus under
//                          multiField the contact correction's K* - K^c (the nodes of two bodies
//                          meeting perfectly plastically, and friction), plus the plastic flow's
//                          dissipation, V0 |s| dgamma at each return (the law's plasticDissipation)
//   W (externalWork)       the work of the grid conditions and of the damping on the nodes, per
//                          node I and component c: where a condition set it (v+ != v^c, the
//                          velocity after the contact, v* without), its whole change of K less f's
//                          work on the motion it leaves and the contact's change,
//                          1/2 m (v+^2 - v^n^2) - dt f v+ - 1/2 m (v^c^2 - v*^2) (f = internal + body
//                          force: a fixed node's reaction does no work, v+ = 0, and the kinetic
//                          energy of a node it brings to rest is W); elsewhere the damping's work
//                          at the step's mean velocity, -alpha dt (mv) (v^n + v*) / 2
// so that K_p + D - W changes by exactly F = dt sum f . (v^n + v*) / 2 over the free components plus
// dt sum f . v+ over the set ones, the work of f on the nodes' motion, and what remains of the
// imbalance, R = F + dU + dPhi, is the time integration's: symplectic
// Euler (v from the force at x^n, x from v^{n+1}; USL's stress of the step's start). On a linear
// mode of frequency omega (q'' = -omega^2 q) it keeps H~ = H - dt omega^2 q v / 2 exactly, and
// |omega^2 q v| <= omega H, so H^n / H^0 lies in [(1 - e) / (1 + e), (1 + e) / (1 - e)], e = omega
// dt / 2: |R| <= 2e / (1 - e) (K + U) ~ omega_max dt (K + U) over the modes, omega_max the grid's
// highest, 2 c_p / dx per axis (at most 2 sqrt(d) c_p / dx). Bounded and oscillating, no drift;
// the nonlinear law and the cell crossings (the stiffness changes as particles move) lie outside
// the argument (tests/cases/health/mpmFsi.sh: twoDisks, 0.36% of K + U against 6.6e-3).
//
// Several ranks (issue 21). The particles are cut by position (particles/Decomposition, Zoltan)
// and each rank solves the grid where its particles are, redundantly near the cuts: a node's sums
// are complete on a rank that holds every particle reaching it. A particle reaches the nodes
// within R = supportHalfWidth x the largest cell size of it (per axis), and a node reached by an
// owned particle is reached only by particles within 2R of that particle, so the halo is the other
// ranks' particles within w = 2R + skin (one cell) of the rank's part, appended at each step's
// start with the fields the particle-to-grid sums read (x, v, m, rho0, J, sigma, material, region,
// C under APIC), and the particles migrate (and the halo is planned again) when 2 max |x - x_m| +
// 2R > w, x_m the positions at the last migration: at most every half cell of motion. Within a
// node the terms come colour by colour, tile by tile, and within a tile in global-id order
// (ParticleColouring), which does not depend on the numbering of a rank's particles: every node
// an owned particle reads has the serial run's bits, and so do G2P and the stress of the owned
// particles. No grid sum is reduced across ranks: the halo of particles (2R + skin wide) replaces
// the one-cell node halo whose partial sums, added across ranks, could not keep the serial order
// (exact sums of five node fields per node would cost more than the redundant scatter). Where
// the halo's state changes within a step its owners refresh it: J and sigma after USF's stress,
// x, v (and C) before MUSL's second map. The sums over nodes (the energy budget's K^n, K*, K+, W,
// the contact pair forces, the small-mass indicator, writeGrid's image) count each node once, on
// the rank that owns the lowest-id particle reaching it (ownedNode_); they agree with the serial
// run to round-off (rank-order sums of per-rank partials), the particle state to the bit. The
// torn-body check joins each rank's pieces through the halo particles' labels from their owners
// (checkTorn). pressureSmoothing averages over a cell's particles in global-id order, with the
// halo's x and J refreshed first.
#include "mpm/MpmSolver.hpp"

#include "core/KeywordSchema.hpp"
#include "core/Log.hpp"
#include "core/Parallel.hpp"
#include "grid/VtiWriter.hpp"
#include "materials/Embedding.hpp"
#include "particles/Decomposition.hpp"
#include "solver/MaterialAssignment.hpp"
#include "solver/SolverRegistry.hpp"
#include "solver/SolverRun.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>
#include <sstream>
#include <utility>

namespace mfdyn {

namespace {

template <int Dim>
std::string vectorText(const Vector<Dim>& a) {
    std::ostringstream s;
    s.precision(6);
    s << "(";
    for (int d = 0; d < Dim; ++d) s << (d ? " " : "") << a[d];
    s << ")";
    return s.str();
}

}  // namespace

template <int Dim>
KeywordSchema MpmSolver<Dim>::keywords() {
    return KeywordSchema("solver", "mpmFsi")
        .dictionary("grid", "the background grid: origin, cellSize, cells (or box and cellSize)")
        .identifier("shapeFunction", "the grid shape functions (a shapeFunction type)")
        .orDefault("linear")
        .identifier("scheme", "when the stress is updated (an mpmScheme type: USL, USF, MUSL)")
        .orDefault("USL")
        .identifier("velocityUpdate", "how particles take the grid velocity (a velocityUpdate type)")
        .orDefault("FLIP")
        .identifier("gridDamping", "damping of the grid momentum (a gridDamping type)")
        .orDefault("none")
        .identifier("pressureSmoothing", "the fluids' pressure checkerboard (a pressureSmoothing type)")
        .orDefault("none")
        .identifier("contact", "how bodies meet on the grid (a contact type: singleField, multiField)")
        .orDefault("singleField")
        .scalar("massCutoff", "kg", "nodes lighter than this get v = a = 0 (note 2.4)")
        .greaterThan(0)
        .orDefault(1e-10)
        .word("outsideGrid", {"stop", "remove"},
              "a particle leaving the grid stops the run, or is removed (its mass reported)")
        .orDefault("stop")
        .word("isolatedParticles", {"stop", "allow"},
              "a particle sharing no grid node with any other particle (extension instability) stops the run")
        .orDefault("stop")
        .dictionary("bodyForce", "body force per unit mass b(x, t) (a bodyForce type)")
        .optional()
        .dictionary("gridBoundaryConditions", "conditions on grid nodes (gridBoundaryCondition types)")
        .optional()
        .flag("writeGrid",
              "write the node fields as grid.vti beside particles.vtp (on several ranks grid.pvti over one "
              "slab grid_<rank>.vti a rank)")
        .orDefault(false);
}

template <int Dim>
MpmSolver<Dim>::MpmSolver(SolverRun& run)
    : Solver(run),
      owner_(adoptParticleSet<Dim>(run.takeParticles())),
      particles_(owner_.get()),
      properties_(openConstant("mpmProperties")),
      materialProperties_(openConstant("materialProperties")),
      settings_(keywords().read(properties_)),
      grid_(CartesianGrid<Dim>::fromDictionary(settings_.dictionary("grid"))),
      x_(particles_->position()),
      v_(particles_->vectorField("velocity")),
      m_(requireScalarField(*particles_, "mass", "particle masses")),
      rho0_(requireScalarField(*particles_, "density", "the reference density rho0: V0 = mass / density")) {
    declarePhases({"shapeFunctions", "particleToGrid", "gridSolve", "gridToParticle", "stress"});
    shape_ = selectByWord<ShapeFunction<Dim>>(properties_, "shapeFunction", "linear");
    linearHats_ = shape_->type() == "linear";
    scheme_ = selectByWord<MpmScheme>(properties_, "scheme", "USL");
    velocityUpdate_ = selectByWord<VelocityUpdate>(properties_, "velocityUpdate", "FLIP");
    damping_ = selectByWord<GridDamping>(properties_, "gridDamping", "none");
    smoothing_ = selectByWord<PressureSmoothing<Dim>>(properties_, "pressureSmoothing", "none");
    contact_ = selectByWord<Contact<Dim>>(properties_, "contact", "singleField");
    massCutoff_ = settings_.scalar("massCutoff");
    removeOutside_ = settings_.word("outsideGrid") == "remove";
    stopIsolated_ = settings_.word("isolatedParticles") == "stop";
    writeGrid_ = settings_.flag("writeGrid");
    if (settings_.given("bodyForce")) bodyForce_ = BodyForce::New(settings_.dictionary("bodyForce"), Dim);
    // The support must fit in the grid (a cubic B-spline needs 4 node layers along each axis).
    if (const std::string problem = shape_->gridProblem(grid_); !problem.empty()) {
        std::string types;
        for (const auto& name : ShapeFunction<Dim>::Selector::names())
            types += (types.empty() ? "" : " | ") + name;
        throw properties_.error(
            properties_.found("shapeFunction") ? "shapeFunction" : "grid",
            problem + ": refine the grid or choose a narrower shape function (valid types: " + types + ")");
    }
    readMaterials();
    initialiseFields();
    decomposition_ = run.decomposition();
    if (decomposition_) {
        haloFields_ = {"position", "velocity",     "mass",     "density",
                       "jacobian", "cauchyStress", "material", "region"};
        if (C_) haloFields_.push_back("affineVelocity");
        // Planned now: the decomposition's report in the log before the first step.
        updateDecomposition();
    }
}

template <int Dim>
MpmSolver<Dim>::~MpmSolver() = default;

template <int Dim>
void MpmSolver<Dim>::readMaterials() {
    // A constitutive law per material (the total-Lagrangian laws, evaluated on the particle's F),
    // or an equation of state with an optional strength law (impactSph's updated-Lagrangian pair,
    // UpdatedLagrangianStress.hpp); which one, and not both, is checked there.
    MaterialModels models;
    models.method = "mpmFsi";
    models.constitutiveLaw = ModelUse::optional;
    models.equationOfState = ModelUse::optional;
    models.strength = ModelUse::optional;
    models.viscosity = ModelUse::optional;  // a fluid's deviator (materials/viscosity/)
    models.equationOfStateOrConstitutiveLaw = true;
    materials_ = std::make_unique<MaterialSet<Dim>>(materialProperties_, models);
    plastic_ = materials_->usesPlasticState();
    assignMaterials(*particles_, materials_->names(), materialProperties_);
    material_ = &particles_->integerField("material");
    givenJacobian_ =
        particles_->hasField("jacobian");  // from the particle file or the state, before ul_ adds it
    ul_ = std::make_unique<UpdatedLagrangianStress<Dim>>(*materials_, *particles_);
    materialWaveSpeed_.assign(materials_->size(), 0.0);
    for (std::size_t k = 0; k < materials_->size(); ++k)
        if (!ul_->handles(std::int64_t(k)))
            materialWaveSpeed_[k] = (*materials_)[k].constitutiveLaw->pWaveSpeed();
}

template <int Dim>
void MpmSolver<Dim>::initialiseFields() {
    const std::size_t n = x_.size();
    checkPositiveMassAndDensity(*particles_, m_, rho0_);
    for (std::size_t i = 0; i < n; ++i) {
        const double lawRho0 = ul_->referenceDensity((*material_)[i]);
        if (std::abs(rho0_[i] - lawRho0) > 1e-9 * lawRho0)
            throw materialProperties_.error(
                "materials", "particle " + std::to_string(particles_->globalId()[i]) + " has density " +
                                 formatKeywordNumber(rho0_[i]) + " but its material '" +
                                 materials_->names()[(*material_)[i]] + "' has rho0 " +
                                 formatKeywordNumber(lawRho0) +
                                 ": generate the particles with the material's density");
    }
    // The grid must cover every particle at the start (bad input, not a run-time event).
    for (std::size_t i = 0; i < n; ++i)
        if (!grid_.contains(x_[i]))
            throw properties_.error(
                "grid", "particle " + std::to_string(particles_->globalId()[i]) + " (body " + bodyName(i) +
                            ") at " + vectorText<Dim>(x_[i]) + " lies outside the grid, which spans " +
                            vectorText<Dim>(grid_.origin()) + " to " + vectorText<Dim>(grid_.upperCorner()) +
                            ": enlarge the grid (origin, cells) to cover every particle");
    // F only where a law reads it (leave out what a scene does not need): a constitutiveLaw (a
    // function of F) on some material, or a state that carries F. The equation-of-state path (the
    // fluids, the strength laws) needs only J, advanced as J <- det(I + dt L) J (updateStress).
    const bool hadF = particles_->hasField("deformationGradient");
    bool lawOfF = hadF;
    for (std::size_t k = 0; k < materials_->size(); ++k) lawOfF = lawOfF || !ul_->handles(std::int64_t(k));
    if (lawOfF) {
        F_ = &particles_->tensorField("deformationGradient");
        if (!hadF) std::fill(F_->begin(), F_->end(), Tensor<Dim>::Identity());
    }
    sigma_ = &particles_->symmTensorField("cauchyStress");
    if (Dim < 3) sigmaZZ_ = &particles_->scalarField("cauchyStressZZ");
    J_ = &particles_->scalarField("jacobian");
    if (!F_ && !givenJacobian_) std::fill(J_->begin(), J_->end(), 1.0);
    W_ = &particles_->scalarField("storedEnergyDensity");
    if (velocityUpdate_->affine()) C_ = &particles_->tensorField("affineVelocity");
    if (plastic_) {
        const bool had = particles_->hasField("plasticDeformation");
        plasticDeformation_ = &particles_->symmTensorField("plasticDeformation");
        if (Dim < 3) plasticOutOfPlane_ = &particles_->scalarField("plasticDeformationOutOfPlane");
        plasticStrain_ = &particles_->scalarField("plasticStrain");
        if (!had)
            for (std::size_t i = 0; i < n; ++i) {
                (*plasticDeformation_)[i] = SymmTensor<Dim>::fromFull(Tensor<Dim>::Identity());
                if (plasticOutOfPlane_) (*plasticOutOfPlane_)[i] = 1.0;
            }
    }
    FieldStore& nodes = grid_.nodes();
    nodeMass_ = &nodes.field<double>("mass");
    nodeMomentum_ = &nodes.field<Vector<Dim>>("momentum");
    nodeForce_ = &nodes.field<Vector<Dim>>("force");
    nodeVelocity_ = &nodes.field<Vector<Dim>>("velocity");
    nodeAcceleration_ = &nodes.field<Vector<Dim>>("acceleration");
    if (C_) {
        nodeX_.resize(grid_.nodeCount());
        parallelFor(nodeX_.size(), [&](std::size_t I) { nodeX_[I] = grid_.nodePosition(std::int64_t(I)); });
    }
    if (contact_->multiField()) {
        // A body is a region (particleGen's): its id indexes the per-body node fields.
        region_ = &std::as_const(*particles_).region();
        const auto& region = *region_;
        for (std::size_t i = 0; i < n; ++i)
            if (region[i] < 0)
                throw properties_.error("contact",
                                        "particle " + std::to_string(particles_->globalId()[i]) +
                                            " has no body (region " + std::to_string(region[i]) +
                                            "): contact multiField needs every particle in a region");
        const double last = GlobalReduce::max(n, [&](std::size_t i) { return double(region[i]); });
        const std::size_t bodies =
            std::max(particles_->regionNames.size(), std::size_t(std::max(last, 0.0)) + 1);
        bodyNames_ = particles_->regionNames;
        for (std::size_t b = bodyNames_.size(); b < bodies; ++b)
            bodyNames_.push_back("region " + std::to_string(b));
        bodyNames_.resize(bodies);
        contact_->bind(bodyNames_);
        multi_ = true;
        allocateBodyFields();
    }
    if (settings_.given("gridBoundaryConditions")) {
        gridConditions_ =
            GridBoundaryConditionList<Dim>(settings_.dictionary("gridBoundaryConditions"), grid_);
        for (const auto& line : gridConditions_.describe()) Log::info("grid boundary condition " + line);
    }
    initialMass_ = GlobalReduce::sum<double>(n, [&](std::size_t i) { return m_[i]; });
    // sigma, J and W of the start state (for the first write and the function objects).
    updateStress(0.0, false);

    std::ostringstream s;
    s << "mpmFsi: " << grid_.describe() << "; shapeFunction " << shape_->type() << ", scheme "
      << scheme_->type() << ", velocityUpdate " << velocityUpdate_->describe() << ", gridDamping "
      << damping_->describe() << ", pressureSmoothing " << smoothing_->describe() << ", contact "
      << contact_->describe() << (multi_ ? " over " + std::to_string(bodyNames_.size()) + " bodies" : "")
      << ", massCutoff " << massCutoff_ << " kg, " << std::size_t(globalSum(double(n))) << " particles";
    Log::info(s.str());
}

template <int Dim>
std::string MpmSolver<Dim>::bodyName(std::size_t i) const {
    const std::int64_t r = particles_->region()[i];
    if (r >= 0 && std::size_t(r) < particles_->regionNames.size())
        return particles_->regionNames[std::size_t(r)];
    return "region " + std::to_string(r);
}

template <int Dim>
void MpmSolver<Dim>::preStep() {
    checkInsideGrid();
}

template <int Dim>
void MpmSolver<Dim>::checkInsideGrid() {
    const std::size_t n = x_.size();
    auto outside = [&](std::size_t i) { return !grid_.contains(x_[i]); };
    if (!removeOutside_) {
        Solver::checkState("preStep", n, outside, [&](std::size_t i, double count) {
            std::ostringstream s;
            s << "particle " << particles_->globalId()[i] << " (body " << bodyName(i) << ") at "
              << vectorText<Dim>(x_[i]) << " has left the grid, which spans "
              << vectorText<Dim>(grid_.origin()) << " to " << vectorText<Dim>(grid_.upperCorner()) << "; "
              << count
              << " particle(s) outside. Remedies: a larger grid (constant/mpmProperties grid), or an open "
                 "boundary that removes such particles (outsideGrid remove;)";
            return s.str();
        });
        return;
    }
    // outsideGrid remove: a global count first, so that every rank agrees whether to compact.
    const double count = GlobalReduce::sum<double>(n, [&](std::size_t i) { return outside(i) ? 1.0 : 0.0; });
    if (count == 0) return;
    const double mass = GlobalReduce::sum<double>(n, [&](std::size_t i) { return outside(i) ? m_[i] : 0.0; });
    std::vector<std::size_t> keep;
    keep.reserve(n);
    std::string bodies;
    for (std::size_t i = 0; i < n; ++i) {
        if (!outside(i))
            keep.push_back(i);
        else if (bodies.find(bodyName(i)) == std::string::npos)
            bodies += (bodies.empty() ? "" : ", ") + bodyName(i);
    }
    particles_->keep(keep);
    replan_ = true;  // the halo plan indexes the owned particles (a global decision: count is global)
    removedMass_ += mass;
    removedParticles_ += std::size_t(count);
    std::ostringstream s;
    s.precision(6);
    s << "outsideGrid remove: " << count << " particle(s) of " << bodies
      << " left the grid at t = " << time().value() << ", mass " << mass << " kg removed (" << removedMass_
      << " kg in all, " << 100.0 * removedMass_ / initialMass_ << "% of the initial mass)";
    Log::info(s.str());
}

template <int Dim>
void MpmSolver<Dim>::updateDecomposition() {
    // A global test, one reduction a step (the header's "Several ranks"): every rank decides alike.
    const std::size_t n = ownedCount();
    const double cell = grid_.cellSize().maxCoeff();
    const double reach = shape_->supportHalfWidth() * cell;
    bool due = haloWidth_ == 0 || replan_;
    if (!due) {
        const double dMax =
            GlobalReduce::max(n, [&](std::size_t i) { return (x_[i] - xAtMigration_[i]).norm(); });
        due = 2 * dMax + 2 * reach > haloWidth_;
    }
    if (!due) return;
    auto timed = phase("shapeFunctions");
    const bool first = haloWidth_ == 0;
    const int rebalancesBefore = decomposition_->rebalances();
    // Every particle costs the same (its support's nodes): weight 1 each.
    decomposition_->migrate(*particles_, {});
    skin_ = cell;
    haloWidth_ = 2 * reach + skin_;
    decomposition_->planHalo(*particles_, haloWidth_);
    replan_ = false;
    xAtMigration_.assign(x_.begin(), x_.begin() + std::ptrdiff_t(ownedCount()));
    if (first || decomposition_->rebalances() != rebalancesBefore)
        Log::info(decomposition_->report(*particles_, {}));
}

template <int Dim>
void MpmSolver<Dim>::markOwnedNodes() {
    // A node is counted by the rank owning the lowest-id particle that reaches it: that rank holds
    // every particle reaching the node (the halo covers two supports), so its sums are complete,
    // and every rank that holds the node whole sees the same lowest id. Nodes reached only by halo
    // particles (incomplete here) are never this rank's.
    const std::size_t owned = ownedCount(), stride = list_.stride;
    const auto& id = particles_->globalId();
    nodeFirstId_.assign(grid_.nodeCount(), std::numeric_limits<std::int64_t>::max());
    colouring_.forEachParticle([&](std::size_t p) {
        const std::size_t base = p * stride;
        for (std::size_t k = 0; k < list_.count[p]; ++k) {
            auto& first = nodeFirstId_[list_.node[base + k]];
            first = std::min(first, id[p]);
        }
    });
    ownedNode_.assign(grid_.nodeCount(), 0);
    parallelFor(owned, [&](std::size_t p) {
        const std::size_t base = p * stride;
        for (std::size_t k = 0; k < list_.count[p]; ++k)
            if (nodeFirstId_[list_.node[base + k]] == id[p]) ownedNode_[list_.node[base + k]] = 1;
    });
}

template <int Dim>
double MpmSolver<Dim>::waveSpeed(std::size_t i) const {
    // An equation-of-state material's speed is the particle's own (its density and state); a
    // constitutive law's is its material's, computed once (pWaveSpeed is not cheap).
    const std::int64_t k = (*material_)[i];
    return ul_->handles(k) ? ul_->waveSpeed(i, rho0_[i]) : materialWaveSpeed_[std::size_t(k)];
}

template <int Dim>
TimeStepVote MpmSolver<Dim>::stableTimeStep() {
    // The CFL vote (note 2.7 [D]): dt = C min(dx) / max_p (c_p + |v_p|), c the p-wave speed of the
    // particle's material; a global vote (every rank steps with the same dt), one per material so
    // that the progress line can name the limiting one. The vote names its particle: the lowest
    // global id among those at the limit (one more global reduction, for the winning limit only).
    const std::size_t n = x_.size();
    auto speedOf = [&](std::size_t i) { return waveSpeed(i) + v_[i].norm(); };
    double speed = 0;
    std::size_t limiting = 0;
    for (std::size_t k = 0; k < materials_->size(); ++k) {
        const double s = GlobalReduce::max(
            n, [&](std::size_t i) { return std::int64_t(k) == (*material_)[i] ? speedOf(i) : 0.0; });
        if (s > speed) speed = s, limiting = k;
    }
    lastSpeed_ = speed;
    const double courant = time().maxCo(0.3);
    TimeStepVote vote{std::numeric_limits<double>::infinity(), "CFL"};
    // Which particle limits: 0 the CFL, 1 the viscous limit (its value), -1 none.
    int limit = -1;
    double viscous = std::numeric_limits<double>::infinity();
    const double dx = grid_.smallestCellSize();
    auto viscousOf = [&](std::size_t i) {
        return ul_->handles((*material_)[i]) ? ul_->viscousTimeStep(i, rho0_[i], dx)
                                             : std::numeric_limits<double>::infinity();
    };
    if (speed > 0) {
        vote = {courant * dx / speed,
                "CFL (maxCo dx / (c + |v|), material " + materials_->names()[limiting] + ")"};
        limit = 0;
    }
    if (ul_->any()) {
        // The viscous limit rho dx^2 / (4 mu) of the fluids (note 2.7 [D]), a global vote.
        viscous = GlobalReduce::min(n, viscousOf);
        if (viscous < vote.deltaT) vote = {viscous, "viscous (rho dx^2 / (4 mu))"}, limit = 1;
    }
    if (bodyForce_)
        if (auto force = bodyForce_->stableTimeStep(); force.deltaT < vote.deltaT) vote = force, limit = -1;
    if (limit >= 0) {
        // The same expressions as the reductions above: the limit is one of these values exactly.
        const std::vector<std::int64_t>& id = particles_->globalId();
        double first = std::numeric_limits<double>::infinity();
        for (std::size_t i = 0; i < n; ++i)
            if (limit == 0 ? (*material_)[i] == std::int64_t(limiting) && speedOf(i) >= speed
                           : viscousOf(i) <= viscous)
                first = std::min(first, double(id[i]));
        first = globalMin(first);
        if (std::isfinite(first)) vote.particle = std::int64_t(first);
    }
    return vote;
}

template <int Dim>
void MpmSolver<Dim>::evaluateShapeFunctions() {
    auto timed = phase("shapeFunctions");
    const std::size_t n = x_.size();
    if (shape_->needsParticleSize()) {
        // uGIMP: the particle's half-extent from its initial volume, l_p = V0^(1/Dim) / 2 per axis.
        halfSize_.resize(n);
        parallelFor(n, [&](std::size_t i) {
            halfSize_[i] = Vector<Dim>::Constant(0.5 * std::pow(m_[i] / rho0_[i], 1.0 / Dim));
        });
    }
    shape_->evaluate(grid_, std::span<const Vector<Dim>>(x_), std::span<const Vector<Dim>>(halfSize_), list_);
    colouring_.build(grid_, std::span<const Vector<Dim>>(x_), list_,
                     std::span<const std::int64_t>(particles_->globalId()));
    if (decomposition_) markOwnedNodes();
}

template <int Dim>
void MpmSolver<Dim>::mapMassAndMomentum() {
    auto& mass = *nodeMass_;
    auto& momentum = *nodeMomentum_;
    std::fill(mass.begin(), mass.end(), 0.0);
    std::fill(momentum.begin(), momentum.end(), Vector<Dim>::Zero());
    const std::size_t stride = list_.stride;
    if (multi_) {
        for (std::size_t b = 0; b < bodyMass_.size(); ++b) {
            std::fill(bodyMass_[b].begin(), bodyMass_[b].end(), 0.0);
            std::fill(bodyMomentum_[b].begin(), bodyMomentum_[b].end(), Vector<Dim>::Zero());
            std::fill(bodyGradient_[b].begin(), bodyGradient_[b].end(), Vector<Dim>::Zero());
            std::fill(bodyPosition_[b].begin(), bodyPosition_[b].end(), Vector<Dim>::Zero());
            std::fill(bodyVolume_[b].begin(), bodyVolume_[b].end(), 0.0);
        }
        // One colour's particles touch disjoint nodes, hence disjoint (body, node) entries too.
        colouring_.forEachParticle([&](std::size_t p) {
            const auto b = std::size_t((*region_)[p]);
            auto& bm = bodyMass_[b];
            auto& bp = bodyMomentum_[b];
            auto& bg = bodyGradient_[b];
            auto& bx = bodyPosition_[b];
            auto& bV = bodyVolume_[b];
            const double Vp = (*J_)[p] * m_[p] / rho0_[p];  // V = J V0
            const std::size_t base = p * stride;
            for (std::size_t k = 0; k < list_.count[p]; ++k) {
                const auto node = list_.node[base + k];
                const double Nm = list_.weight[base + k] * m_[p];
                const Vector<Dim> vp = C_ ? Vector<Dim>(v_[p] + (*C_)[p] * (nodeX_[node] - x_[p])) : v_[p];
                mass[node] += Nm;
                momentum[node] += Nm * vp;
                bm[node] += Nm;
                bp[node] += Nm * vp;
                bg[node] += m_[p] * list_.gradient[base + k];
                bx[node] += Nm * x_[p];
                bV[node] += list_.weight[base + k] * Vp;
            }
        });
        return;
    }
    colouring_.forEachParticle([&](std::size_t p) {
        const std::size_t base = p * stride;
        for (std::size_t k = 0; k < list_.count[p]; ++k) {
            const auto node = list_.node[base + k];
            const double Nm = list_.weight[base + k] * m_[p];
            mass[node] += Nm;
            if (C_)
                momentum[node] += Nm * (v_[p] + (*C_)[p] * (nodeX_[node] - x_[p]));
            else
                momentum[node] += Nm * v_[p];
        }
    });
}

template <int Dim>
void MpmSolver<Dim>::mapForces(double t) {
    auto& force = *nodeForce_;
    std::fill(force.begin(), force.end(), Vector<Dim>::Zero());
    const std::size_t stride = list_.stride;
    if (multi_) {
        for (auto& f : bodyNodeForce_) std::fill(f.begin(), f.end(), Vector<Dim>::Zero());
        colouring_.forEachParticle([&](std::size_t p) {
            Vector<Dim> b = Vector<Dim>::Zero();
            if (bodyForce_) bodyForce_->acceleration(x_[p].data(), t, b.data());
            const Tensor<Dim> Vsigma = ((*J_)[p] * m_[p] / rho0_[p]) * (*sigma_)[p].full();
            const Vector<Dim> mb = m_[p] * b;
            auto& bf = bodyNodeForce_[std::size_t((*region_)[p])];
            const std::size_t base = p * stride;
            for (std::size_t k = 0; k < list_.count[p]; ++k) {
                const Vector<Dim> f = list_.weight[base + k] * mb - Vsigma * list_.gradient[base + k];
                force[list_.node[base + k]] += f;
                bf[list_.node[base + k]] += f;
            }
        });
        return;
    }
    colouring_.forEachParticle([&](std::size_t p) {
        Vector<Dim> b = Vector<Dim>::Zero();
        if (bodyForce_) bodyForce_->acceleration(x_[p].data(), t, b.data());
        // V_p sigma_p with V_p = J_p V0_p: the only place the current volume enters (note 2.3).
        const Tensor<Dim> Vsigma = ((*J_)[p] * m_[p] / rho0_[p]) * (*sigma_)[p].full();
        const Vector<Dim> mb = m_[p] * b;
        const std::size_t base = p * stride;
        for (std::size_t k = 0; k < list_.count[p]; ++k)
            force[list_.node[base + k]] += list_.weight[base + k] * mb - Vsigma * list_.gradient[base + k];
    });
}

template <int Dim>
void MpmSolver<Dim>::nodeVelocityFromMomentum(double t) {
    auto& v = *nodeVelocity_;
    const auto& mass = *nodeMass_;
    const auto& momentum = *nodeMomentum_;
    parallelFor(v.size(), [&](std::size_t I) {
        v[I] = mass[I] >= massCutoff_ ? Vector<Dim>(momentum[I] / mass[I]) : Vector<Dim>::Zero();
    });
    if (!gridConditions_.empty()) gridConditions_.apply(grid_, v, nullptr, t, 0.0);
    if (!multi_) return;
    for (std::size_t b = 0; b < bodyMass_.size(); ++b) {
        const auto& mb = bodyMass_[b];
        const auto& pb = bodyMomentum_[b];
        auto& vb = bodyVelocity_[b];
        parallelFor(vb.size(), [&](std::size_t I) {
            vb[I] = mb[I] >= massCutoff_ ? Vector<Dim>(pb[I] / mb[I]) : Vector<Dim>::Zero();
        });
    }
    // USF's and MUSL's velocity for L: the bodies' velocities corrected where they meet (no
    // acceleration, no force recorded), then the grid conditions.
    correctContact(0.0, false, t);
    for (auto& vb : bodyVelocity_)
        if (!gridConditions_.empty()) gridConditions_.apply(grid_, vb, nullptr, t, 0.0);
}

template <int Dim>
void MpmSolver<Dim>::solveGrid(double dt, double t) {
    auto timed = phase("gridSolve");
    const double alpha = damping_->coefficient();
    // The energy budget's grid terms (the header's equations): K^n = sum 1/2 m |v^n|^2 of v^n =
    // (mv) / m and K* of the solved v* = v^n + dt a, over the solved nodes (m_I >= massCutoff),
    // fused into the solve's own pass.
    auto solve = [&](const std::vector<double>& m, const std::vector<Vector<Dim>>& mv,
                     const std::vector<Vector<Dim>>& f, std::vector<Vector<Dim>>& vI,
                     std::vector<Vector<Dim>>& aI) {
        return GlobalReduce::sum<SumArray<2>>(vI.size(), [&](std::size_t I) {
            SumArray<2> e;
            if (m[I] >= massCutoff_) {
                const Vector<Dim> v0 = mv[I] / m[I];
                aI[I] = (f[I] - alpha * mv[I]) / m[I];
                vI[I] = v0 + dt * aI[I];
                if (countsNode(I)) {
                    e.s[0] = 0.5 * m[I] * v0.squaredNorm();
                    e.s[1] = 0.5 * m[I] * vI[I].squaredNorm();
                }
            } else {
                aI[I] = Vector<Dim>::Zero();
                vI[I] = Vector<Dim>::Zero();
            }
            return e;
        });
    };
    // After the contact correction and the conditions, per node and component: K+, and W, the
    // work of what acted on the nodes beside f: where a condition set the component (v+ != v^c),
    // its whole change of K less f's work on the motion it leaves, 1/2 m (v+^2 - v^n^2) - dt f v+ -
    // 1/2 m (v^c^2 - v*^2) (a fixed node's reaction does no work: v+ = 0; the kinetic energy it
    // takes from a node brought to rest is W); elsewhere the damping's, -alpha dt (mv) (v^n + v*) / 2.
    auto settled = [&](const std::vector<double>& m, const std::vector<Vector<Dim>>& mv,
                       const std::vector<Vector<Dim>>& f, const std::vector<Vector<Dim>>& solved,
                       const std::vector<Vector<Dim>>& contacted, const std::vector<Vector<Dim>>& vI) {
        return GlobalReduce::sum<SumArray<2>>(vI.size(), [&](std::size_t I) {
            SumArray<2> e;
            if (!(m[I] >= massCutoff_) || !countsNode(I)) return e;
            const Vector<Dim> v0 = mv[I] / m[I];
            e.s[0] = 0.5 * m[I] * vI[I].squaredNorm();
            for (int c = 0; c < Dim; ++c) {
                const double vn = v0[c], vs = solved[I][c], vc = contacted[I][c], vp = vI[I][c];
                e.s[1] += vp != vc ? 0.5 * m[I] * (vp * vp - vn * vn) - dt * f[I][c] * vp -
                                         0.5 * m[I] * (vc * vc - vs * vs)
                                   : -0.5 * alpha * dt * mv[I][c] * (vn + vs);
            }
            return e;
        });
    };
    const bool conditions = !gridConditions_.empty();
    const std::size_t fields = multi_ ? bodyMass_.size() : 1;
    auto massOf = [&](std::size_t b) -> const std::vector<double>& {
        return multi_ ? bodyMass_[b] : *nodeMass_;
    };
    auto momentumOf = [&](std::size_t b) -> const std::vector<Vector<Dim>>& {
        return multi_ ? bodyMomentum_[b] : *nodeMomentum_;
    };
    auto forceOf = [&](std::size_t b) -> const std::vector<Vector<Dim>>& {
        return multi_ ? bodyNodeForce_[b] : *nodeForce_;
    };
    auto velocity = [&](std::size_t b) -> std::vector<Vector<Dim>>& {
        return multi_ ? bodyVelocity_[b] : *nodeVelocity_;
    };
    auto acceleration = [&](std::size_t b) -> std::vector<Vector<Dim>>& {
        return multi_ ? bodyAcceleration_[b] : *nodeAcceleration_;
    };
    // Note 2.4 with the signs of the author's code: a = (f - alpha mv) / m, v = mv / m + a dt; under
    // multiField each body's field on its own, the contact correction where bodies meet, then each
    // body's grid conditions (the walls have the last word). The shared field's v and a are not
    // needed then (writeGrid writes its mass, momentum and force).
    SumArray<2> e;
    for (std::size_t b = 0; b < fields; ++b)
        e += solve(massOf(b), momentumOf(b), forceOf(b), velocity(b), acceleration(b));
    const bool budget = conditions || alpha != 0;  // else W = 0 exactly, K+ = K^c
    solvedVelocity_.resize(budget ? fields : 0);
    for (std::size_t b = 0; b < solvedVelocity_.size(); ++b) solvedVelocity_[b] = velocity(b);
    double contactLoss = 0;
    if (multi_) {
        correctContact(dt, true, t);
        // The contact correction's loss (the nodes' velocities meeting perfectly plastically, and
        // friction's) is the scheme's: it goes to the dissipated energy, as its change of K.
        const double contacted = gridKinetic();
        contactLoss = e.s[1] - contacted;
        e.s[1] = contacted;
    }
    contactedVelocity_.resize(budget && multi_ ? fields : 0);
    for (std::size_t b = 0; b < contactedVelocity_.size(); ++b) contactedVelocity_[b] = velocity(b);
    if (conditions)
        for (std::size_t b = 0; b < fields; ++b)
            gridConditions_.apply(grid_, velocity(b), &acceleration(b), t + dt, dt);
    gridKineticStart_ = e.s[0];
    gridKineticSolved_ = e.s[1];
    dissipated_ += contactLoss;
    if (!budget) return;
    SumArray<2> after;
    for (std::size_t b = 0; b < fields; ++b)
        after += settled(massOf(b), momentumOf(b), forceOf(b), solvedVelocity_[b],
                         multi_ ? contactedVelocity_[b] : solvedVelocity_[b], velocity(b));
    gridKineticSolved_ = after.s[0];
    externalWork_ += after.s[1];
}

template <int Dim>
void MpmSolver<Dim>::gridToParticles(double dt) {
    auto timed = phase("gridToParticle");
    const double r = velocityUpdate_->flipFraction();
    const std::size_t stride = list_.stride;
    parallelFor(ownedCount(), [&](std::size_t p) {
        // The particle's own body's field under multiField, the shared one else.
        const Vector<Dim>* vI = velocityOf(p);
        const Vector<Dim>* aI =
            multi_ ? bodyAcceleration_[std::size_t((*region_)[p])].data() : nodeAcceleration_->data();
        const std::size_t base = p * stride;
        Vector<Dim> vPic = Vector<Dim>::Zero(), aFlip = Vector<Dim>::Zero();
        for (std::size_t k = 0; k < list_.count[p]; ++k) {
            const double N = list_.weight[base + k];
            vPic += N * vI[list_.node[base + k]];
            aFlip += N * aI[list_.node[base + k]];
        }
        if (C_) {
            // APIC's C_p = B_p D_p^-1 (MpmModels.cpp): for linear hats exactly sum_I v_I (x) grad N_Ip.
            Tensor<Dim> C = Tensor<Dim>::Zero();
            if (linearHats_) {
                for (std::size_t k = 0; k < list_.count[p]; ++k)
                    C += vI[list_.node[base + k]] * list_.gradient[base + k].transpose();
            } else {
                Tensor<Dim> B = Tensor<Dim>::Zero(), D = Tensor<Dim>::Zero();
                for (std::size_t k = 0; k < list_.count[p]; ++k) {
                    const double N = list_.weight[base + k];
                    const Vector<Dim> dx = nodeX_[list_.node[base + k]] - x_[p];
                    B += N * vI[list_.node[base + k]] * dx.transpose();
                    D += N * dx * dx.transpose();
                }
                C = B * D.inverse();
            }
            (*C_)[p] = C;
        }
        x_[p] += dt * vPic;
        v_[p] = r * (v_[p] + dt * aFlip) + (1.0 - r) * vPic;
    });
}

template <int Dim>
void MpmSolver<Dim>::updateStress(double dt, bool advanceState) {
    const std::size_t n = ownedCount();
    if (advanceState && plastic_) plasticLoss_.assign(n, 0.0);
    auto timed = phase("stress");
    const std::size_t stride = list_.stride;
    const bool move = dt != 0.0;
    parallelFor(n, [&](std::size_t p) {
        Tensor<Dim> L = Tensor<Dim>::Zero();
        if (move) {
            const Vector<Dim>* vI = velocityOf(p);
            const std::size_t base = p * stride;
            // Component by component, the same sums in the same order as L += v_I grad N^T, which
            // GCC compiled to a 3 x 3 stack temporary whose reload stalled on store forwarding
            // (bench/mpm/README.md: a third of the Taylor bar's time).
            for (std::size_t k = 0; k < list_.count[p]; ++k) {
                const Vector<Dim>& v = vI[list_.node[base + k]];
                const Vector<Dim>& g = list_.gradient[base + k];
                for (int b = 0; b < Dim; ++b)
                    for (int a = 0; a < Dim; ++a) L(a, b) += v[a] * g[b];
            }
            if (F_) (*F_)[p] = (Tensor<Dim>::Identity() + dt * L) * (*F_)[p];
        }
        // Without F (no law reads it): J^{n+1} = det(I + dt L) J^n, the determinant of the same
        // update (plane strain: F_zz = 1).
        const Tensor<3> F3 = F_ ? embed<Dim>((*F_)[p], 1.0) : Tensor<3>::Identity();
        const double Jnow =
            F_ ? F3.determinant()
               : (move ? embed<Dim>(Tensor<Dim>(Tensor<Dim>::Identity() + dt * L), 1.0).determinant() *
                             (*J_)[p]
                       : (*J_)[p]);
        // An inverted particle (J <= 0) keeps its last stress: the state check stops the run on
        // its J, and the state written for diagnosis holds no NaN of a law evaluated out of range.
        if (!(Jnow > 0)) {
            (*J_)[p] = Jnow;
            return;
        }
        if (ul_->handles((*material_)[p])) {
            // Equation of state + strength: p and tau advanced with L over the step from the
            // J of the previous step (UpdatedLagrangianStress.hpp); W = rho0 e.
            const double Jnew = Jnow;
            ul_->update(p, L, (*J_)[p], Jnew, rho0_[p], dt, advanceState, (*sigma_)[p],
                        sigmaZZ_ ? &(*sigmaZZ_)[p] : nullptr, (*W_)[p]);
            (*J_)[p] = Jnew;
            return;
        }
        const Tensor<3> H3 = cofactor(F3);
        const double J = F3.determinant();
        Tensor<3> P3;
        double w = 0, pressure = 0;
        SymmTensor<3> cp;
        double epsP = 0;
        ConstitutiveLaw::Fields f;
        f.size = 1, f.F = &F3, f.H = &H3, f.J = &J, f.P = &P3, f.pressure = &pressure, f.energyDensity = &w;
        const ConstitutiveLaw& law = this->law(p);
        if (law.usesPlasticState()) {
            cp = SymmTensor<3>::fromFull(embed<Dim>((*plasticDeformation_)[p].full(),
                                                    plasticOutOfPlane_ ? (*plasticOutOfPlane_)[p] : 1.0));
            epsP = (*plasticStrain_)[p];
            f.plasticState = &cp, f.plasticStrain = &epsP;
            if (advanceState) f.plasticDissipation = &plasticLoss_[p];
        }
        law.stress(f, advanceState);
        if (advanceState && law.usesPlasticState()) {
            const Tensor<3> c = cp.full();
            (*plasticDeformation_)[p] = SymmTensor<Dim>::fromFull(inPlane<Dim>(c));
            if (plasticOutOfPlane_) (*plasticOutOfPlane_)[p] = c(2, 2);
            (*plasticStrain_)[p] = epsP;
        }
        // Cauchy sigma = P F^T / J (symmetric for an objective law; its symmetric part is stored).
        const Tensor<3> sigma = P3 * F3.transpose() / J;
        (*sigma_)[p] = SymmTensor<Dim>::fromFull(inPlane<Dim>(sigma));
        if (sigmaZZ_) (*sigmaZZ_)[p] = sigma(2, 2);
        (*J_)[p] = J;
        (*W_)[p] = w;
    });
    // The plastic flow's dissipation (the budget's D; the law's |s| dgamma per reference volume).
    if (advanceState && plastic_)
        dissipated_ +=
            GlobalReduce::sum<double>(n, [&](std::size_t p) { return m_[p] / rho0_[p] * plasticLoss_[p]; });
}

template <int Dim>
void MpmSolver<Dim>::smoothPressure() {
    if (!smoothing_->active() || !ul_->any()) return;
    auto timed = phase("stress");
    // A cell's mean reads its halo particles' J where they are now (USL and MUSL: after the
    // G2P); what the pass writes into the halo is discarded (the next step appends it afresh).
    particles_->refreshHalo(x_.data(), sizeof(Vector<Dim>));
    particles_->refreshHalo(J_->data(), sizeof(double));
    PressureSmoothingFields<Dim> f;
    f.position = x_;
    f.mass = m_;
    f.referenceDensity = rho0_;
    f.material = *material_;
    if (F_) f.deformationGradient = *F_;  // empty where no law reads F
    f.jacobian = *J_;
    f.cauchyStress = *sigma_;
    if (sigmaZZ_) f.cauchyStressZZ = *sigmaZZ_;
    f.smoothed = [this](std::int64_t k) { return ul_->isFluid(k); };
    f.pressureAt = [this](std::size_t p, double J) { return ul_->pressureAt(p, J, rho0_[p]); };
    if (auto* pressure = ul_->pressureField()) f.pressure = *pressure;
    f.globalId = particles_->globalId();
    smoothing_->apply(grid_, f);
}

template <int Dim>
void MpmSolver<Dim>::checkIsolated() {
    if (!stopIsolated_) return;
    const auto& mass = *nodeMass_;
    const std::size_t stride = list_.stride;
    // Isolated: on every node of its support the mass is the particle's own share, N_Ip m_p, to
    // round-off; no other particle is within reach, so its body has torn apart at it.
    auto isolated = [&](std::size_t p) {
        const std::size_t base = p * stride;
        for (std::size_t k = 0; k < list_.count[p]; ++k) {
            const double N = list_.weight[base + k];
            if (N <= 0) continue;
            // multiField: its own body's mass (another body's particles do not hold it together).
            const double m = multi_ ? bodyMass_[std::size_t((*region_)[p])][list_.node[base + k]]
                                    : mass[list_.node[base + k]];
            if (m - N * m_[p] > 1e-12 * m) return false;
        }
        return true;
    };
    Solver::checkState("particleToGrid", ownedCount(), isolated, [&](std::size_t p, double count) {
        std::ostringstream s;
        s << "particle " << particles_->globalId()[p] << " (body " << bodyName(p) << ") at "
          << vectorText<Dim>(x_[p]) << " shares no grid node with any other particle: it has separated from "
          << "its body by more than the shape function's support (numerical fracture, the extension "
             "instability of doc/methods/mpm.md section 6.2); "
          << count
          << " particle(s) isolated. Remedies: more particles per cell (particleGen), a coarser grid, "
             "or a wider shape function (uGIMP, quadraticBSpline); `isolatedParticles allow;` runs on";
        return s.str();
    });
}

template <int Dim>
void MpmSolver<Dim>::checkTorn() {
    // The extension instability of a piece (doc/methods/mpm.md section 6.2; the hanging block of
    // section 4.2 on the 8 x 8 grid with 5 x 5 points): particles are joined when they share a
    // grid node with N > 0, and a body (region) whose particles form more than one such piece
    // has torn apart by more than the support. A detached row falls as a piece while every one
    // of its particles still shares nodes with its neighbours in the row, so checkIsolated (a
    // piece of one) misses it and the run went on until the row left the grid. Union-find over
    // the nodes, serial, O(particles x support) per step, over the rank's owned and halo
    // particles; on several ranks the pieces are joined through the halo (below).
    if (!stopIsolated_) return;
    const std::size_t n = x_.size();
    const std::size_t stride = list_.stride;
    pieceParent_.resize(grid_.nodeCount());
    for (std::size_t i = 0; i < pieceParent_.size(); ++i) pieceParent_[i] = i;
    auto find = [&](std::size_t a) {
        while (pieceParent_[a] != a) a = pieceParent_[a] = pieceParent_[pieceParent_[a]];
        return a;
    };
    // A particle's piece is the root of its first node of N > 0 (every particle has one: sum N = 1).
    auto firstNode = [&](std::size_t p) {
        const std::size_t base = p * stride;
        for (std::size_t k = 0; k < list_.count[p]; ++k)
            if (list_.weight[base + k] > 0) return std::size_t(list_.node[base + k]);
        return std::size_t(list_.node[base]);
    };
    for (std::size_t p = 0; p < n; ++p) {
        const std::size_t base = p * stride;
        const std::size_t a = find(firstNode(p));
        for (std::size_t k = 0; k < list_.count[p]; ++k)
            if (list_.weight[base + k] > 0) {
                const std::size_t b = find(std::size_t(list_.node[base + k]));
                if (b != a) pieceParent_[b] = a;
            }
    }
    // A piece is named by the lowest global id among its particles here (owned and halo).
    auto& root = pieceRoot_;
    root.resize(n);
    const auto& id = particles_->globalId();
    const std::int64_t none = std::numeric_limits<std::int64_t>::max();
    pieceLabel_.assign(grid_.nodeCount(), none);
    for (std::size_t p = 0; p < n; ++p) {
        root[p] = find(firstNode(p));
        pieceLabel_[root[p]] = std::min(pieceLabel_[root[p]], id[p]);
    }
    // Several ranks: a rank's piece holding a halo particle is the same body piece as its owner's
    // piece holding it (every two particles sharing a node are both held by the owner of either),
    // so the pieces join through the halo's labels as their owners have them: a few pairs of
    // labels, gathered everywhere and joined (union-find over labels, the lowest naming each).
    std::map<std::int64_t, std::int64_t> joined;  // label -> a lower label of the same piece
    auto findLabel = [&](std::int64_t a) {
        for (auto it = joined.find(a); it != joined.end(); it = joined.find(a)) a = it->second;
        return a;
    };
    const std::size_t owned = ownedCount();
    if (decomposition_) {
        std::vector<std::int64_t> ownerLabel(n);
        for (std::size_t p = 0; p < n; ++p) ownerLabel[p] = pieceLabel_[root[p]];
        particles_->refreshHalo(ownerLabel.data(), sizeof(std::int64_t));
        std::vector<std::pair<std::int64_t, std::int64_t>> local;
        for (std::size_t h = owned; h < n; ++h)
            if (ownerLabel[h] != pieceLabel_[root[h]])
                local.emplace_back(pieceLabel_[root[h]], ownerLabel[h]);
        std::sort(local.begin(), local.end());
        local.erase(std::unique(local.begin(), local.end()), local.end());
        std::vector<std::int64_t> flat;
        for (const auto& [a, b] : local) flat.push_back(a), flat.push_back(b);
        const std::vector<std::int64_t> all = globalConcatenation(flat);
        for (std::size_t k = 0; k + 1 < all.size(); k += 2) {
            const std::int64_t a = findLabel(all[k]), b = findLabel(all[k + 1]);
            if (a != b) joined[std::max(a, b)] = std::min(a, b);
        }
    }
    // Per piece: its particles (every region) and, per region, its lowest id, over all ranks;
    // a body's main piece is its largest, ties to the one holding the body's lowest id (the serial
    // run's first in index order); a particle of any other piece is torn off.
    std::map<std::int64_t, std::int64_t> size;                                  // label -> particles
    std::map<std::pair<std::int64_t, std::int64_t>, std::int64_t> regionFirst;  // (label, region) -> id
    const auto& region = particles_->region();
    std::vector<std::int64_t> label(owned);
    {
        std::size_t lastRoot = std::numeric_limits<std::size_t>::max();
        std::int64_t lastLabel = 0;
        for (std::size_t p = 0; p < owned; ++p) {
            if (root[p] != lastRoot) lastRoot = root[p], lastLabel = findLabel(pieceLabel_[root[p]]);
            label[p] = lastLabel;
            ++size[lastLabel];
            auto [it, fresh] = regionFirst.try_emplace({lastLabel, region[p]}, id[p]);
            if (!fresh) it->second = std::min(it->second, id[p]);
        }
    }
    if (decomposition_) {
        std::vector<std::int64_t> flat;
        for (const auto& [l, c] : size) flat.push_back(l), flat.push_back(c);
        const std::vector<std::int64_t> sizes = globalConcatenation(flat);
        size.clear();
        for (std::size_t k = 0; k + 1 < sizes.size(); k += 2) size[sizes[k]] += sizes[k + 1];
        flat.clear();
        for (const auto& [key, first] : regionFirst)
            flat.push_back(key.first), flat.push_back(key.second), flat.push_back(first);
        const std::vector<std::int64_t> firsts = globalConcatenation(flat);
        regionFirst.clear();
        for (std::size_t k = 0; k + 2 < firsts.size(); k += 3) {
            auto [it, fresh] = regionFirst.try_emplace({firsts[k], firsts[k + 1]}, firsts[k + 2]);
            if (!fresh) it->second = std::min(it->second, firsts[k + 2]);
        }
    }
    struct Main {
        std::int64_t label, size, first;
    };
    std::map<std::int64_t, Main> mainPiece;  // region -> its main piece
    for (const auto& [key, first] : regionFirst) {
        if (key.second < 0) continue;
        Main& m = mainPiece.try_emplace(key.second, Main{0, 0, none}).first->second;
        const std::int64_t s = size[key.first];
        if (s > m.size || (s == m.size && first < m.first)) m = {key.first, s, first};
    }
    auto torn = [&](std::size_t p) { return region[p] >= 0 && label[p] != mainPiece.at(region[p]).label; };
    Solver::checkState("particleToGrid", owned, torn, [&](std::size_t p, double count) {
        std::ostringstream s;
        s << "body " << bodyName(p) << " has torn apart: particle " << id[p] << " at "
          << vectorText<Dim>(x_[p]) << " is in a piece of " << size.at(label[p])
          << " particle(s) that shares no grid node with the body's main piece ("
          << mainPiece.at(region[p]).size
          << " particles): numerical fracture, the extension instability of doc/methods/mpm.md section "
             "6.2; "
          << count
          << " particle(s) torn off. Remedies: more particles per cell (particleGen), a coarser grid, or a "
             "wider shape function (uGIMP, quadraticBSpline); `isolatedParticles allow;` runs on";
        return s.str();
    });
}

template <int Dim>
void MpmSolver<Dim>::checkFinite(const char* phaseName) const {
    auto bad = [&](std::size_t i) {
        return !x_[i].allFinite() || !v_[i].allFinite() || (F_ && !(*F_)[i].allFinite()) || !((*J_)[i] > 0) ||
               !(*sigma_)[i].full().allFinite();
    };
    Solver::checkState(phaseName, ownedCount(), bad, [&](std::size_t i, double count) {
        std::ostringstream s;
        s.precision(6);
        s << "particle " << particles_->globalId()[i] << " (body " << bodyName(i) << ", material "
          << materials_->names()[(*material_)[i]] << ") at " << vectorText<Dim>(x_[i])
          << " has J = " << (*J_)[i] << ", |v| = " << v_[i].norm() << "; " << count
          << " particle(s) affected. ";
        if (!((*J_)[i] > 0))
            s << "The particle is inverted (J <= 0): too large a step (lower maxCo or deltaT), or a law "
                 "unstable in compression (stVenantKirchhoff below a stretch of 1/sqrt(3), note 1: use "
                 "neoHookean)";
        else
            s << "The state is no longer finite: the step is unstable (lower maxCo or deltaT)";
        return s.str();
    });
}

template <int Dim>
void MpmSolver<Dim>::allocateBodyFields() {
    const std::size_t bodies = bodyNames_.size(), nodes = grid_.nodeCount();
    bodyMass_.assign(bodies, std::vector<double>(nodes, 0.0));
    bodyVolume_.assign(bodies, std::vector<double>(nodes, 0.0));
    for (auto* f : {&bodyMomentum_, &bodyGradient_, &bodyPosition_, &bodyNodeForce_, &bodyVelocity_,
                    &bodyAcceleration_})
        f->assign(bodies, std::vector<Vector<Dim>>(nodes, Vector<Dim>::Zero()));
}

template <int Dim>
void MpmSolver<Dim>::correctContact(double dt, bool afterForce, double t) {
    ContactNodes<Dim> nodes;
    nodes.mass = &bodyMass_;
    nodes.massGradient = &bodyGradient_;
    nodes.massPosition = &bodyPosition_;
    nodes.volume = &bodyVolume_;
    nodes.velocity = &bodyVelocity_;
    nodes.acceleration = afterForce ? &bodyAcceleration_ : nullptr;
    nodes.grid = &grid_;
    nodes.shape = shape_.get();
    nodes.massCutoff = massCutoff_;
    nodes.cellSize = grid_.smallestCellSize();
    nodes.cellVolume = grid_.cellSize().prod();
    if (!ownedNode_.empty()) nodes.countedNodes = &ownedNode_;
    std::vector<Vector<Dim>> force = contact_->correct(nodes, dt);
    if (!afterForce || force.empty()) return;
    if (decomposition_)
        for (auto& F : force)
            for (int d = 0; d < Dim; ++d) F[d] = globalSum(F[d]);
    // One row a step: time, then per pair (a, b) the force on a from b and its magnitude.
    const std::size_t B = bodyNames_.size();
    if (!contactCsv_) {
        std::vector<std::string> columns{"time"};
        const char* axis[] = {"x", "y", "z"};
        for (std::size_t a = 0; a < B; ++a)
            for (std::size_t b = a + 1; b < B; ++b) {
                const std::string pair = bodyNames_[a] + "_" + bodyNames_[b];
                for (int d = 0; d < Dim; ++d) columns.push_back(pair + "_" + axis[d]);
                columns.push_back(pair + "_magnitude");
            }
        contactCsv_ = std::make_unique<CsvFile>(
            runCase().postProcessing() / "contact" / startTimeName() / "contactForces.csv", columns, t);
        contactRow_.reserve(columns.size());
    }
    contactRow_.assign(1, t + dt);
    for (std::size_t a = 0; a < B; ++a)
        for (std::size_t b = a + 1; b < B; ++b) {
            const Vector<Dim>& F = force[Contact<Dim>::pairIndex(a, b, B)];
            for (int d = 0; d < Dim; ++d) contactRow_.push_back(F[d]);
            contactRow_.push_back(F.norm());
            if (F.norm() > peakContactForce_) {
                peakContactForce_ = F.norm();
                peakContactTime_ = t + dt;
                peakContactPair_ = bodyNames_[a] + " - " + bodyNames_[b];
            }
        }
    contactCsv_->row(contactRow_);
}

template <int Dim>
void MpmSolver<Dim>::step(double dt) {
    const double t = time().value();
    // Several ranks: the halo for this step's sums, removed however the step ends (a diagnosis
    // throws from a state check: the state written then is the owned particles').
    struct HaloScope {
        ParticleSetBase* set = nullptr;
        ~HaloScope() {
            if (set) set->clearGhosts();
        }
    } halo;
    if (decomposition_) {
        updateDecomposition();
        auto timed = phase("shapeFunctions");
        decomposition_->appendHalo(*particles_, haloFields_);
        halo.set = particles_;
    }
    ++steps_;
    const double kineticStart = particleKinetic();
    evaluateShapeFunctions();
    {
        auto timed = phase("particleToGrid");
        mapMassAndMomentum();
    }
    checkIsolated();
    checkTorn();
    const auto order = scheme_->stressUpdate();
    if (order == MpmScheme::StressUpdate::first) {
        // USF: the stress from the velocity the particles bring, v_I^n = (mv)_I / m_I.
        nodeVelocityFromMomentum(t);
        updateStress(dt, true);
        smoothPressure();
        // The forces read the halo's new J and sigma.
        particles_->refreshHalo(J_->data(), sizeof(double));
        particles_->refreshHalo(sigma_->data(), sizeof(SymmTensor<Dim>));
    }
    {
        auto timed = phase("particleToGrid");
        mapForces(t);
    }
    solveGrid(dt, t);
    gridToParticles(dt);
    // The transfers' loss (the energy budget's D, the header's equations): what P2G loses from the
    // particles' kinetic energy to the grid's (K_p^n - K^n) and G2P from the grid's constrained one
    // to the particles' new one (K+ - K_p^{n+1}); the solve between them is f's work and the grid
    // conditions' and damping's (W, solveGrid).
    dissipated_ += (kineticStart - gridKineticStart_) + (gridKineticSolved_ - particleKinetic());
    if (order == MpmScheme::StressUpdate::modifiedLast) {
        // MUSL: the updated particle velocities mapped back, v_I = sum N m v_p^{n+1} / m_I.
        auto timed = phase("particleToGrid");
        // The map reads the halo's moved x, v (and C) of this step's G2P.
        particles_->refreshHalo(x_.data(), sizeof(Vector<Dim>));
        particles_->refreshHalo(v_.data(), sizeof(Vector<Dim>));
        if (C_) particles_->refreshHalo(C_->data(), sizeof(Tensor<Dim>));
        mapMassAndMomentum();
        nodeVelocityFromMomentum(t + dt);
    }
    if (order != MpmScheme::StressUpdate::first) {
        updateStress(dt, true);
        smoothPressure();
    }
    particleSteps_ += std::int64_t(ownedCount());
    checkFinite("step");
}

template <int Dim>
double MpmSolver<Dim>::particleKinetic() const {
    return GlobalReduce::sum<double>(ownedCount(),
                                     [&](std::size_t i) { return 0.5 * m_[i] * v_[i].squaredNorm(); });
}

template <int Dim>
double MpmSolver<Dim>::gridKinetic() const {
    // The nodes the solve updates (m_I >= massCutoff; the others' v is 0), each counted by one rank.
    auto kinetic = [&](const std::vector<double>& m, const std::vector<Vector<Dim>>& v) {
        return GlobalReduce::sum<double>(v.size(), [&](std::size_t I) {
            return m[I] >= massCutoff_ && countsNode(I) ? 0.5 * m[I] * v[I].squaredNorm() : 0.0;
        });
    };
    if (!multi_) return kinetic(*nodeMass_, *nodeVelocity_);
    double k = 0;
    for (std::size_t b = 0; b < bodyMass_.size(); ++b) k += kinetic(bodyMass_[b], bodyVelocity_[b]);
    return k;
}

template <int Dim>
std::vector<HealthIndicator> MpmSolver<Dim>::healthIndicators() const {
    // smallMassNodes: the small-mass problem of MPM (a node at the edge of the body that only the
    // tails of the shape functions reach: m_I = sum N_Ip m_p tiny while grad N_Ip is not, so the
    // node's acceleration f_I / m_I and through L = sum v_I (x) grad N_Ip the stress blow up;
    // Sulsky, Zhou & Schreyer 1995; Steffen, Kirby & Berzins 2008; de Vaucorbeil et al. 2020,
    // section 4). Measured as the node's own explicit-stability number: with the lumped mass m_I
    // and the diagonal stiffness K_II = sum_p V_p grad N_Ip . C grad N_Ip <= sum_p m_p c_p^2
    // |grad N_Ip|^2 (rho_p V_p = m_p, C's largest eigenvalue rho c_p^2 along grad N), the Rayleigh
    // quotient omega_I^2 = K_II / m_I bounds the largest frequency of the linearised step from
    // below, so dt omega_I / 2 > 1 proves the central-difference (symplectic Euler) step unstable
    // at that node. Value: the largest dt omega_I / 2 over the solved nodes (m_I >= massCutoff;
    // an interior node of a uniform body with linear hats has about Co / sqrt(2) in 1D); count:
    // the particles reaching a node above 1 (N_Ip > 0); worst: the particle of lowest global id
    // reaching the worst node. Over each
    // body's own field under multiField. Computed at the health check's writes only.
    HealthIndicator indicator{
        "smallMassNodes", 0.0, 0, -1,
        "max over the grid nodes of dt omega_I / 2, omega_I^2 = sum_p m_p c_p^2 "
        "|grad N_Ip|^2 / m_I (the node's Rayleigh quotient); counted: particles reaching a "
        "node above 1, where the explicit step is unstable (the small-mass problem, "
        "Sulsky et al. 1995)"};
    // Between steps the set holds the owned particles; the list and the colouring are the last
    // step's, over the owned and (several ranks) the halo particles, whose m c^2 and body come
    // from their owners (the halo plan is the last step's: particles migrate at a step's start).
    const std::size_t n = ownedCount(), nodes = grid_.nodeCount(), stride = list_.stride;
    const std::size_t listed = list_.count.size();
    const std::size_t fields = multi_ ? bodyMass_.size() : 1;
    const double dt = time().deltaT();
    std::vector<double> stiffness(fields * nodes, 0.0);
    const bool mapped = time().timeIndex() > 0 &&
                        listed == n + (decomposition_ ? decomposition_->haloSize() : std::size_t(0));
    std::vector<double> mc2(listed, 0.0);
    std::vector<std::int64_t> body(multi_ ? listed : 0, 0);
    if (mapped) {
        for (std::size_t p = 0; p < n; ++p) mc2[p] = m_[p] * waveSpeed(p) * waveSpeed(p);
        if (multi_) std::copy(region_->begin(), region_->begin() + std::ptrdiff_t(n), body.begin());
        if (decomposition_) {
            decomposition_->refresh(mc2.data(), sizeof(double), n);
            if (multi_) decomposition_->refresh(body.data(), sizeof(std::int64_t), n);
        }
        colouring_.forEachParticle([&](std::size_t p) {
            const std::size_t offset = multi_ ? std::size_t(body[p]) * nodes : 0;
            const std::size_t base = p * stride;
            for (std::size_t k = 0; k < list_.count[p]; ++k)
                stiffness[offset + list_.node[base + k]] += mc2[p] * list_.gradient[base + k].squaredNorm();
        });
    }
    auto massOf = [&](std::size_t j) { return multi_ ? bodyMass_[j / nodes][j % nodes] : (*nodeMass_)[j]; };
    // Complete at every node an owned particle reaches; the largest is taken over the nodes each
    // rank counts (the others may be short of particles here).
    auto number = [&](std::size_t j) {
        const double m = massOf(j);
        return mapped && m >= massCutoff_ ? 0.5 * dt * std::sqrt(stiffness[j] / m) : 0.0;
    };
    indicator.value = GlobalReduce::max(
        fields * nodes, [&](std::size_t j) { return countsNode(j % nodes) ? number(j) : 0.0; });
    // The largest number over the nodes particle p reaches (N_Ip > 0).
    auto reached = [&](std::size_t p) {
        if (!mapped) return 0.0;
        const std::size_t offset = multi_ ? std::size_t((*region_)[p]) * nodes : 0;
        const std::size_t base = p * stride;
        double largest = 0;
        for (std::size_t k = 0; k < list_.count[p]; ++k)
            if (list_.weight[base + k] > 0)
                largest = std::max(largest, number(offset + list_.node[base + k]));
        return largest;
    };
    indicator.count = std::size_t(
        GlobalReduce::sum<double>(n, [&](std::size_t p) { return reached(p) > 1.0 ? 1.0 : 0.0; }));
    double worst = std::numeric_limits<double>::infinity();
    if (indicator.value > 0)
        for (std::size_t p = 0; p < n; ++p)
            if (reached(p) >= indicator.value) worst = std::min(worst, double(particles_->globalId()[p]));
    worst = globalMin(worst);
    if (std::isfinite(worst)) indicator.worst = std::int64_t(worst);
    return {indicator};
}

template <int Dim>
std::optional<double> MpmSolver<Dim>::internalEnergy() const {
    // The exact stored energy sum_p V0_p W(F_p) (note 4.3 [D]; not 1/2 sigma:eps): a
    // conservation sum over the whole body.
    return GlobalReduce::sum<double>(x_.size(), [&](std::size_t i) { return m_[i] / rho0_[i] * (*W_)[i]; });
}

template <int Dim>
std::optional<double> MpmSolver<Dim>::potentialEnergy() const {
    if (!bodyForce_) return std::nullopt;
    return GlobalReduce::sum<double>(
        x_.size(), [&](std::size_t i) { return m_[i] * bodyForce_->potential(x_[i].data()); });
}

namespace {
const std::vector<std::string> gridOutputFields{"mass", "momentum", "velocity", "force"};
std::string gridPieceName(int rank) {
    return "grid_" + std::to_string(rank) + ".vti";
}
}  // namespace

template <int Dim>
std::vector<ExtraFile> MpmSolver<Dim>::extraOutput() const {
    if (!writeGrid_) return {};
    if (!decomposition_) return {vtiFile(grid_, time().value(), "grid.vti", gridOutputFields)};
    // The index of the ranks' slabs (pieceOutput); every rank's grid has the fields' types.
    return {{"grid.pvti",
             pvtiText(grid_, gridOutputFields, gridPieceCount(grid_, Communicator::size()), gridPieceName)}};
}

template <int Dim>
std::vector<ExtraFile> MpmSolver<Dim>::pieceOutput() const {
    if (!writeGrid_ || !decomposition_) return {};
    // A rank's nodes are no box (each node is counted by the owner of the lowest-id particle
    // reaching it), so the pieces are slabs along the last axis (VtiWriter.hpp), each filled
    // from the gathered image: the values of the serial run's grid.vti to the bit.
    const CartesianGrid<Dim> whole = gatheredGrid(gridOutputFields);
    const int pieces = gridPieceCount(grid_, Communicator::size());
    const int rank = Communicator::rank();
    if (rank >= pieces) return {};
    return {{gridPieceName(rank), vtiPieceText(whole, time().value(), gridOutputFields, rank, pieces)}};
}

template <int Dim>
CartesianGrid<Dim> MpmSolver<Dim>::gatheredGrid(const std::vector<std::string>& fields) const {
    // The whole grid as the serial run has it: each node from the rank that counts it, the
    // nodes no particle reaches from this rank's own arrays (zero, or what a grid condition set:
    // the same on every rank). The values travel as their bits (exact).
    CartesianGrid<Dim> whole(grid_.origin(), grid_.cellSize(), grid_.cells());
    const FieldStore& mine = grid_.nodes();
    FieldStore& out = whole.nodes();
    std::vector<std::int64_t> packed;
    for (const auto& name : fields) {
        if (name == "mass") {
            const auto& local = mine.requireField<double>(name);
            auto& all = out.field<double>(name);
            all = local;
            packed.clear();
            for (std::size_t I = 0; I < local.size(); ++I)
                if (countsNode(I))
                    packed.push_back(std::int64_t(I)),
                        packed.push_back(std::bit_cast<std::int64_t>(local[I]));
            const auto gathered = globalConcatenation(packed);
            for (std::size_t k = 0; k + 1 < gathered.size(); k += 2)
                all[std::size_t(gathered[k])] = std::bit_cast<double>(gathered[k + 1]);
            continue;
        }
        const auto& local = mine.requireField<Vector<Dim>>(name);
        auto& all = out.field<Vector<Dim>>(name);
        all = local;
        packed.clear();
        for (std::size_t I = 0; I < local.size(); ++I) {
            if (!countsNode(I)) continue;
            packed.push_back(std::int64_t(I));
            for (int d = 0; d < Dim; ++d) packed.push_back(std::bit_cast<std::int64_t>(local[I][d]));
        }
        const auto gathered = globalConcatenation(packed);
        for (std::size_t k = 0; k + Dim < gathered.size(); k += Dim + 1)
            for (int d = 0; d < Dim; ++d)
                all[std::size_t(gathered[k])][d] = std::bit_cast<double>(gathered[k + 1 + std::size_t(d)]);
    }
    return whole;
}

template <int Dim>
std::vector<std::string> MpmSolver<Dim>::summary(double loopSeconds) const {
    std::vector<std::string> lines;
    char line[200];
    (void)loopSeconds;  // SolverRun prints the particle-steps/s
    std::snprintf(line, sizeof line, "P2G colouring        %zu colours of tiles of %d", colouring_.colours(),
                  colouring_.period()[0]);
    std::string text = line;
    for (int d = 1; d < Dim; ++d) text += " x " + std::to_string(colouring_.period()[d]);
    lines.push_back(text + " cells (ParticleColouring.hpp)");
    if (multi_) {
        if (peakContactPair_.empty())
            std::snprintf(line, sizeof line, "contact multiField   no contact force between %zu bodies",
                          bodyNames_.size());
        else
            std::snprintf(
                line, sizeof line,
                "contact multiField   peak pair force %.6g N (per m of depth in 2D; %s) at t = %.6g s",
                peakContactForce_, peakContactPair_.c_str(), peakContactTime_);
        lines.push_back(line);
    }
    if (decomposition_)
        for (auto& l : decomposition_->summary(*particles_, double(steps_), "step"))
            lines.push_back(std::move(l));
    if (removedParticles_ > 0) {
        std::snprintf(line, sizeof line,
                      "outsideGrid remove   %zu particles, %.6g kg (%.4g%% of the initial mass)",
                      removedParticles_, removedMass_, 100.0 * removedMass_ / initialMass_);
        lines.push_back(line);
    }
    return lines;
}

template class MpmSolver<1>;
template class MpmSolver<2>;
template class MpmSolver<3>;

MFDYN_REGISTER_SOLVER(MpmSolver, "mpmFsi",
                      "The explicit material point method (USL/USF/MUSL, FLIP/PIC/APIC)");

}  // namespace mfdyn
