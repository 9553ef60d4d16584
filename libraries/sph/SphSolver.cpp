// impactSph's discretisation (Zisis 2017; doc/methods/sph-impact.md §2–4), for a pair i, j, x_ij = x_i − x_j,
// r̂ = x_ij/|x_ij|, v_ij = v_i − v_j and ∇_iW_ij(h) = r̂ dW/dr:
//
//   density sums (loop A)  S_i = Σ_j b_j W_ij(h_i),  ω_i = 1 + h_i/(d S_i) Σ_j b_j ∂W_ij/∂h(h_i),
//                          ñ_i = Σ_j W_ij(h_i)
//   continuity             dρ_i/dt = (c_i/ω_i) Σ_j b_j v_ij·∇_iW_ij(h_i)  (+ mass flux, Dissipation.hpp)
//   momentum               m_i dv_i/dt = −Σ_j [a_i b_j P_i/ω_i ∇_iW_ij(h_i) + a_j b_i P_j/ω_j ∇_iW_ij(h_j)]
//                          (+ viscosity)
//   energy                 de_i/dt = (P_i/ρ_i²)(c_i/ω_i) Σ_j b_j v_ij·∇_iW_ij(h_i)  (+ heating, conduction)
//
// Strength (Zisis 2017 eqs. 6.5–6.9, volume form without ω; sign of 6.9 corrected, note §12):
//   velocity gradient      L_i = −Σ_j (m_j/ρ_j) v_ij ⊗ ∇_iW_ij(h_i),   (L_ab = ∂v_a/∂x_b)
//   force                  dv_i/dt += ρ_i⁻¹ Σ_j (m_j/ρ_j) [τ_i ∇_iW_ij(h_i) + τ_j ∇_iW_ij(h_j)]
//   heating                de_i/dt += (τ_i/ρ_i) : L_i
//   stress                 dτ/dt from the material's strength law (Jaumann rate), integrated with
//                          U by the leapfrog and returned to the yield surface after each update.
//
// with the scheme's a, b, c (DensityScheme.hpp); the sums include the particle itself where W(0) ≠ 0.
// Leapfrog (Zisis 2017 eqs. 4.29–4.34), U = {v, ρ, e}, f = dU/dt:
//
//   start         U^{1/2} = U^0 + f(x^0, U^0) Δt/2
//   step k        f^k = f(x^k, U^k);  U^{k+1/2} = U^{k−1/2} + f^k (Δt_{k−1} + Δt_k)/2;
//                 x^{k+1} = x^k + v^{k+1/2} Δt_k;  U^{k+1} = U^{k+1/2} + f^k Δt_k/2
//
// (the half-step weight (Δt_{k−1} + Δt_k)/2 reduces to the thesis's Δt for a constant step).
// Time step: Δt ≤ ξ min_i h_i/(|v_i| + c_L,i) and, optionally, Δt ≤ ξ_ρ min_i ρ_i/|dρ_i/dt| (note §4),
// with c_L² = c² + M/ρ the longitudinal elastic wave speed of a solid (M = 2μ(1 − α) = 4G/3 in 3D,
// Strength::longitudinalStiffness; c_L = c for a fluid), as LAMMPS-SMD and Spheral take it: the
// deviatoric stress carries waves too, and a vote on the equation of state's c alone runs a solid
// 1.2 times past its Courant number (copper, aluminium). Measured (issue 16): the Taylor bar
// quarter at 0.2 mm with maxCo 0.2 on c gains energy from 49 µs (the leapfrog unstable in a
// cluster of the rim under −1 GPa of tension; +6e-5 of E by 56 µs, +1.3% by 80 µs); restarted at
// 48 µs with maxCo 0.168 = 0.2/1.19 (the step c_L gives) or 0.1 it keeps the energy to 1e-8.
// `courantSpeed bulk` gives the thesis's vote on c back.
#include "sph/SphSolver.hpp"

#include "core/ExactReal.hpp"
#include "core/Log.hpp"
#include "core/MessageText.hpp"
#include "core/Parallel.hpp"
#include "particles/Decomposition.hpp"
#include "solver/MaterialAssignment.hpp"
#include "solver/SolverRegistry.hpp"
#include "solver/SolverRun.hpp"
#include "sph/SphHealth.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <sstream>

namespace mfdyn {

namespace {

// e with P(ρ, e) = target, by bracketing and bisection (EOS are increasing in e at fixed ρ for
// every model here; the bracket grows until it holds the root).
double energyForPressure(const EquationOfState& eos, double rho, double target) {
    double lo = 0, hi = 1;
    auto f = [&](double e) { return eos.pressure(rho, e) - target; };
    if (f(lo) > 0) {
        lo = -1;
        while (f(lo) > 0 && lo > -1e30) lo *= 2;
    }
    while (f(hi) < 0 && hi < 1e30) hi *= 2;
    for (int k = 0; k < 200 && hi - lo > 1e-15 * std::max(1.0, std::abs(hi)); ++k) {
        const double mid = 0.5 * (lo + hi);
        (f(mid) < 0 ? lo : hi) = mid;
    }
    return 0.5 * (lo + hi);
}

// constant/sphProperties/artificialStress (Monaghan 2000; Gray, Monaghan & Swift 2001).
KeywordSchema artificialStressKeywords() {
    return KeywordSchema("impactSph", "artificialStress")
        .scalar("epsilon", "-", "epsilon: the fraction of the tensile principal stress opposed (0: off)")
        .atLeast(0)
        .orDefault(0.3)
        .scalar("exponent", "-", "n of the pair factor f_ij^n, f_ij = W(r_ij, h)/W(dp, h)")
        .orDefault(4.0);
}

}  // namespace

// constant/sphProperties. The family dictionaries are read by their families; `momentum`:
// variational (matched to the density scheme, conservative) or difference, dv_i/dt =
// −ρ_i⁻¹ Σ_j (m_j/ρ_j)(P_j − P_i) ∇_iW_ij(h_i), free of the K-error of §7 but not
// momentum-conserving (Zisis 2017 §2.4: rejected for shocks, offered for comparison);
// `integrator`: leapfrog (Zisis 2017 eqs. 4.29–4.34, one rate evaluation a step) or
// predictorCorrector (the midpoint rule, two evaluations a step, no state carried between steps):
//   U* = U^n + f(x^n, U^n) Δt/2,  x* = x^n + v^n Δt/2;   f* = f(x*, U*);
//   U^{n+1} = U^n + f* Δt,        x^{n+1} = x^n + (v^n + f_v* Δt/2) Δt.
template <int Dim>
KeywordSchema SphSolver<Dim>::keywords() {
    return KeywordSchema("solver", "impactSph")
        .dictionary("kernel", "the smoothing kernel W(r, h) (family kernel)")
        .dictionary("densityScheme", "the density measure, its form and gradH terms (family densityScheme)")
        .dictionary("smoothingLength", "the smoothing-length law h (family smoothingLength)")
        .dictionary("dissipation", "the artificial dissipation (family dissipation)")
        .scalar("densityRateLimit", "-", "xi_rho of the time-step limit dt <= xi_rho rho/|drho/dt| (0: off)")
        .atLeast(0)
        .orDefault(0.0)
        .scalar("neighbourSkin", "-", "Verlet skin as a fraction of the initial median support radius")
        .atLeast(0)
        .orDefault(0.2)
        .word("neighbourRebuild", {"checked", "skin"},
              "when the Verlet list is rebuilt: checked (the particles that outran half the skin are "
              "tested for new neighbours) or skin (once 2 D + G exceeds the skin; rebuilds at almost every "
              "step of a strong shock)")
        .orDefault("checked")
        .word("mirrorGhosts", {"withList", "everyStep"},
              "when the mirror-ghost layer is built: withList (at list rebuilds, one support plus the "
              "skin thick, re-placed from its sources in between; rebuilt when a particle comes within "
              "reach of a plane from beyond it) or everyStep (each step, and the list with it: the "
              "former way, for comparison; the same results)")
        .orDefault("withList")
        .word("momentum", {"variational", "difference"},
              "momentum equation: variational (conservative) or difference (for comparison)")
        .orDefault("variational")
        .word("courantSpeed", {"longitudinal", "bulk"},
              "the wave speed of the Courant limit: longitudinal (sqrt(c^2 + M/rho), M = 4G/3 in 3D "
              "from the strength law: the elastic wave speed of a solid) or bulk (the equation of "
              "state's c alone, the thesis's; a solid then runs 1.2 times past maxCo)")
        .orDefault("longitudinal")
        .word("integrator", {"leapfrog", "predictorCorrector"},
              "time integrator: leapfrog (one rate evaluation a step) or midpoint predictor-corrector")
        .orDefault("leapfrog")
        .dictionary("artificialStress",
                    "Monaghan's artificial stress against the tensile instability of solids")
        .optional()
        .nested(&artificialStressKeywords);
}

template <int Dim>
SphSolver<Dim>::SphSolver(SolverRun& run)
    : Solver(run),
      owner_(adoptParticleSet<Dim>(run.takeParticles())),
      particles_(owner_.get()),
      properties_(openConstant("sphProperties")),
      materialProperties_(openConstant("materialProperties")),
      settings_(keywords().read(properties_)),
      kernel_(Kernel::New(settings_.dictionary("kernel"))),
      W_(kernel_->template evaluator<Dim>()),
      scheme_(DensityScheme::New(settings_.dictionary("densityScheme"))),
      hLaw_(SmoothingLengthLaw::New(settings_.dictionary("smoothingLength"))),
      dissipation_(Dissipation::New(settings_.dictionary("dissipation"))),
      densityRateLimit_(settings_.scalar("densityRateLimit")),
      neighbourSkin_(settings_.scalar("neighbourSkin")),
      omegaMin_(scheme_->omegaMin()),
      differenceForm_(settings_.word("momentum") == "difference"),
      predictorCorrector_(settings_.word("integrator") == "predictorCorrector"),
      ghostsEveryStep_(settings_.word("mirrorGhosts") == "everyStep"),
      materials_(materialProperties_,
                 MaterialModels{"impactSph", ModelUse::required, ModelUse::optional, ModelUse::refused}),
      x_(particles_->position()),
      v_(particles_->vectorField("velocity")),
      m_(requireScalarField(*particles_, "mass", "particle masses")),
      rho_(requireScalarField(*particles_, "density", "initial density")),
      p_(particles_->scalarField("pressure")),
      c_(particles_->scalarField("soundSpeed")),
      h_(particles_->scalarField("smoothingLength")),
      material_(particles_->integerField("material")) {
    declarePhases(
        {"updateNeighbours", "densitySums", "equationOfState", "computeRates", "strength", "integrate"});
    readMaterials();
    initialiseFields();
    if (settings_.word("courantSpeed") == "longitudinal" && materials_.anyStrength())
        for (std::size_t k = 0; k < materials_.size(); ++k)
            longitudinalStiffness_.push_back(
                materials_[k].strength ? materials_[k].strength->longitudinalStiffness() : 0.0);
    if (settings_.given("artificialStress")) {
        const KeywordValues& as = settings_.nested("artificialStress");
        artificialStressEpsilon_ = as.scalar("epsilon");
        artificialStressExponent_ = as.scalar("exponent");
        if (!materials_.anyStrength())
            throw settings_.error("artificialStress",
                                  "artificial stress acts on solids: no material has a strength law");
    }
    boundaries_ = readBoundaryConditions(*particles_, {.ghosts = true, .boundaryForces = false});
    decomposition_ = run.decomposition();
    if (decomposition_) {
        // What the phases read of a neighbour before they refresh it themselves: the kernel
        // factors and density sums read x, h, m and rho, the force loop v, e and the stress
        // (tau refreshed by its reflection); p, c, omega and the number density are refreshed
        // where they are computed (copyToGhosts). The half-step fields never travel.
        // The region too: a boundary condition's selection judges halo particles (mirror sources).
        haloFields_ = {"position", "velocity", "mass", "density", "smoothingLength", "material", "region"};
        if (e_) haloFields_.push_back("specificInternalEnergy");
        if (tau_) haloFields_.push_back("deviatoricStress");
        // Planned now, so that what runs before the first step (the function objects at the
        // start time, the health indicators) sees each rank's neighbours across its cuts.
        updateDecomposition();
    }
}

template <int Dim>
SphSolver<Dim>::~SphSolver() = default;

template <int Dim>
void SphSolver<Dim>::readMaterials() {
    assignMaterials(*particles_, materials_.names(), materialProperties_);
}

template <int Dim>
void SphSolver<Dim>::initialiseFields() {
    const std::size_t n = x_.size();
    checkPositiveMassAndDensity(*particles_, m_, rho_);
    if (materials_.needsEnergy()) {
        const bool hadEnergy = particles_->hasField("specificInternalEnergy");
        e_ = &particles_->scalarField("specificInternalEnergy");
        if (!hadEnergy) {
            if (!particles_->hasField("pressure") && n > 0)
                throw InputError(
                    "the particle file has neither 'specificInternalEnergy' nor 'pressure': one of them "
                    "sets the initial thermodynamic state");
            // p_ was read from the file: invert the equation of state for e.
            for (std::size_t i = 0; i < n; ++i)
                (*e_)[i] = energyForPressure(*materials_[material_[i]].eos, rho_[i], p_[i]);
        }
    }
    for (std::size_t i = 0; i < n; ++i)
        if (!(h_[i] > 0)) h_[i] = hLaw_->initial(Dim, m_[i], rho_[i]);
    if (scheme_->gradH()) omega_ = &particles_->scalarField("omega");
    if (hLaw_->needsNumberDensity() || scheme_->gradH()) number_ = &particles_->scalarField("numberDensity");
    // The leapfrog carries the half-step state between steps; the predictor-corrector does not.
    if (!predictorCorrector_) {
        vHalf_ = &particles_->vectorField("velocityHalfStep");
        if (!scheme_->summation()) rhoHalf_ = &particles_->scalarField("densityHalfStep");
        if (materials_.needsEnergy()) eHalf_ = &particles_->scalarField("specificInternalEnergyHalfStep");
    }
    if (materials_.anyStrength()) {
        tau_ = &particles_->symmTensorField("deviatoricStress");
        if (!predictorCorrector_) tauHalf_ = &particles_->symmTensorField("deviatoricStressHalfStep");
        if (materials_.usesPlasticStrain()) plasticStrain_ = &particles_->scalarField("plasticStrain");
        if (materials_.usesTemperature()) {
            const bool had = particles_->hasField("temperature");
            temperature_ = &particles_->scalarField("temperature");
            if (!had)
                for (std::size_t i = 0; i < n; ++i)
                    if (const auto& law = materials_[material_[i]].strength; law && law->usesTemperature())
                        (*temperature_)[i] = law->initialTemperature();
        }
        velocityGradient_.assign(n, Tensor<Dim>::Zero());
        dtaudt_.assign(n, SymmTensor<Dim>{});
    }
    dvdt_.assign(n, Vector<Dim>::Zero());
    drhodt_.assign(n, 0.0);
    dedt_.assign(n, 0.0);
    a_.assign(n, 0.0), b_.assign(n, 0.0), cc_.assign(n, 0.0);
    if (omega_) std::fill(omega_->begin(), omega_->end(), 1.0);
}

// Mirror ghosts on the particle set's owned/ghost range: GhostBlock (boundaryConditions) gives
// their positions, velocities, sources and maps; the set copies every field from the source and
// reflects the stress. They are read-only neighbours in every sum of this rate evaluation.
//
// The layer of a step (`layer` below) holds the images of the particles within one support
// radius of a plane (thicknessFactor 3 × a third of the largest support). Remade every step, it
// changes the particle count and indices, and the candidate list had to be rebuilt at every step
// (3066 rebuilds in 3066 steps on the Taylor bar quarter at 0.4 mm). With `mirrorGhosts
// withList` the layer put into the set is instead one built at a list rebuild, one support plus
// the skin thick (keptGhosts_), with the same ghosts in the same order until it is rebuilt:
//   - a ghost of the kept layer that this step's layer also has (same source, same map: the
//     layers are built in one canonical order, so this step's is a subsequence of the kept one)
//     takes its position and velocity from this step's layer, bit for bit as it was made before;
//   - one it lacks (its source has moved out of the support's reach, or onto a plane) is placed
//     at the affine image Q x_source + offset of its build, so that the skin test stays exact
//     for it (a mirror keeps distances), and is left out of every sum (ghostActive_);
//   - when this step's layer is not a subsequence of the kept one (a particle came within reach
//     of a plane from beyond the layer built, or the largest support grew), the layer is built
//     again and the list with it.
// The sums see the same pairs as with the layer of each step, in another order: a row lists its
// candidates in the cell order of the list's last build (NeighbourSearch), so the results agree
// to round-off (2e-12 of each field's largest value after 798 steps of the Taylor bar quarter at
// 0.4 mm). Rows sorted by index (NeighbourSearchOptions::sortRows) would give the same bits, but
// cost four times a rebuild there (20 against 5 ms), 0.57 s of the 13 s run. Test:
// impactSph.mirrorGhostsKept.
template <int Dim>
void SphSolver<Dim>::addGhosts() {
    // What the kept mirror layer is compared with: the set as removeGhosts() left it.
    const std::uint64_t topologyBeforeHalo = particles_->topologyVersion();
    if (decomposition_) {
        // The halo first (other ranks' particles within reach), with the fields the phases read
        // of their neighbours before they refresh them (haloFields_).
        decomposition_->appendHalo(*particles_, haloFields_);
        const std::size_t n = x_.size();
        a_.resize(n), b_.resize(n), cc_.resize(n);
    }
    if (!boundaries_.makesGhosts()) return;
    const std::size_t owned = particles_->ownedCount();
    // Global: the layer of one rank is seen by the particles of every rank near the plane, so it
    // must cover the largest support anywhere, and every rank must build it alike.
    const double hMax = GlobalReduce::max(owned, [&](std::size_t i) { return h_[i]; });
    // The layer must cover the kernel's support; mirrorPlane makes it thicknessFactor (3) × the
    // length it is given, so it is given a third of the largest support radius.
    const double t = time().value();
    const GhostBlock<Dim> layer = boundaries_.ghosts(*particles_, v_, kernel_->supportRadius(hMax) / 3.0, t);
    const GhostBlock<Dim>* placed = &layer;
    if (!ghostsEveryStep_) {
        // Particles appended, removed or reordered since the last step (preStep) make the kept
        // sources other particles'.
        if (!ghostLayerKept_ || topologyBeforeHalo != topologyAfterGhosts_ || !placeKeptGhosts(layer)) {
            buildGhostLayer(hMax, t);
            if (!placeKeptGhosts(layer))
                throw Error("impactSph: the mirror-ghost layer just built lacks a ghost of the step's layer");
        }
        placed = &keptGhosts_;
    }
    const std::size_t first = particles_->addGhosts(placed->source, placed->map);  // after the halo
    for (std::size_t k = 0; k < placed->size(); ++k) {
        x_[first + k] = placed->position[k];
        v_[first + k] = placed->velocity[k];
    }
    if (tau_) particles_->reflectTensorsToGhosts(*tau_);
    const std::size_t n = x_.size();
    a_.resize(n), b_.resize(n), cc_.resize(n);
    // everyStep: ghosts come and go with the flow, the candidate list is rebuilt each step.
    if (ghostsEveryStep_ && verlet_) verlet_->invalidate();
}

// The kept layer: every image within one support plus the skin of a plane (the thickness the
// conditions make scaled by 1 + skin/support), with the affine offsets that re-place each ghost
// from its source. The candidate list is rebuilt with it.
template <int Dim>
void SphSolver<Dim>::buildGhostLayer(double hMax, double t) {
    const double support = kernel_->supportRadius(hMax);
    // The list's skin or, before the list exists (updateNeighbours makes it after this), the same
    // rule on the owned particles. Only how often the layer is built depends on it: the match in
    // placeKeptGhosts() keeps the layer complete whatever its thickness.
    double skin = verlet_ ? verlet_->skin() : 0.0;
    if (!verlet_) {
        std::vector<double> sorted(particles_->ownedCount());
        for (std::size_t i = 0; i < sorted.size(); ++i) sorted[i] = kernel_->supportRadius(h_[i]);
        std::nth_element(sorted.begin(), sorted.begin() + long(sorted.size() / 2), sorted.end());
        skin = neighbourSkin_ * (sorted.empty() ? 1.0 : sorted[sorted.size() / 2]);
    }
    keptGhosts_ = boundaries_.ghosts(*particles_, v_, (support + skin) / 3.0, t);
    ghostOffset_.resize(keptGhosts_.size());
    for (std::size_t g = 0; g < keptGhosts_.size(); ++g)
        ghostOffset_[g] = keptGhosts_.position[g] - keptGhosts_.map[g] * x_[keptGhosts_.source[g]];
    ghostLayerKept_ = true;
    ++ghostLayerBuilds_;
    if (verlet_) verlet_->invalidate();
}

// Matches this step's layer against the kept one in their common order, fills the kept ghosts'
// positions and velocities and ghostActive_; false when the step's layer has a ghost the kept
// one lacks.
template <int Dim>
bool SphSolver<Dim>::placeKeptGhosts(const GhostBlock<Dim>& layer) {
    const std::size_t owned = x_.size();  // the owned particles and the halo (MPI): the images follow
    GhostBlock<Dim>& kept = keptGhosts_;
    ghostActive_.assign(owned + kept.size(), 1);
    std::size_t next = 0;
    for (std::size_t g = 0; g < kept.size(); ++g) {
        const std::size_t s = kept.source[g];
        if (next < layer.size() && layer.source[next] == s && layer.map[next] == kept.map[g]) {
            kept.position[g] = layer.position[next];
            kept.velocity[g] = layer.velocity[next];
            ++next;
        } else {
            kept.position[g] = kept.map[g] * x_[s] + ghostOffset_[g];
            kept.velocity[g] = kept.map[g] * v_[s];
            ghostActive_[owned + g] = 0;
        }
    }
    filterGhosts_ = kept.size() > layer.size();
    return next == layer.size();
}

template <int Dim>
void SphSolver<Dim>::removeGhosts() {
    if (particles_->ghostCount() != 0) {
        particles_->clearGhosts();
        const std::size_t n = x_.size();
        a_.resize(n), b_.resize(n), cc_.resize(n);
    }
    topologyAfterGhosts_ = particles_->topologyVersion();
}

// The median support radius the Verlet skin is a fraction of. On several ranks the median of
// the owned particles of all ranks (the halo would count a particle twice), so every rank and
// the serial run take the same skin.
template <int Dim>
double SphSolver<Dim>::medianSupport(const std::vector<double>& radius) const {
    if (decomposition_)
        return globalMedian(
            std::vector<double>(radius.begin(), radius.begin() + long(particles_->ownedCount())));
    std::vector<double> sorted(radius);
    std::nth_element(sorted.begin(), sorted.begin() + long(sorted.size() / 2), sorted.end());
    return sorted.empty() ? 1.0 : sorted[sorted.size() / 2];
}

// Several ranks (issue 21): the owned particles stay where they are, and the halo with them,
// until some particle may have moved out of reach of its halo. The halo was planned with width
// w = R_max + skin around each rank's part; a pair within the support R(t) of particles that
// moved d_i and d_j since is covered while R_max(t) + d_i + d_j <= w, so the particles migrate
// to their owners (and the halo is planned again) when 2 max d + R_max(t) > w: a global test,
// one reduction a step. Only at the start of a step: the predictor-corrector's midpoint copies
// the state by index, so it may not move particles; it checks the halo still covers instead.
template <int Dim>
void SphSolver<Dim>::updateDecomposition() {
    auto timed = phase("updateNeighbours");
    const std::size_t n = particles_->ownedCount();
    const double rMax = GlobalReduce::max(n, [&](std::size_t i) { return kernel_->supportRadius(h_[i]); });
    if (skin_ < 0) {
        std::vector<double> radius(n);
        for (std::size_t i = 0; i < n; ++i) radius[i] = kernel_->supportRadius(h_[i]);
        skin_ = neighbourSkin_ * medianSupport(radius);
    }
    bool due = xAtMigration_.size() != n || haloWidth_ == 0;
    if (!due) {
        const double dMax =
            GlobalReduce::max(n, [&](std::size_t i) { return (x_[i] - xAtMigration_[i]).norm(); });
        due = 2 * dMax + rMax > haloWidth_;
    }
    if (!due) return;
    if (midStep_)
        throw RunError(
            "impactSph: particles outran the halo of their rank within one step (more than half the "
            "Verlet skin in half a step); remedy: a smaller maxCo, or a larger neighbourSkin in "
            "constant/sphProperties");
    // Each particle's cost is its candidate count (the pair loops' work): the load the partition
    // balances.
    std::vector<double> weights(n, 1.0);
    if (verlet_ && verlet_->candidates().size() >= n) {
        const auto& offsets = verlet_->candidates().offsets();
        for (std::size_t i = 0; i < n; ++i) weights[i] = double(offsets[i + 1] - offsets[i]) + 1.0;
    }
    const bool first = haloWidth_ == 0;
    const int rebalancesBefore = decomposition_->rebalances();
    decomposition_->migrate(*particles_, weights);
    haloWidth_ = rMax + skin_;
    decomposition_->planHalo(*particles_, haloWidth_);
    // The halo's members and order change with the plan even when no owned particle moved: the
    // candidate list and the kept mirror layer index them, and the conditions' selections index
    // the owned particles.
    if (verlet_) verlet_->invalidate();
    ghostLayerKept_ = false;
    boundaries_.updateSelections(*particles_);
    const std::size_t owned = particles_->ownedCount();
    xAtMigration_.assign(x_.begin(), x_.begin() + long(owned));
    // Per-particle scratch of the solver follows the new owned count (recomputed before use).
    dvdt_.resize(owned), drhodt_.resize(owned), dedt_.resize(owned);
    if (tau_) velocityGradient_.resize(owned), dtaudt_.resize(owned);
    a_.resize(owned), b_.resize(owned), cc_.resize(owned);
    if (first || decomposition_->rebalances() != rebalancesBefore)
        Log::info(decomposition_->report(*particles_, {}));
}

template <int Dim>
void SphSolver<Dim>::updateNeighbours() {
    auto timed = phase("updateNeighbours");
    std::vector<double>& radius = radius_;
    radius.resize(x_.size());
    for (std::size_t i = 0; i < x_.size(); ++i) radius[i] = kernel_->supportRadius(h_[i]);
    if (!verlet_) {
        const double skin = neighbourSkin_ * medianSupport(radius);
        // Checked: the few particles that outrun the skin (a gas's free end, a strong shock's
        // front) are tested instead of rebuilding the whole list at almost every step.
        const bool checked = settings_.word("neighbourRebuild") == "checked";
        verlet_ =
            std::make_unique<VerletList<Dim>>(skin, NeighbourDomain<Dim>{}, NeighbourSearchOptions{},
                                              checked ? VerletPolicy::checked : VerletPolicy::displacement);
        // Rows in global-id order: every sum over neighbours is then the same to the bit on any
        // number of ranks (whose numbering and cells differ) and whenever the list was rebuilt
        // (issue 21: a stiff equation of state turns the last bits of the density into 1e-12 of
        // the pressure).
        verlet_->orderRowsBy(&particles_->globalId());
    }
    // Particles appended or removed (preStep) invalidate the list. Ghosts change the version at
    // every step (added, then cleared): with a kept layer addGhosts() watches the version itself
    // and invalidates the list when it builds the layer again; with everyStep it is rebuilt anyway.
    // On several ranks the halo is appended at every evaluation but changes only with the owned
    // particles (a migration): the list follows those.
    if (decomposition_)
        verlet_->track(particles_->ownedTopologyVersion());
    else if (!boundaries_.makesGhosts())
        verlet_->track(particles_->topologyVersion());
    if (verlet_->update(x_, radius)) ++rebuilds_;
    ++neighbourUpdates_;
    neighbours_.list = &verlet_->candidates();
    neighbours_.selected = nullptr, neighbours_.count = nullptr;
}

// f(h) = c_i Σ_j b_j W_ij(h) − m_i (η/h)^d, f'(h) = c_i Σ_j b_j ∂W_ij/∂h + d m_i η^d / h^{d+1}; Newton
// steps kept inside a bracket [lo, hi] that is halved when a step leaves it. h may not outgrow the
// candidate list: its upper end is the radius the list was built for (support + skin).
template <int Dim>
void SphSolver<Dim>::solveSmoothingLength() {
    auto timed = phase("densitySums");
    if (!scheme_->explicitSummation())
        throw properties_.error("smoothingLength",
                                "the summation smoothing length needs an explicit density sum "
                                "(densityScheme mass or number)");
    const std::size_t n = particles_->ownedCount();
    scheme_->coefficients(x_.size(), m_.data(), rho_.data(), a_.data(), b_.data(), cc_.data());
    const double eta = hLaw_->eta(), tolerance = hLaw_->tolerance();
    const int maxIterations = hLaw_->maxIterations();
    const double reach = 1.0 + verlet_->skin() / std::max(1e-300, kernel_->supportRadius(1.0));
    std::vector<int> failed(n, 0);
    const char* active = filterGhosts_ ? ghostActive_.data() : nullptr;  // kept ghosts of this step
    parallelFor(n, [&](std::size_t i) {
        const double mi = m_[i], ci = cc_[i];
        auto f = [&](double h, double& slope) {
            double sum = b_[i] * W_.W(0.0, h), dsum = b_[i] * W_.dWdh(0.0, h);
            for (const auto j : neighbours_[i]) {
                if (active && !active[j]) continue;
                const double r = (x_[i] - x_[j]).norm();
                sum += b_[j] * W_.W(r, h);
                dsum += b_[j] * W_.dWdh(r, h);
            }
            const double target = mi * std::pow(eta / h, Dim);
            slope = ci * dsum + Dim * target / h;
            return ci * sum - target;
        };
        double lo = 0.5 * h_[i], hi = std::min(2.0 * h_[i], h_[i] * reach), h = h_[i];
        for (int k = 0; k < maxIterations; ++k) {
            double slope;
            const double value = f(h, slope);
            (value > 0 ? hi : lo) = h;  // f grows with h: the sum settles, the target falls as h^-d
            double next = slope != 0 ? h - value / slope : 0.5 * (lo + hi);
            if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
            if (std::abs(next - h) < tolerance * h) {
                h = next;
                failed[i] = 0;
                break;
            }
            h = next;
            failed[i] = k + 1 == maxIterations;
        }
        h_[i] = h;
    });
    particles_->copyToGhosts(h_);
    if (std::any_of(failed.begin(), failed.end(), [](int v) { return v != 0; }))
        Log::warning("summation smoothing length: some particles did not converge to the tolerance in " +
                     std::to_string(maxIterations) + " iterations (step " +
                     std::to_string(time().timeIndex()) + ")");
}

template <int Dim>
void SphSolver<Dim>::computeEquationOfState() {
    auto timed = phase("equationOfState");
    const std::size_t n = particles_->ownedCount();
    parallelFor(n, [&](std::size_t i) {
        const EquationOfState& eos = *materials_[material_[i]].eos;
        const double e = e_ ? (*e_)[i] : 0.0;
        eos.evaluate(1, &rho_[i], &e, &p_[i], &c_[i]);
        // A model gives c = NaN where c^2 < 0 (EquationOfState::evaluate); the state check still
        // stops on c = 0 and describes c^2 from the model, and the failing state written for
        // diagnosis holds no NaN that the state did not already have.
        if (std::isnan(c_[i]) && std::isfinite(rho_[i]) && std::isfinite(e)) c_[i] = 0.0;
    });
    particles_->copyToGhosts(p_);
    particles_->copyToGhosts(c_);
}

template <int Dim>
void SphSolver<Dim>::computeKernelFactors() {
    auto timed = phase("densitySums");
    const std::size_t n = x_.size();
    invH_.resize(n), wNorm_.resize(n), dhNorm_.resize(n), gradNorm_.resize(n), volume_.resize(n);
    const KernelEvaluator<Dim> W = W_;
    parallelFor(n, [&](std::size_t i) {
        const double h = h_[i], invH = W.invKappa / h;
        double power = invH;
        for (int d = 1; d < Dim; ++d) power *= invH;
        const double c = W.norm * power;
        invH_[i] = invH;
        wNorm_[i] = c;
        dhNorm_[i] = -W.norm * power / h;
        gradNorm_[i] = c * invH;
        volume_[i] = m_[i] / rho_[i];
    });
}

// The candidates (support + skin) cut to the pairs within either support, r < max(H_i, H_j),
// once a step for the three pair loops that follow: about a quarter of the candidates lie in the
// skin, and a branch on each of them in every loop is mispredicted often. A pair at the edge
// may be kept by rounding (the test has a margin of 1e-9); it adds exact zeros, as every term
// carries W or ∇W. Each row is compacted in place of its candidate row, so rows are written
// independently (any thread count gives the same list). A kept ghost that this step's layer
// lacks is left out (addGhosts).
template <int Dim>
void SphSolver<Dim>::selectNeighbours() {
    auto timed = phase("updateNeighbours");
    const NeighbourList& list = verlet_->candidates();
    const std::size_t n = particles_->ownedCount();
    selected_.resize(list.pairCount());
    selectedCount_.resize(n);
    const Vector<Dim>* x = x_.data();
    const double* invH = invH_.data();
    const auto& offsets = list.offsets();
    const char* active = filterGhosts_ ? ghostActive_.data() : nullptr;
    parallelForWork(n, list.pairCount(), [&](std::size_t i) {
        const Vector<Dim> xi = x[i];
        const double invHi = invH[i];
        NeighbourList::Index* out = selected_.data() + offsets[i];
        std::size_t found = 0;
        if (active)
            for (const auto j : list[i]) {
                const double m = std::min(invHi, invH[j]);
                out[found] = j;
                found += ((xi - x[j]).squaredNorm() * (m * m) < 1.0 + 1e-9) & (active[j] != 0);
            }
        else
            for (const auto j : list[i]) {
                const double m = std::min(invHi, invH[j]);
                out[found] = j;
                found += (xi - x[j]).squaredNorm() * (m * m) < 1.0 + 1e-9;
            }
        selectedCount_[i] = NeighbourList::Index(found);
    });
    neighbours_.selected = selected_.data();
    neighbours_.count = selectedCount_.data();
}

// Loop A: S_i, ω_i, ñ_i and, when ρ is not summed (so m_j/ρ_j is already this step's), the
// velocity gradient L_i, from one kernel evaluation per pair within the support of h_i (pairs
// beyond it add exact zeros to every sum, so they are skipped).
template <int Dim>
void SphSolver<Dim>::computeDensitySums() {
    auto timed = phase("densitySums");
    const std::size_t n = particles_->ownedCount();
    scheme_->coefficients(x_.size(), m_.data(), rho_.data(), a_.data(), b_.data(), cc_.data());
    const bool summation = scheme_->summation();
    gradientWithSums_ = tau_ && !summation;
    if (!summation && !omega_ && !number_ && !gradientWithSums_) return;
    const bool gradient = gradientWithSums_;
    std::vector<double> newRho(summation ? n : 0);
    const KernelEvaluator<Dim> W = W_;
    const Vector<Dim>* x = x_.data();
    const Vector<Dim>* v = v_.data();
    const double* b = b_.data();
    const double* volume = volume_.data();
    parallelForWork(n, neighbours_.list->pairCount(), [&](std::size_t i) {
        const double hi = h_[i], invHi = invH_[i], wNormi = wNorm_[i], dhNormi = dhNorm_[i],
                     gradNormi = gradNorm_[i];
        double w0, dw0;
        W.shape(0.0, w0, dw0);
        double sum = b[i] * (wNormi * w0), count = wNormi * w0, dh = b[i] * (dhNormi * (Dim * w0));
        const Vector<Dim> xi = x[i], vi = v[i];
        Tensor<Dim> L = Tensor<Dim>::Zero();
        for (const auto j : neighbours_[i]) {
            const Vector<Dim> xij = xi - x[j];
            const double r = xij.norm();
            const double u = r * invHi;
            if (u >= 1.0) continue;
            double w, dw;
            W.shape(u, w, dw);
            const double wij = wNormi * w;
            sum += b[j] * wij;
            count += wij;
            dh += b[j] * (dhNormi * (Dim * w + u * dw));
            if (gradient && r != 0) L -= (volume[j] * (gradNormi * dw) / r) * (vi - v[j]) * xij.transpose();
        }
        // At a free surface the sum behind ω loses its far half and ω falls towards 0 as the edge
        // thins, which would blow dρ/dt up there; ω is floored (omegaMin). Any per-particle ω
        // keeps the pair forces antisymmetric and the energy equation matched, so the floor
        // costs no conservation, only the exact variational form at those few particles.
        if (omega_) (*omega_)[i] = std::max(omegaMin_, 1.0 + hi / (Dim * sum) * dh);
        if (number_) (*number_)[i] = count;
        if (summation) newRho[i] = cc_[i] * sum;
        if (gradient) velocityGradient_[i] = L;
    });
    if (summation) {
        std::copy(newRho.begin(), newRho.end(), rho_.begin());
        particles_->copyToGhosts(rho_);
        scheme_->coefficients(x_.size(), m_.data(), rho_.data(), a_.data(), b_.data(), cc_.data());
        parallelFor(x_.size(), [&](std::size_t i) { volume_[i] = m_[i] / rho_[i]; });
    }
    if (omega_) particles_->copyToGhosts(*omega_);
    if (number_) particles_->copyToGhosts(*number_);
}

// The per-particle factors of the pair terms, then the fused pair loop (SphPairLoop.hpp) compiled
// with the dissipation model's pair terms: one virtual call to the model, none per pair.
template <int Dim>
void SphSolver<Dim>::computeRates() {
    auto timed = phase("computeRates");
    // Artificial stress R_i = Q diag(−ε max(λ_a, 0)/ρ_i²) Qᵀ from the principal values λ_a of the
    // total stress σ = −P I + τ (tension positive); the pair term Σ_j m_j (R_i + R_j) f_ij^n ∇̄W with
    // f_ij = W(r_ij, h̄)/W(Δp, h̄), Δp = h̄/η the particle spacing (Gray, Monaghan & Swift 2001).
    const bool artificialStress = artificialStressEpsilon_ > 0 && tau_;
    if (artificialStress) {
        artificialStress_.resize(x_.size());  // ghosts too: their stress is reflected, their P copied
        parallelFor(x_.size(), [&](std::size_t i) {
            const Tensor<Dim> sigma = (*tau_)[i].full() - p_[i] * Tensor<Dim>::Identity();
            Eigen::SelfAdjointEigenSolver<Tensor<Dim>> eigen(sigma);
            Vector<Dim> r = Vector<Dim>::Zero();
            for (int a = 0; a < Dim; ++a)
                if (eigen.eigenvalues()[a] > 0)
                    r[a] = -artificialStressEpsilon_ * eigen.eigenvalues()[a] / (rho_[i] * rho_[i]);
            artificialStress_[i] = eigen.eigenvectors() * r.asDiagonal() * eigen.eigenvectors().transpose();
        });
    }
    // a_j P_j/ω_j of the second pressure term, for every particle (ghosts included), so that the
    // pair loop divides only where the pair itself is in the denominator.
    pressureTerm_.resize(x_.size());
    parallelFor(x_.size(),
                [&](std::size_t j) { pressureTerm_[j] = a_[j] * p_[j] / (omega_ ? (*omega_)[j] : 1.0); });

    SphPairLoop<Dim> loop;
    loop.owned = particles_->ownedCount();
    loop.size = x_.size();
    loop.particles = particles_;
    loop.W = W_;
    loop.neighbours = neighbours_;
    loop.pairCount = neighbours_.list->pairCount();
    loop.x = x_.data(), loop.v = v_.data();
    loop.m = m_.data(), loop.rho = rho_.data(), loop.p = p_.data(), loop.c = c_.data(), loop.h = h_.data();
    loop.e = e_ ? e_->data() : nullptr;
    loop.omega = omega_ ? omega_->data() : nullptr;
    loop.a = a_.data(), loop.b = b_.data(), loop.cc = cc_.data();
    loop.invH = invH_.data(), loop.gradNorm = gradNorm_.data(), loop.volume = volume_.data();
    loop.pressureTerm = pressureTerm_.data();
    loop.differenceForm = differenceForm_;
    loop.tau = tau_ ? tau_->data() : nullptr;
    loop.velocityGradient = tau_ ? velocityGradient_.data() : nullptr;
    loop.artificialStress = artificialStress ? artificialStress_.data() : nullptr;
    loop.artificialStressExponent = artificialStressExponent_;
    loop.eta = hLaw_->eta();
    loop.dvdt = dvdt_.data(), loop.drhodt = drhodt_.data(), loop.dedt = dedt_.data();
    dissipation_->computeRates(loop);
}

template <int Dim>
void SphSolver<Dim>::ensureRates() {
    if (ratesValid_) return;
    if (decomposition_) updateDecomposition();
    addGhosts();
    updateNeighbours();
    if (hLaw_->iterative()) solveSmoothingLength();
    computeKernelFactors();
    selectNeighbours();
    computeDensitySums();
    computeEquationOfState();
    checkState("computeEquationOfState");
    if (materials_.anyStrength()) {
        computeVelocityGradient();
        computeStressRate();
    }
    computeRates();
    pairInteractions_ += double(neighbours_.list->pairCount());
    removeGhosts();
    std::vector<Vector<Dim>> freeRates;  // dv/dt before the constraints, for their power
    if (!boundaries_.empty()) {
        freeRates.assign(dvdt_.begin(), dvdt_.begin() + std::ptrdiff_t(particles_->ownedCount()));
        boundaries_.constrainAcceleration(*particles_, dvdt_, time().value());
    }
    measurePower(freeRates);
    ratesValid_ = true;
}

// The energy budget of the health check (RunContext: K + U + D − W constant), with K = Σ ½ m|v|²
// and U = Σ m e over the owned particles. From the rates f = (dv/dt, de/dt) before the
// boundary conditions act, and a^c the constrained dv/dt,
//
//   dissipation power   Ḋ = −Σ_i m_i (v_i·dv_i/dt + de_i/dt)      (what the rates lose from K + U)
//   constraint power    Ẇ = Σ_i m_i v_i·(a^c_i − dv_i/dt)         (the work rate of the conditions)
//
// plus, at each velocity constraint of the synchronised v, the jump Σ ½ m (|v'|² − |v|²) it makes
// (constrainVelocityWork: a rigid wall's impulse, a prescribed speed set). Ḋ is measured, not
// assumed: for the scheme as published it is zero to round-off, term by term (SphSolver.cpp's
// head, DensityScheme.hpp, RiemannDissipation.cpp):
//   - pressure: with a_i = m_i c_i/ρ_i², Σ_i m_i v_i·(pressure force) = −Σ_i a_i P_i/ω_i Σ_j b_j
//     v_ij·∇_iW_ij(h_i) = −Σ_i m_i de_i/dt (the variational pairing, any per-particle ω, the floor too);
//   - viscosity: the pair force is antisymmetric and the viscous heating of i and j together,
//     −m_i m_j a_v v'(v_ij·r̂)² F/ρ̄, is exactly minus its work (v' and ρ̄ are symmetric in i, j);
//   - conduction: m_i m_j a_e v'(e_i − e_j) F/ρ̄ is antisymmetric, a transfer of e between the pair;
//   - the artificial mass flux enters dρ/dt only, never v or e: it moves no energy (it changes P
//     through ρ later, and the pressure terms stay matched to e);
//   - strength: Σ_i V_i τ_i:L_i heating is minus the work of the stress force (same V, same ∇W);
//   - artificial stress: its heating −½ Σ_j v_ij·f_ij is minus its work, pair by pair;
//   - mirror ghosts: the real particles and their images are a mirror-symmetric system whose total
//     energy the pair sums keep, the images' half equal to the real half, so the real half is kept.
// impactSph has no XSPH, no body force and does not apply boundary forces (prescribedTraction's
// addBoundaryForces hook is not called): nothing else moves energy. What makes Ḋ non-zero:
// `momentum difference` (not antisymmetric: its power does not match the
// pdV work), a user dissipation whose heating is not its work, a ghost layer short of the support,
// or a pair missing from one of its two rows. Without an energy equation (a barotropic equation of
// state) U is not measured, and neither is D.
//
// In time, each integrator's own quadrature of its rates: the midpoint rule for the
// predictor-corrector (the midpoint powers × Δt), the trapezoid for the leapfrog, whose rates f^k
// at t_k drive the step [t_k, t_{k+1}]: Δt_k Ẋ^k at the step, ½ Δt_k (Ẋ^{k+1} − Ẋ^k) at the next
// evaluation (so a write between the two is off by O(Δt²) of the last step only). Both are
// second-order, as the integrators: the budget's imbalance is then the integrator's O(Δt²) energy
// error (and the round-off of the sums).
template <int Dim>
void SphSolver<Dim>::measurePower(const std::vector<Vector<Dim>>& freeRates) {
    const std::size_t n = particles_->ownedCount();
    const bool constrained = !freeRates.empty();
    const SumArray<2> power = GlobalReduce::sum<SumArray<2>>(n, [&](std::size_t i) {
        SumArray<2> t;
        const Vector<Dim>& a = constrained ? freeRates[i] : dvdt_[i];
        t.s[0] = -m_[i] * (v_[i].dot(a) + dedt_[i]);
        if (constrained) t.s[1] = m_[i] * v_[i].dot(dvdt_[i] - a);
        return t;
    });
    dissipationPower_ = power.s[0];
    constraintPower_ = power.s[1];
    if (pendingDt_ > 0) {
        dissipated_ += 0.5 * pendingDt_ * (dissipationPower_ - pendingDissipationPower_);
        externalWork_ += 0.5 * pendingDt_ * (constraintPower_ - pendingConstraintPower_);
        pendingDt_ = 0;
    }
}

template <int Dim>
double SphSolver<Dim>::constrainVelocityWork(std::vector<Vector<Dim>>& v, double t) {
    const std::size_t n = particles_->ownedCount();
    const std::vector<Vector<Dim>> before(v.begin(), v.begin() + std::ptrdiff_t(n));
    boundaries_.constrainVelocity(*particles_, v, t);
    return GlobalReduce::sum<double>(
        n, [&](std::size_t i) { return 0.5 * m_[i] * (v[i].squaredNorm() - before[i].squaredNorm()); });
}

template <int Dim>
void SphSolver<Dim>::computeVelocityGradient() {
    if (gradientWithSums_) return;  // done in the density-sum loop
    auto timed = phase("strength");
    const KernelEvaluator<Dim> W = W_;
    parallelForWork(particles_->ownedCount(), neighbours_.list->pairCount(), [&](std::size_t i) {
        Tensor<Dim> L = Tensor<Dim>::Zero();
        const double invHi = invH_[i], gradNormi = gradNorm_[i];
        for (const auto j : neighbours_[i]) {
            const Vector<Dim> xij = x_[i] - x_[j];
            const double r = xij.norm();
            const double u = r * invHi;
            if (r == 0 || u >= 1.0) continue;
            double w, dw;
            W.shape(u, w, dw);
            L -= (volume_[j] * (gradNormi * dw) / r) * (v_[i] - v_[j]) * xij.transpose();
        }
        velocityGradient_[i] = L;
    });
}

template <int Dim>
typename Strength<Dim>::Fields SphSolver<Dim>::strengthFields(std::size_t i, SymmTensor<Dim>* tau) {
    typename Strength<Dim>::Fields f;
    f.size = 1;
    f.velocityGradient = &velocityGradient_[i];
    f.density = &rho_[i];
    f.tau = tau;
    f.tauRate = &dtaudt_[i];
    f.plasticStrain = plasticStrain_ ? &(*plasticStrain_)[i] : nullptr;
    f.temperature = temperature_ ? &(*temperature_)[i] : nullptr;
    return f;
}

template <int Dim>
void SphSolver<Dim>::computeStressRate() {
    auto timed = phase("strength");
    parallelFor(particles_->ownedCount(), [&](std::size_t i) {
        if (const auto& law = materials_[material_[i]].strength)
            law->stressRate(strengthFields(i, &(*tau_)[i]));
        else
            dtaudt_[i] = SymmTensor<Dim>{};
    });
}

template <int Dim>
void SphSolver<Dim>::returnToYieldSurface(std::vector<SymmTensor<Dim>>& tau, double dt) {
    parallelFor(x_.size(), [&](std::size_t i) {
        if (const auto& law = materials_[material_[i]].strength)
            law->returnToYieldSurface(strengthFields(i, &tau[i]), dt);
    });
}

template <int Dim>
TimeStepVote SphSolver<Dim>::stableTimeStep() {
    ensureRates();
    const double xi = time().maxCo();
    const std::size_t n = particles_->ownedCount();
    const std::vector<std::int64_t>& id = particles_->globalId();
    // Time-step votes are global: every rank must take the same Δt. The argmin rides in the same
    // reduction (ArgMin: the lowest global id among equal values), so the vote names its particle.
    const ArgMin courant = GlobalReduce::sum<ArgMin>(n, [&](std::size_t i) {
        const double stiffness = longitudinalStiffness_.empty() ? 0.0 : longitudinalStiffness_[material_[i]];
        const double c = stiffness > 0 ? std::sqrt(c_[i] * c_[i] + stiffness / rho_[i]) : c_[i];
        return ArgMin{h_[i] / (v_[i].norm() + c), id[i]};
    });
    TimeStepVote vote{xi * courant.value, "Courant", courant.particle()};
    if (densityRateLimit_ > 0 && !scheme_->summation()) {
        const ArgMin rate = GlobalReduce::sum<ArgMin>(n, [&](std::size_t i) {
            const double r = std::abs(drhodt_[i]);
            return ArgMin{r > 0 ? rho_[i] / r : std::numeric_limits<double>::infinity(), id[i]};
        });
        const double limit = densityRateLimit_ * rate.value;
        if (limit < vote.deltaT) vote = {limit, "density rate", rate.particle()};
    }
    return vote;
}

template <int Dim>
void SphSolver<Dim>::stepPredictorCorrector(double dt) {
    ensureRates();
    auto timed = phase("integrate");
    const std::size_t n = x_.size();
    const bool continuity = !scheme_->summation();
    const auto x0 = x_;
    const auto v0 = v_;
    const auto rho0 = rho_;
    std::vector<double> e0;
    if (e_) e0 = *e_;
    std::vector<SymmTensor<Dim>> tau0;
    if (tau_) tau0 = *tau_;
    auto advance = [&](double span) {
        parallelFor(n, [&](std::size_t i) {
            x_[i] = x0[i] + span * (v0[i] + 0.5 * span * dvdt_[i]);
            v_[i] = v0[i] + span * dvdt_[i];
            if (continuity) rho_[i] = rho0[i] + span * drhodt_[i];
            if (e_) (*e_)[i] = e0[i] + span * dedt_[i];
            if (tau_)
                for (int k = 0; k < SymmTensor<Dim>::size; ++k)
                    (*tau_)[i].c[k] = tau0[i].c[k] + span * dtaudt_[i].c[k];
        });
    };
    const double t = time().value();
    // Predictor to the midpoint; the plastic history is not advanced there.
    advance(0.5 * dt);
    std::vector<double> history, heat;
    if (plasticStrain_) history = *plasticStrain_;
    if (temperature_) heat = *temperature_;
    if (tau_) returnToYieldSurface(*tau_, 0.5 * dt);
    if (plasticStrain_) *plasticStrain_ = history;
    if (temperature_) *temperature_ = heat;
    if (!boundaries_.empty()) boundaries_.constrainVelocity(*particles_, v_, t + 0.5 * dt);
    updateSmoothingLength();
    timed.stop();
    ratesValid_ = false;
    midStep_ = true;
    ensureRates();
    midStep_ = false;
    timed.resume();
    // Corrector over the whole step with the midpoint rates (and the budget by the midpoint rule).
    advance(dt);
    dissipated_ += dt * dissipationPower_;
    externalWork_ += dt * constraintPower_;
    if (tau_) returnToYieldSurface(*tau_, dt);
    if (!boundaries_.empty()) {
        externalWork_ += constrainVelocityWork(v_, t + dt);
        boundaries_.constrainPosition(*particles_, t + dt);
    }
    ratesValid_ = false;
    started_ = true;
    previousDeltaT_ = dt;
    timed.stop();
    // Checked before h follows the density: a density through zero would make h NaN, in the
    // state written for diagnosis too.
    checkState("integrate");
    updateSmoothingLength();
}

template <int Dim>
void SphSolver<Dim>::step(double dt) {
    if (predictorCorrector_) return stepPredictorCorrector(dt);
    ensureRates();
    auto timed = phase("integrate");
    const std::size_t n = x_.size();
    const double weight = started_ ? 0.5 * (previousDeltaT_ + dt) : 0.5 * dt;
    const bool continuity = rhoHalf_ != nullptr;
    parallelFor(n, [&](std::size_t i) {
        auto& vh = (*vHalf_)[i];
        vh = (started_ ? vh : v_[i]) + weight * dvdt_[i];
        x_[i] += dt * vh;
        v_[i] = vh + 0.5 * dt * dvdt_[i];
        if (continuity) {
            double& rh = (*rhoHalf_)[i];
            rh = (started_ ? rh : rho_[i]) + weight * drhodt_[i];
            rho_[i] = rh + 0.5 * dt * drhodt_[i];
        }
        if (eHalf_) {
            double& eh = (*eHalf_)[i];
            eh = (started_ ? eh : (*e_)[i]) + weight * dedt_[i];
            (*e_)[i] = eh + 0.5 * dt * dedt_[i];
        }
    });
    if (tau_) {
        // τ advances with U; the half-step stress and the synchronised one each return to the
        // yield surface (the plastic history advances on the half step, which carries the state).
        auto& tau = *tau_;
        auto& tauHalf = *tauHalf_;
        parallelFor(n, [&](std::size_t i) {
            for (int k = 0; k < SymmTensor<Dim>::size; ++k)
                tauHalf[i].c[k] = (started_ ? tauHalf[i].c[k] : tau[i].c[k]) + weight * dtaudt_[i].c[k];
        });
        returnToYieldSurface(tauHalf, weight);
        parallelFor(n, [&](std::size_t i) {
            for (int k = 0; k < SymmTensor<Dim>::size; ++k)
                tau[i].c[k] = tauHalf[i].c[k] + 0.5 * dt * dtaudt_[i].c[k];
        });
        std::vector<double> history;
        if (plasticStrain_) history = *plasticStrain_;  // the synchronised return must not advance it twice
        std::vector<double> heat;
        if (temperature_) heat = *temperature_;
        returnToYieldSurface(tau, 0.5 * dt);
        if (plasticStrain_) *plasticStrain_ = std::move(history);
        if (temperature_) *temperature_ = std::move(heat);
    }
    // The budget: this step's part of the trapezoid (measurePower completes it).
    dissipated_ += dt * dissipationPower_;
    externalWork_ += dt * constraintPower_;
    pendingDt_ = dt, pendingDissipationPower_ = dissipationPower_, pendingConstraintPower_ = constraintPower_;
    if (!boundaries_.empty()) {
        const double t = time().value();
        boundaries_.constrainVelocity(*particles_, *vHalf_, t + 0.5 * dt);
        externalWork_ += constrainVelocityWork(v_, t + dt);
        boundaries_.constrainPosition(*particles_, t + dt);
    }
    started_ = true;
    previousDeltaT_ = dt;
    ratesValid_ = false;
    timed.stop();
    // Checked before h follows the density: a density through zero would make h NaN, in the
    // state written for diagnosis too.
    checkState("integrate");
    updateSmoothingLength();
}

template <int Dim>
void SphSolver<Dim>::updateSmoothingLength() {
    hLaw_->update(Dim, x_.size(), m_.data(), rho_.data(), number_ ? number_->data() : nullptr, h_.data());
}

template <int Dim>
void SphSolver<Dim>::checkState(const char* phaseName) const {
    auto bad = [&](std::size_t i) {
        return !(rho_[i] > 0) || !std::isfinite(rho_[i]) || !x_[i].allFinite() || !v_[i].allFinite() ||
               !std::isfinite(p_[i]) || !(c_[i] > 0) || !(h_[i] > 0) || (e_ && !std::isfinite((*e_)[i]));
    };
    Solver::checkState(phaseName, particles_->ownedCount(), bad, [&](std::size_t i, double count) {
        std::ostringstream s;
        s.precision(6);
        s << "particle " << particles_->globalId()[i] << " (region " << particles_->region()[i]
          << ", material " << materials_[material_[i]].name << ") has density " << rho_[i] << ", pressure "
          << p_[i] << ", sound speed " << c_[i] << ", h " << h_[i];
        if (e_) s << ", e " << (*e_)[i];
        s << ", |v| " << v_[i].norm() << "; " << count << " particles affected";
        if (std::isfinite(rho_[i]) && !(rho_[i] > 0)) {
            s << "\n    the density has fallen through zero. Remedy: lower maxCo; beside a particle of "
                 "much larger mass (an interface between materials at one lattice spacing, a density "
                 "ratio of hundreds) the continuity density's artificial mass flux moves density "
                 "between unequal masses: switch it off (constant/sphProperties: dissipation { density "
                 "(0 0); }) or take the summation density (densityScheme { form summation; })";
        } else if (std::isfinite(rho_[i]) && !(c_[i] > 0)) {
            // The two ways out of an equation of state's range call for different remedies: a
            // compressed, little-heated state (the constant-Gamma factor of mieGruneisen) or an
            // expanded one (strong tension: the uncut pressure far below zero, which a particle
            // under a minimumPressure cut-off reaches by expanding freely).
            const double rho0 = materials_[material_[i]].eos->referenceDensity();
            const EquationOfState& eos = *materials_[material_[i]].eos;
            s << "\n    the equation of state gives c^2 <= 0 (c^2 = "
              << eos.soundSpeedSquared(rho_[i], e_ ? (*e_)[i] : 0.0) << ") at this state (density "
              << rho_[i];
            if (rho_[i] < rho0)
                s << ", " << rho_[i] / rho0 << " of rho0 " << rho0
                  << "): the state has left the model's range of validity in tension (for "
                     "mieGruneisen, the uncut pressure far below zero; a minimumPressure cut-off clamps "
                     "P, not c^2, so a particle held at the cut-off expands freely until c^2 turns "
                     "negative: spalled material, which no failure model removes yet; without the "
                     "cut-off the tension holds it back; for tillotson, the cold expanded branch "
                     "A mu + B mu^2 dominates below rho0 and e < Ecv: tens of GPa of tension). Remedy: "
                     "the material has spalled, and mfdyn has no failure model yet to release it: a "
                     "run past this point needs a lower impact speed or an equation of state whose "
                     "tension limit also bounds c^2";
            else
                s << ", " << rho_[i] / rho0 << " of rho0 " << rho0
                  << "): the state has left the model's range of validity in compression (for "
                     "mieGruneisen, strong compression with little heating; try hugoniot linearUsUp, "
                     "gruneisen constantRhoGamma, a smaller deltaT or more dissipation)";
        }
        return s.str();
    });
}

template <int Dim>
std::optional<double> SphSolver<Dim>::internalEnergy() const {
    if (!e_) return std::nullopt;
    const auto& e = *e_;
    // A conservation sum: added to the global kinetic energy by conservedQuantities.
    return GlobalReduce::sum<double>(particles_->ownedCount(), [&](std::size_t i) { return m_[i] * e[i]; });
}

template <int Dim>
std::optional<double> SphSolver<Dim>::schemeDissipation() const {
    if (!e_) return std::nullopt;  // U not measured: Ḋ would hold its rate (measurePower)
    return dissipated_;
}

template <int Dim>
std::optional<double> SphSolver<Dim>::externalWork() const {
    return externalWork_;
}

// The indicators of SphHealth.cpp on the owned particles, with this moment's mirror images as
// neighbours (the layer is made again here: between steps the solver keeps none in the set).
template <int Dim>
std::vector<HealthIndicator> SphSolver<Dim>::healthIndicators() const {
    const std::size_t owned = particles_->ownedCount();
    SphHealthState<Dim> s;
    s.owned = s.size = owned;
    s.x = x_.data(), s.v = v_.data(), s.m = m_.data(), s.rho = rho_.data(), s.h = h_.data(), s.p = p_.data();
    s.soundSpeed = c_.data();
    s.tau = tau_ ? tau_->data() : nullptr;
    s.globalId = particles_->globalId().data();
    s.W = W_;
    // Between steps the set holds no ghosts: the neighbours a particle has beyond its rank (the
    // halo, refreshed here from the last plan, which still covers) and across the mirror planes
    // are gathered into copies, [owned][halo][images], or a particle at a rank's cut would look
    // like one at a free surface.
    const std::size_t halo = decomposition_ ? decomposition_->haloSize() : 0;
    if (halo == 0 && !boundaries_.makesGhosts()) return sphHealthIndicators(s);
    GhostBlock<Dim> layer;
    if (boundaries_.makesGhosts()) {
        const double hMax = GlobalReduce::max(owned, [&](std::size_t i) { return h_[i]; });
        layer = boundaries_.ghosts(*particles_, v_, kernel_->supportRadius(hMax) / 3.0, time().value());
    }
    std::vector<Vector<Dim>> x, v;
    std::vector<double> m, rho, h, p;
    auto extend = [&](auto& out, const auto& field, const auto& images) {
        out.assign(field.begin(), field.begin() + std::ptrdiff_t(owned));
        out.resize(owned + halo);
        if (halo) decomposition_->refresh(out.data(), sizeof(out[0]), owned);
        out.insert(out.end(), images.begin(), images.end());
        return out.data();
    };
    s.size = owned + halo + layer.size();
    s.x = extend(x, x_, layer.position), s.v = extend(v, v_, layer.velocity);
    s.m = extend(m, m_, layer.gather(m_)), s.rho = extend(rho, rho_, layer.gather(rho_));
    s.h = extend(h, h_, layer.gather(h_)), s.p = extend(p, p_, layer.gather(p_));
    // A halo particle images no one (an index no owned particle has).
    std::vector<std::size_t> imageOf(halo, std::numeric_limits<std::size_t>::max());
    imageOf.insert(imageOf.end(), layer.source.begin(), layer.source.end());
    s.imageOf = imageOf.data();
    return sphHealthIndicators(s);
}

template <int Dim>
std::string SphSolver<Dim>::solverState() const {
    return std::string("leapfrogStarted    ") + (started_ ? "yes" : "no") + ";\npreviousDeltaTExact \"" +
           exactRealText(previousDeltaT_) + "\";\n";
}

template <int Dim>
void SphSolver<Dim>::restoreSolverState(const Dictionary& state) {
    started_ = state.getOrDefault<bool>("leapfrogStarted", false);
    // Read whole and checked, as Time reads its own exact reals (core/ExactReal): a damaged value
    // would resume the leapfrog with a wrong half step.
    const double value =
        state.found("previousDeltaTExact") ? readExactReal(state, "previousDeltaTExact") : 0.0;
    if (value < 0)
        throw state.error("previousDeltaTExact",
                          "expected a time step >= 0, found " + exactRealText(value) +
                              ": the state file is damaged; restart from an earlier time");
    previousDeltaT_ = value;
    // The file carries ρ, P, c, h as written; the half-step state resumes the leapfrog exactly.
}

template <int Dim>
std::vector<std::pair<std::string, double>> SphSolver<Dim>::phaseTimes() const {
    auto phases = Solver::phaseTimes();  // updateNeighbours first (declared so)
    phases.front().first += " (" + std::to_string(rebuilds_) + " rebuilds)";
    return phases;
}

template <int Dim>
std::vector<std::string> SphSolver<Dim>::summary(double loopSeconds) const {
    char line[160];
    std::snprintf(
        line, sizeof line,
        "pair interactions/s  %.4g (%.1f candidate pairs per particle, %zu list rebuilds in %zu steps)",
        loopSeconds > 0 ? pairInteractions_ / loopSeconds : 0.0,
        neighbourUpdates_ && !x_.empty() ? pairInteractions_ / double(neighbourUpdates_) / double(x_.size())
                                         : 0.0,
        rebuilds_, neighbourUpdates_);
    std::vector<std::string> lines{line};
    if (boundaries_.makesGhosts() && !ghostsEveryStep_) {
        std::snprintf(
            line, sizeof line,
            "mirror-ghost layers  %zu built in %zu steps (%zu ghosts in the last, one support + skin)",
            ghostLayerBuilds_, neighbourUpdates_, keptGhosts_.size());
        lines.emplace_back(line);
    }
    if (decomposition_)
        for (auto& l : decomposition_->summary(*particles_, double(neighbourUpdates_), "rate evaluation"))
            lines.push_back(std::move(l));
    return lines;
}

template class SphSolver<1>;
template class SphSolver<2>;
template class SphSolver<3>;

MFDYN_REGISTER_SOLVER(SphSolver, "impactSph", "Updated-Lagrangian SPH for shocks and impact");

}  // namespace mfdyn
