// fpmSolid: the finite pointset method for the dynamics of hypo-elastic solids (von Nida 2005;
// the method as engineered is doc/methods/fpm.md). Particles are the nodes of a moving
// least-squares fit in the current configuration (meshfreeOperators/LeastSquaresOperators, fit
// weights by name); the system is split into a volumetric (Euler), a deviatoric (shear) and a
// rotation part (§3.1). Built: the rotation part (§3.4) with prescribed or frozen particle motion
// (the rotation-only test, §4.9, R4 of §4b) and the Euler part (§3.2, fpm/EulerPart.hpp: the
// pressure-gradient upwinding) on frozen particles (the Euler validation, §4.4, R6) or moving them
// with its upwind velocity v_uw (the thesis's Euler-only runs, R6L), the shear part (§3.3,
// fpm/ShearPart.hpp: dimensional upwinding, the particles moved with its v_D), and the free surface
// (meshfreeOperators/SurfaceDetection, fpm/FreeSurfaceCondition.hpp: the thesis's p = p_o and
// S n = 0, or sigma n = -p_o n on the total stress). A step (the outline of the first build; the
// shear stage and the free surface's conditions after each stage are in step()):
//
//     neighbours (cell list, radius h, self included; (1 + maxShift) h for the Euler part's
//     shifted fits when a particle is shifted) -> fit (weights once per particle, applied to the
//     components of v and to p) -> euler (n = grad p / |grad p|, c^2 from the particle's
//     equationOfState at (rho, e), the fits at x -+ l n, rho, v, p, e updated by forward Euler)
//     -> rotation (on the Euler part's v: grad v refitted; W = skew grad v,
//     S <- exp(dt W) S exp(dt W)^T) -> volume (V <- V (1 + dt div v), the note's §4b remark)
//     -> motion (prescribed: the exact rigid rotation of x, v = omega a x (x - c); upwind:
//     x <- x + dt v_uw of the step's start; frozen: none) -> particleManagement (optional, last:
//     close pairs merged, particles inserted into holes, fpm/ParticleManagement.cpp)
//
// constant/fpmProperties:
//     subsystems (euler rotation);      // euler | shear | rotation; the order
//                                       // is the thesis's (euler before rotation) whatever is written
//     euler      { delta 0.3; maxShift 0.5; }  // the shift l = delta c (delta in s), or
//                                       // { deltaFraction 0.2; }: l = 0.2 h; l <= maxShift h
//     fitWeight  { type truncatedGaussian; alpha 6.25; squared yes; }   // family fitWeight
//     order      1;                     // the basis: 1 (the thesis) or 2
//     derivatives full;                 // full (the thesis's 3.11) | diffuse
//     smoothingLengthRatio 2;           // h = ratio x spacing (the thesis's r = 0.5: h = 1.5, 0.75)
//     smoothingLength 1.5;              // or h itself (not both)
//     spacing    0.75;                  // optional: the particle spacing (default: the largest V^(1/d))
//     motion     { velocity prescribed; omega 1; axis (0 0 -1); centre (0 0 0); }   // or { velocity frozen; }
//                                       // or { velocity upwind; } (euler: x <- x + dt v_uw)
//     initialState { type rigidRotation; omega (0 0 -1); }   // optional, with velocity frozen: v at a fresh start
//     initialStress { S (10 -10 0 0 0 0); shape { type box; min (-9 -9 -9); max (0 9 9); } }  // optional
//     particleManagement { insert yes; holeSize 0.5; merge yes; mergeDistance 0.15; }  // optional, off
//
// S is given as (xx yy zz xy yz xz); initialStress is applied at a fresh start to the particles
// inside its shape (all of them without one).
//
// Several ranks (mpirun; issue 21): the particles are cut by position, each rank advances its
// owned ones, and the halo (the other ranks' particles within the widest rows' reach plus h/2,
// with x, v, p, S) is appended at the step's start and refreshed after each stage; every fit's
// rows are in global-id order, so the state is the serial one to the bit (updateDecomposition).
// particleManagement runs on the whole set gathered on every rank, then cut again (manageParticles).
// system/controlDict: a fixed deltaT (adjustTimeStep no; the thesis's 0.001), or adjustTimeStep yes
// with maxCo: dt = maxCo x spacing / max |v| (prescribed motion), maxCo x spacing / max (c_L + |v|)
// with the Euler or shear part (c_L^2 = c^2 + (2 - 2/d) mu / rho, the note's [R] of §3.5).
//
// constant/materialProperties (optional): materials { name { equationOfState { ... } strength { ... } } }
// through the shared MaterialSet (both models optional; a constitutiveLaw is refused), the
// particles' `material` assigned. The Euler part needs it, and an equationOfState for every
// material: c^2 = soundSpeedSquared(rho, e) (the EOS gives the coefficient; p itself is evolved by its
// rate equation, §1, and read from the particles at a fresh start), e = specificInternalEnergy
// evolved by de/dt = -p div v / rho when the EOS needs it. c^2 <= 0 (the bracket rho c^2 of the
// Euler part's Dp/Dt) is a RunError naming the particle. The rotation part uses no material.
//
// Fields: position x, velocity v, density rho (particleGen's, constant in the rotation part),
// pressure p (0 unless given), specificInternalEnergy e (euler, an EOS that needs it),
// deviatoricStress S (symmetric), volume V (m / rho at a fresh start), globalId.
// With prescribed motion and the rotation part alone, the exact answer is known for any
// initial stress, S_exact(x, t) = Q(t) S0(Q(t)^T x) Q(t)^T with Q(t) the rotation by omega t (§4.9's
// S11 = 10 cos 2t, S21 = -10 sin 2t for S0 = diag(10, -10, 0), omega 1, axis -z): every step
// measures max |S - S_exact| (components), max | |x - c| - |x0 - c| | and the largest |S| of the
// particles that started unstressed; their largest values over the run are in the summary and in
// each time directory's file `rotationError`.
#include "fpm/FpmSolver.hpp"

#include "core/Log.hpp"
#include "core/Parallel.hpp"
#include "fpm/FreeSurfaceCondition.hpp"
#include "fpm/RotationPart.hpp"
#include "solver/InitialState.hpp"
#include "solver/LinearVelocity.hpp"
#include "solver/MaterialAssignment.hpp"
#include "solver/SolverRegistry.hpp"
#include "solver/SolverRun.hpp"

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <limits>
#include <numeric>
#include <sstream>
#include <type_traits>

namespace mfdyn {

namespace {

const std::vector<std::string> subsystemNames{"euler", "shear", "rotation"};

std::string joined(const std::vector<std::string>& words) {
    std::string text;
    for (const auto& w : words) text += (text.empty() ? "" : " | ") + w;
    return text;
}

template <int Dim>
typename LeastSquaresOperators<Dim>::Options fitOptions(const KeywordValues& settings) {
    typename LeastSquaresOperators<Dim>::Options options;
    options.order = int(settings.integer("order"));
    options.form = LeastSquaresOperators<Dim>::Form::value;  // the thesis's fit: any point, c_0 the value
    options.derivative = settings.word("derivatives") == "full"
                             ? LeastSquaresOperators<Dim>::Derivative::full
                             : LeastSquaresOperators<Dim>::Derivative::diffuse;
    options.minNeighbours = 2 * (Dim + 1);  // the note's 2(d+1) (§2)
    options.onFailure = LeastSquaresOperators<Dim>::OnFailure::throwError;
    const std::string& fallback = settings.word("fitFallback");
    options.fallback = fallback == "growSupport" ? LeastSquaresOperators<Dim>::Fallback::growSupport
                       : fallback == "shepard"   ? LeastSquaresOperators<Dim>::Fallback::shepard
                                                 : LeastSquaresOperators<Dim>::Fallback::none;
    return options;
}

NeighbourSearchOptions searchOptions() {
    NeighbourSearchOptions options;
    options.criterion = PairCriterion::gather;
    options.includeSelf = true;  // the value form fits the point's own value too
    options.sortRows = true;     // rows by index: the fit's sums in an order that does not depend on cells
    return options;
}

}  // namespace

namespace {

// An upwind part's shift from its dictionary: delta (a time, l = delta c) or deltaFraction (of h),
// not both, and the clamp maxShift; the part's defaults kept where neither is given.
void readShift(const KeywordValues& e, const Dictionary& dict, bool& deltaIsTime, double& delta,
               double& maxShift) {
    if (e.given("delta") && e.given("deltaFraction"))
        throw dict.error("deltaFraction", "give delta (a time) or deltaFraction (of h), not both");
    if (e.given("deltaFraction")) {
        deltaIsTime = false;
        delta = e.scalar("deltaFraction");
    } else if (e.given("delta")) {
        delta = e.scalar("delta");
    }
    maxShift = e.scalar("maxShift");
}

}  // namespace

template <int Dim>
KeywordSchema FpmSolver<Dim>::motionKeywords() {
    return KeywordSchema("solver", "fpmSolid/motion")
        .word("velocity", {"prescribed", "frozen", "upwind", "dimensional"},
              "the particles' motion: the rigid rotation v = omega axis x (x - centre), moved exactly "
              "(x <- c + Q (x - c), |x - c| kept to round-off), none, the Euler part's upwind "
              "velocity v_uw (x <- x + dt v_uw, the thesis's Euler-only runs; subsystems with euler), or "
              "the shear part's dimensional velocity v_D plus, with euler, the Euler part's upwind "
              "correction only (x <- x + dt (v_D + v_uw - Pi^c v), the thesis's coupled runs, §5.4)")
        .scalar("omega", "rad/s", "the angular speed of the prescribed rotation (velocity prescribed)")
        .optional()
        .vector("axis", "-", "the rotation axis, normalised here (velocity prescribed)")
        .ofLength(3)
        .optional()
        .vector("centre", "m", "a point on the axis")
        .ofLength(3)
        .orDefault(std::vector<double>{0, 0, 0});
}

template <int Dim>
KeywordSchema FpmSolver<Dim>::eulerKeywords() {
    return KeywordSchema("solver", "fpmSolid/euler")
        .scalar("delta", "s", "the upwind offset as a time: the shift length l = delta c (the thesis's 0.3)")
        .greaterThan(0)
        .optional()
        .scalar("deltaFraction", "-",
                "the shift length as a fraction of h, l = deltaFraction h (not with delta)")
        .greaterThan(0)
        .optional()
        .scalar("maxShift", "-", "the clamp l <= maxShift h (the note's 0.5)")
        .greaterThan(0)
        .atMost(1)
        .orDefault(0.5)
        .word("soundSpeed", {"isentropic", "literal"},
              "the c^2 of Dp/Dt = -rho c^2 div v: the equationOfState's isentropic one, or the thesis's "
              "literal dp/drho|e (1.29), with the -(g p / rho) div v part then in the shear part's "
              "(g/rho) sigma : grad v_D (an ideal gas alone is then isothermal, doc/methods/fpm.md §1)")
        .orDefault("isentropic")
        .word(
            "direction", {"gradient", "minimisation", "central"},
            "the upwind direction: along grad p (the thesis's), or its failing alternatives kept as negative "
            "controls (doc/methods/fpm.md §3.2, §4.1): the minimisation direction of |s^T E s| (5.27), or "
            "none (central)")
        .orDefault("gradient");
}

template <int Dim>
KeywordSchema FpmSolver<Dim>::freeSurfaceKeywords() {
    return KeywordSchema("solver", "fpmSolid/freeSurface")
        .scalar("pressure", "Pa",
                "the outer pressure p_o: p = p_o on the surface particles (the Euler part's condition) and, "
                "with the shear part, S n = 0, so that sigma n = -p_o n (doc/methods/fpm.md §3.2, §3.3)")
        .word("normals", {"centreOfMass", "covariance", "planeFit", "smoothedCovariance"},
              "the surface normal estimator (meshfreeOperators/SurfaceDetection.hpp; centreOfMass is the "
              "thesis's zeroth-order normal)")
        .orDefault("smoothedCovariance")
        .flag(
            "traction",
            "with the shear part, also S n = 0 on the surface particles (sigma n = -p_o n); no: p = p_o only")
        .orDefault(true)
        .word("velocity", {"unchanged", "characteristic"},
              "the surface particles' state when a part's conditions overwrite p and S: unchanged (v, rho, "
              "e kept), or characteristic (the outgoing characteristic kept: v -= (sigma n - sigma_o n) / Z "
              "per direction, Z = rho c in the Euler part, sqrt(mu rho) tangential and "
              "sqrt(2 (1 - 1/d) mu rho) normal in the shear part; and the Euler part's entropy wave "
              "rho - p / c^2: rho += (p_o - p) / c^2, e += p drho / rho^2)")
        .orDefault("unchanged")
        .word("condition", {"thesis", "traction"},
              "thesis: p = p_o and S n = 0, each part its own (the thesis's; it also sets the stress along "
              "the surface to -p_o); traction: sigma n = -p_o n on the total stress sigma = S - p I, its "
              "tangential block kept and re-split into p and S, after the shear and the Euler stage (a "
              "bent plate's surface carries its bending stress; fpm/FreeSurfaceCondition.hpp)")
        .orDefault("thesis")
        .scalar("edgeAngle", "deg",
                "with condition traction: a surface particle whose row holds a surface normal more than "
                "this from its own is at an edge or corner (SurfaceDetection::edges) and takes the thesis's "
                "conditions (p = p_o, S n = 0: sigma = -p_o I in-plane at a 2D corner, where both faces are "
                "free); 0: no edges")
        .atLeast(0)
        .lessThan(180)
        .orDefault(0)
        .scalar("offsetThreshold", "-", "the centre-of-mass offset above which a particle is a candidate")
        .atLeast(0)
        .lessThan(1)
        .orDefault(0.02)
        .scalar("scanLength", "-", "the scan region's length, in h (Marrone et al. 2010's h/2)")
        .greaterThan(0)
        .atMost(0.5)
        .orDefault(0.5);
}

template <int Dim>
KeywordSchema FpmSolver<Dim>::instabilityKeywords() {
    return KeywordSchema("solver", "fpmSolid/instabilityCheck")
        .vector("pressure", "Pa",
                "(lo hi): a particle pressure outside stops the run as an instability (the thesis's "
                "criterion for "
                "its failing schemes, single particles with p > 20 or p < -5 in the shock tube, §4.1)")
        .ofLength(2)
        .optional()
        .scalar("stress", "Pa",
                "a particle with a component |S_ij| above this stops the run as an instability")
        .greaterThan(0)
        .optional();
}

template <int Dim>
KeywordSchema FpmSolver<Dim>::managementKeywords() {
    return KeywordSchema("solver", "fpmSolid/particleManagement")
        .flag("insert",
              "insert a particle, with the order-1 fit's state, where a hole opens inside the body "
              "(fpm/ParticleManagement.cpp)")
        .orDefault(false)
        .scalar("holeSize", "-", "a hole: a point inside the body with no particle within holeSize h")
        .greaterThan(0)
        .atMost(1)
        .orDefault(0.5)
        .flag("merge",
              "merge a pair of particles closer than mergeDistance h into one (mass and momentum kept)")
        .orDefault(false)
        .scalar("mergeDistance", "-", "the distance below which a pair is merged, in h")
        .greaterThan(0)
        .lessThan(0.5)
        .orDefault(0.15)
        .scalar("surfaceOffset", "-",
                "a hole candidate y is inside the body when the centre-of-mass offset of its neighbours, "
                "|sum w (x_j - y)| / (h sum w), is at most this (0.5 one spacing beyond a lattice face, "
                "0.13-0.20 at a missing face particle's site, 0 at an interior one)")
        .greaterThan(0)
        .lessThan(1)
        .orDefault(0.3)
        .integer("interval", "-", "applied after the motion every this many steps")
        .atLeast(1)
        .orDefault(1);
}

template <int Dim>
KeywordSchema FpmSolver<Dim>::shearKeywords() {
    return KeywordSchema("solver", "fpmSolid/shear")
        .scalar("delta", "s",
                "the upwind offset as a time: the shift length l = delta c_S, c_S = sqrt(mu / rho) (the "
                "thesis's 0.3, which the clamp then takes: 0.3 c_S > h in its tests)")
        .greaterThan(0)
        .optional()
        .scalar("deltaFraction", "-",
                "the shift length as a fraction of h, l = deltaFraction h (not with delta)")
        .greaterThan(0)
        .optional()
        .scalar("maxShift", "-", "the clamp l <= maxShift h (the note's 0.5)")
        .greaterThan(0)
        .atMost(1)
        .orDefault(0.5)
        .word("velocity", {"printed", "corrected"},
              "the dimensional velocity v_D that moves the particles: (5.52) as printed, the mean of the "
              "shifted fits, or with the upwind correction -(1/(d Z)) sum_l (Pi_l+ S^il - Pi_l- S^il)/2, "
              "the analogue of the Euler part's (5.22) (doc/methods/fpm.md §7 item 7)")
        .orDefault("printed")
        .word(
            "scheme", {"dimensional", "central"},
            "dimensional upwinding (the thesis's), or none (central: the thesis's failing scheme, a negative "
            "control, §4.5)")
        .orDefault("dimensional");
}

template <int Dim>
KeywordSchema FpmSolver<Dim>::initialStressKeywords() {
    return KeywordSchema("solver", "fpmSolid/initialStress")
        .vector("S", "Pa", "the deviatoric stress (xx yy zz xy yz xz) set at a fresh start")
        .ofLength(6)
        .dictionary("shape", "the particles it applies to (a shape type; default all)")
        .optional();
}

// constant/fpmProperties: every keyword the solver reads (doc/models/solver/fpmSolid.md).
template <int Dim>
KeywordSchema FpmSolver<Dim>::keywords() {
    return KeywordSchema("solver", "fpmSolid")
        .words("subsystems",
               "the parts of the split that run (doc/methods/fpm.md §3.1): shear | euler | rotation, applied "
               "in the thesis's order shear -> euler -> rotation whatever the order written")

        .dictionary("fitWeight", "the least-squares fit's weight W(|x - y| / h) (a fitWeight type)")
        .integer("order", "-", "the fit's basis: 1 (linear, the thesis) or 2 (quadratic, the note's remedy)")
        .atLeast(1)
        .atMost(2)
        .orDefault(1)
        .word("derivatives", {"full", "diffuse"},
              "the gradient: of the approximant in the evaluation point (full, the thesis's 3.11) or the "
              "fit's linear coefficients (diffuse)")
        .orDefault("full")
        .word(
            "fitFallback", {"none", "growSupport", "shepard"},
            "a particle whose fit is singular or has fewer than 2(d+1) neighbours: an error (none), refitted "
            "with h x 1.2, 1.44, ... up to x 2 (growSupport; the neighbours are then searched within 2 h), "
            "or given the order-0 fit with zero gradient (shepard); counted in the summary")
        .orDefault("none")
        .scalar("smoothingLengthRatio", "-",
                "h = smoothingLengthRatio x spacing, h the fit's support radius (the thesis's r = 0.5: 2)")
        .greaterThan(0)
        .orDefault(2.0)
        .scalar("smoothingLength", "m", "h itself (the thesis's 1.5), instead of smoothingLengthRatio")
        .greaterThan(0)
        .optional()
        .scalar("spacing", "m", "the particle spacing (default: the largest V^(1/d))")
        .greaterThan(0)
        .optional()
        .scalar("shiftedFitCondition", "-",
                "the upwind parts' shifted fits fail below this reciprocal condition of their moment matrix "
                "(a point "
                "beyond a free surface sees one plane of particles: then the shift is shortened, or central)")
        .greaterThan(0)
        .lessThan(1)
        .orDefault(1e-6)
        .integer("shiftedFitOrder", "-",
                 "the basis of the upwind parts' fits at the shifted points (default: order); 1 with order "
                 "2 keeps the quadratic central fit but a linear one at points up to maxShift h beyond a "
                 "surface particle, where a quadratic extrapolates (the rotating sphere's README)")
        .atLeast(1)
        .atMost(2)
        .optional()
        .dictionary(
            "euler",
            "the Euler part's upwinding: delta (a time) or deltaFraction (of h), maxShift, soundSpeed")
        .optional()
        .nested(&FpmSolver<Dim>::eulerKeywords)
        .dictionary(
            "shear",
            "the shear part's dimensional upwinding: delta (a time) or deltaFraction (of h), maxShift, "
            "velocity")
        .optional()
        .nested(&FpmSolver<Dim>::shearKeywords)
        .dictionary("splitting", "the splitting of the step into the parts (a splitting type: lie, strang)")
        .optional()
        .dictionary("motion", "the particle motion: a prescribed rigid rotation, or frozen")
        .nested(&FpmSolver<Dim>::motionKeywords)
        .dictionary("initialState",
                    "with velocity frozen: the velocity set at a fresh start (an initialState type, e.g. "
                    "rigidRotation: the rotation part on fixed particles, as in the thesis's coupled run)")
        .optional()
        .dictionary("initialStress", "a uniform deviatoric stress set at a fresh start inside a shape")
        .optional()
        .nested(&FpmSolver<Dim>::initialStressKeywords)
        .dictionary(
            "freeSurface",
            "free-surface detection every step and its conditions p = p_o, sigma n = -p_o n: pressure, "
            "normals, offsetThreshold, scanLength")
        .optional()
        .nested(&FpmSolver<Dim>::freeSurfaceKeywords)
        .dictionary(
            "instabilityCheck",
            "stop the run as an instability, with the particle, where its pressure leaves a range or its "
            "deviatoric stress exceeds a bound (the negative controls of doc/methods/fpm.md R9)")
        .optional()
        .nested(&FpmSolver<Dim>::instabilityKeywords)
        .dictionary("particleManagement",
                    "insertion into holes and merging of close pairs after the motion (off by default): "
                    "insert, holeSize, merge, mergeDistance, surfaceOffset, interval")
        .optional()
        .nested(&FpmSolver<Dim>::managementKeywords)
        .dictionary("reference",
                    "{ type linearFlow; }: the exact uniform state of a linear velocity field (initialState "
                    "linearVelocity) and uniform rho, p, e, S, measured every step (doc/methods/fpm.md §4.4, "
                    "§4.6, §4.10; fpm/LinearFlowReference.hpp)")
        .optional();
}

template <int Dim>
KeywordValues FpmSolver<Dim>::readSettings(const Dictionary& properties) {
    // An entry the schema does not know is an error at its line with the valid keywords (a misspelt
    // keyword would otherwise fall back to a default silently).
    const KeywordSchema schema = keywords();
    std::vector<std::string> known;
    for (const auto& k : schema.keywords()) known.push_back(k.name);
    for (const auto& key : properties.keys()) {
        if (std::find(known.begin(), known.end(), key) != known.end()) continue;
        const std::string guess = closestMatch(key, known);
        throw properties.error(key, "unknown keyword '" + key +
                                        "' in fpmProperties; valid keywords: " + joined(known) +
                                        (guess.empty() ? "" : "; did you mean '" + guess + "'?"));
    }
    return schema.read(properties);
}

template <int Dim>
FpmSolver<Dim>::FpmSolver(SolverRun& run)
    : Solver(run),
      owner_(adoptParticleSet<Dim>(run.takeParticles())),
      properties_(openConstant("fpmProperties")),
      settings_(readSettings(properties_)),
      x_(owner_->position()),
      v_(owner_->vectorField("velocity")),
      rho_(requireScalarField(*owner_, "density", "particle densities")),
      search_(NeighbourDomain<Dim>{}, searchOptions()),
      fit_(fitOptions<Dim>(settings_)) {
    if constexpr (Dim == 1)
        throw InputError("fpmSolid: the method is 2D or 3D (the thesis's is 3D); this case is 1D");
    declarePhases({"neighbours", "fit", "shear", "euler", "rotation", "volume", "motion"});
    readSubsystems();
    fitWeight_ = FitWeight::New(settings_.dictionary("fitWeight"));
    splitting_ = settings_.given("splitting")
                     ? fpm::Splitting::New(settings_.dictionary("splitting"))
                     : fpm::Splitting::New(Dictionary::parse("type lie;", "fpmProperties"));
    readMotion();
    readEuler();
    readShear();
    readFreeSurface();
    if (settings_.given("instabilityCheck")) {
        const KeywordValues& c = settings_.nested("instabilityCheck");
        if (c.given("pressure")) {
            checkPressure_ = true;
            pressureLow_ = c.vector("pressure")[0];
            pressureHigh_ = c.vector("pressure")[1];
            if (!(pressureLow_ < pressureHigh_))
                throw settings_.dictionary("instabilityCheck")
                    .error("pressure", "expected (lo hi) with lo < hi");
        }
        if (c.given("stress")) stressBound_ = c.scalar("stress");
    }
    if (settings_.given("initialStress")) {
        const Dictionary& dict = settings_.dictionary("initialStress");
        const std::vector<double>& s = settings_.nested("initialStress").vector("S");
        // (xx yy zz xy yz xz), truncated to the dimension by SymmTensor's own order
        const int ij[6][2] = {{0, 0}, {1, 1}, {2, 2}, {0, 1}, {1, 2}, {0, 2}};
        for (int k = 0; k < 6; ++k) {
            const int i = ij[k][0], j = ij[k][1];
            if (i < Dim && j < Dim) {
                stress0_(i, j) = s[std::size_t(k)];
            } else if (s[std::size_t(k)] != 0) {
                throw dict.error("S", "component " + std::to_string(k + 1) + " is out of this " +
                                          std::to_string(Dim) + "D case's plane and must be 0");
            }
        }
        if (dict.isDict("shape")) stressShape_ = Shape::New(dict.subDict("shape"), Dim);
        hasInitialStress_ = true;
    }
    readMaterials();
    initialiseFields();
    readManagement();
    boundaryConditions_ = readBoundaryConditions(*owner_, {.ghosts = false, .boundaryForces = false});
    if (!boundaryConditions_.empty() && !(euler_ || shear_) && !prescribed_)
        Log::warning(
            "fpmSolid: boundary conditions with the rotation part alone act on v only, which it does not "
            "evolve");
    decomposition_ = run.decomposition();
    if (decomposition_) {
        // What the fits read of a neighbour: its position, and the fields fitted (v by every part,
        // p by the Euler part, S by the shear part); rho, e, c, mu and the material are read of the
        // particle itself only. The halo's v, p and S are refreshed where a stage or a surface
        // condition changed them (refreshHalo).
        haloFields_ = {"position", "velocity", "pressure"};
        if (S_) haloFields_.push_back("deviatoricStress");
        // Planned now, so that what runs before the first step (the health indicators) sees each
        // rank's neighbours across its cuts.
        updateDecomposition();
    }
}

// constant/materialProperties, when the case has one, through the shared MaterialSet: per material
// an equation of state and a strength law (its shear modulus), both optional, for the Euler and shear
// parts to come (the rotation part reads none); each particle's material assigned and logged.
template <int Dim>
void FpmSolver<Dim>::readMaterials() {
    const Dictionary* dict = openOptionalConstant("materialProperties");
    if (!dict && euler_)
        throw properties_.error("subsystems",
                                "the Euler part needs constant/materialProperties with an equationOfState "
                                "(c^2 of its pressure equation)");
    if (!dict && shear_)
        throw properties_.error("subsystems",
                                "the shear part needs constant/materialProperties with a strength law (its "
                                "shear modulus)");
    if (!dict) return;
    MaterialModels models;
    models.method = "fpmSolid";
    models.equationOfState = ModelUse::optional;
    models.strength = ModelUse::optional;
    materials_ = std::make_unique<MaterialSet<Dim>>(*dict, models);
    assignMaterials(*owner_, materials_->names(), *dict);
    if (euler_) {
        const std::vector<std::int64_t>& material = owner_->integerField("material");
        for (std::size_t i = 0; i < material.size(); ++i)
            if (!(*materials_)[std::size_t(material[i])].eos)
                throw dict->error("materials", "the Euler part needs an equationOfState in material '" +
                                                   materials_->names()[std::size_t(material[i])] +
                                                   "' (particle " + std::to_string(owner_->globalId()[i]) +
                                                   " is made of it)");
    }
    if (shear_) {
        // mu per particle from its strength law (0 without one: the particle is not sheared), the
        // deviator's weight from the laws (one value for the run), plasticity where a law yields.
        const std::vector<std::int64_t>& material = owner_->integerField("material");
        bool anyStrength = false, weightSet = false;
        for (std::size_t k = 0; k < materials_->size(); ++k) {
            const auto* strength = (*materials_)[k].strength.get();
            if (!strength) continue;
            if (weightSet && strength->deviatorWeight() != deviatorWeight_)
                throw dict->error("materials",
                                  "the strength laws of material '" + materials_->names()[k] +
                                      "' and another weigh the deviator's trace differently "
                                      "(deviator dimension | three): give every material the same");
            deviatorWeight_ = strength->deviatorWeight();
            weightSet = true;
            plastic_ =
                plastic_ || std::isfinite(strength->yieldStress(0.0, 0.0, strength->initialTemperature()));
            if (strength->usesTemperature())
                throw dict->error("materials",
                                  "material '" + materials_->names()[k] + "': strength " + strength->type() +
                                      " needs a temperature, which fpmSolid does not evolve; use "
                                      "hookean or vonMises");
        }
        assignShearModuli();
        for (std::size_t i = 0; i < material.size(); ++i)
            anyStrength = anyStrength || (*materials_)[std::size_t(material[i])].strength != nullptr;
        // over every rank: one whose particles are all unstrained is no error
        anyStrength =
            GlobalReduce::max(std::size_t(1), [&](std::size_t) { return anyStrength ? 1.0 : 0.0; }) > 0;
        if (!anyStrength)
            throw dict->error(
                "materials",
                "the shear part needs a strength law with a shear modulus in some material "
                "(e.g. strength { type hookean; shearModulus 50; }); none of the particles has one");
        if (plastic_) plasticStrain_ = &owner_->scalarField("plasticStrain");
    }
    if ((euler_ || shear_) && materials_->needsEnergy()) e_ = &owner_->scalarField("specificInternalEnergy");
    Log::info("fpmSolid: " + std::to_string(materials_->size()) + " material(s) read; " +
              (euler_ || shear_
                   ? std::string(euler_ ? "the Euler part takes c^2 from their equationOfState" : "") +
                         (euler_ && shear_ ? "; " : "") +
                         (shear_ ? "the shear part takes mu from their strength law and g = "
                                   "dp/de|rho from their equationOfState (0 without one)"
                                 : "")
                   : std::string("the rotation part uses none of their models")));
}

// mu per owned particle from its material's strength law (0 without one: not sheared); again after
// a migration, which brings other particles.
template <int Dim>
void FpmSolver<Dim>::assignShearModuli() {
    const std::vector<std::int64_t>& material = owner_->integerField("material");
    mu_.assign(owner_->ownedCount(), 0.0);
    for (std::size_t i = 0; i < mu_.size(); ++i) {
        const auto* strength = (*materials_)[std::size_t(material[i])].strength.get();
        if (strength) mu_[i] = strength->shearModulus();
    }
}

template <int Dim>
void FpmSolver<Dim>::readEuler() {
    if (!euler_ && upwindMotion_)
        throw settings_.dictionary("motion").error(
            "velocity", "velocity upwind is the Euler part's: subsystems with euler");
    if (!euler_) {
        if (settings_.given("euler"))
            throw properties_.error("euler", "euler { ... } is for subsystems with euler");
        return;
    }
    if (prescribed_)
        throw settings_.dictionary("motion").error(
            "velocity",
            "the Euler part evolves v: it runs on frozen particles (motion { velocity frozen; }) "
            "or moves them with its upwind velocity (motion { velocity upwind; })");
    fpm::UpwindOptions upwind;
    if (settings_.given("euler")) {
        const KeywordValues& e = settings_.nested("euler");
        readShift(e, settings_.dictionary("euler"), upwind.deltaIsTime, upwind.delta, upwind.maxShift);
        literalSoundSpeed_ = e.word("soundSpeed") == "literal";
        const std::string& direction = e.word("direction");
        upwind.direction = direction == "minimisation" ? fpm::UpwindDirection::minimisation
                           : direction == "central"    ? fpm::UpwindDirection::central
                                                       : fpm::UpwindDirection::gradient;
    }
    upwind.shiftedFitCondition = settings_.scalar("shiftedFitCondition");
    eulerPart_ = std::make_unique<fpm::EulerPart<Dim>>(shiftedFitBase(), upwind);
}

template <int Dim>
void FpmSolver<Dim>::readShear() {
    if (!shear_ && dimensionalMotion_)
        throw settings_.dictionary("motion").error(
            "velocity", "velocity dimensional is the shear part's: subsystems with shear");
    if (!shear_) {
        if (settings_.given("shear"))
            throw properties_.error("shear", "shear { ... } is for subsystems with shear");
        return;
    }
    if (prescribed_)
        throw settings_.dictionary("motion").error(
            "velocity",
            "the shear part evolves v: it runs on frozen particles (motion { velocity frozen; }) "
            "or moves them with its dimensional velocity (motion { velocity dimensional; })");
    if (upwindMotion_)
        throw settings_.dictionary("motion").error(
            "velocity",
            "with the shear part the particles move with its dimensional velocity (the thesis's "
            "coupled runs, §5.4): motion { velocity dimensional; } or frozen");
    fpm::ShearOptions options;
    options.literalSoundSpeed = literalSoundSpeed_;
    if (settings_.given("shear")) {
        const KeywordValues& e = settings_.nested("shear");
        readShift(e, settings_.dictionary("shear"), options.deltaIsTime, options.delta, options.maxShift);
        options.correctedVelocity = e.word("velocity") == "corrected";
        options.central = e.word("scheme") == "central";
    }
    options.shiftedFitCondition = settings_.scalar("shiftedFitCondition");
    shearPart_ = std::make_unique<fpm::ShearPart<Dim>>(shiftedFitBase(), options);
}

// The fit options the upwind parts build their shifted fits from: the central fit's, at
// shiftedFitOrder where given.
template <int Dim>
typename LeastSquaresOperators<Dim>::Options FpmSolver<Dim>::shiftedFitBase() const {
    typename LeastSquaresOperators<Dim>::Options options = fitOptions<Dim>(settings_);
    if (settings_.given("shiftedFitOrder")) options.order = int(settings_.integer("shiftedFitOrder"));
    return options;
}

template <int Dim>
FpmSolver<Dim>::~FpmSolver() = default;

template <int Dim>
void FpmSolver<Dim>::readSubsystems() {
    const std::vector<std::string>& names = settings_.words("subsystems");
    for (const auto& name : names) {
        if (std::find(subsystemNames.begin(), subsystemNames.end(), name) == subsystemNames.end()) {
            const std::string guess = closestMatch(name, subsystemNames);
            throw properties_.error(
                "subsystems", "unknown subsystem '" + name + "'; valid choices: " + joined(subsystemNames) +
                                  (guess.empty() ? "" : "; did you mean '" + guess + "'?"));
        }
        if (name == "shear") shear_ = true;
        if (name == "euler") euler_ = true;
        if (name == "rotation") rotation_ = true;
    }
    if (!euler_ && !rotation_ && !shear_)
        throw properties_.error("subsystems", "no subsystem to run: shear | euler | rotation");
    if (shear_) parts_.push_back(fpm::Subsystem::shear);
    if (euler_) parts_.push_back(fpm::Subsystem::euler);
    if (rotation_) parts_.push_back(fpm::Subsystem::rotation);
}

template <int Dim>
void FpmSolver<Dim>::readMotion() {
    const KeywordValues& motion = settings_.nested("motion");
    const Dictionary& dict = settings_.dictionary("motion");
    prescribed_ = motion.word("velocity") == "prescribed";
    upwindMotion_ = motion.word("velocity") == "upwind";
    dimensionalMotion_ = motion.word("velocity") == "dimensional";
    const std::vector<double>& c = motion.vector("centre");
    for (int k = 0; k < Dim; ++k) centre_(k) = c[std::size_t(k)];
    if (!prescribed_) {
        for (const char* key : {"omega", "axis"})
            if (motion.given(key))
                throw dict.error(key, std::string(key) + " belongs to velocity prescribed, not " +
                                          motion.word("velocity"));
        return;
    }
    if (!motion.given("omega") || !motion.given("axis"))
        throw dict.error("velocity", "velocity prescribed needs omega (rad/s) and axis (x y z)");
    omega_ = motion.scalar("omega");
    const std::vector<double>& a = motion.vector("axis");
    axis_ = Vector<3>(a[0], a[1], a[2]);
    if (!(axis_.norm() > 0)) throw dict.error("axis", "the axis must not be zero");
    axis_.normalize();
    if (Dim == 2 && (axis_(0) != 0 || axis_(1) != 0))
        throw dict.error("axis", "in 2D the rotation axis is z: (0 0 1) or (0 0 -1)");
}

template <int Dim>
Vector<Dim> FpmSolver<Dim>::prescribedVelocity(const Vector<Dim>& x) const {
    Vector<3> r = Vector<3>::Zero();
    for (int k = 0; k < Dim; ++k) r(k) = x(k) - centre_(k);
    const Vector<3> v = omega_ * axis_.cross(r);
    return v.template head<Dim>();
}

template <int Dim>
SymmTensor<Dim> FpmSolver<Dim>::initialStressAt(const Vector<Dim>& X) const {
    if (!hasInitialStress_) return {};
    if (stressShape_) {
        double p[3] = {0, 0, 0};
        for (int k = 0; k < Dim; ++k) p[k] = X(k);
        if (!stressShape_->inside(p)) return {};
    }
    return stress0_;
}

template <int Dim>
void FpmSolver<Dim>::initialiseFields() {
    const std::size_t n = x_.size();
    const bool fresh = run_.restartState() == nullptr;
    std::vector<double>& m = requireScalarField(*owner_, "mass", "particle masses");
    checkPositiveMassAndDensity(*owner_, m, rho_);
    const bool hadVolume = owner_->template findField<double>("volume") != nullptr;
    const bool hadStress = owner_->template findField<SymmTensor<Dim>>("deviatoricStress") != nullptr;
    p_ = &owner_->scalarField("pressure");
    V_ = &owner_->scalarField("volume");
    // The deviator only where something evolves or reads it (leave out what a scene does not
    // need): the shear part, the rotation part (which turns a given stress), an initial stress; a
    // state that carries one keeps it.
    if (shear_ || rotation_ || hasInitialStress_ || hadStress)
        S_ = &owner_->symmTensorField("deviatoricStress");
    if (!hadVolume)
        for (std::size_t i = 0; i < n; ++i) (*V_)[i] = m[i] / rho_[i];
    if (S_ && (fresh || !hadStress))
        for (std::size_t i = 0; i < n; ++i) (*S_)[i] = initialStressAt(x_[i]);
    if (prescribed_ && fresh)
        for (std::size_t i = 0; i < n; ++i) v_[i] = prescribedVelocity(x_[i]);
    if (settings_.given("initialState")) {
        const Dictionary& dict = settings_.dictionary("initialState");
        if (prescribed_)
            throw dict.error(
                "type",
                "velocity prescribed sets v itself: initialState is for `motion { velocity frozen; }`");
        const auto state = InitialState<Dim>::New(dict);
        if (state->hasDisplacement())
            throw dict.error("type", "fpmSolid takes a velocity from initialState, not a displacement (" +
                                         dict.get<std::string>("type") + " has one)");
        if (fresh) {
            const std::vector<Vector<Dim>> X = x_;
            state->apply(*owner_, X);
        }
    }

    double largestVolume = 0;
    for (std::size_t i = 0; i < n; ++i) largestVolume = std::max(largestVolume, (*V_)[i]);
    largestVolume = GlobalReduce::max(std::size_t(1), [&](std::size_t) { return largestVolume; });
    spacing_ = settings_.given("spacing") ? settings_.scalar("spacing") : std::pow(largestVolume, 1.0 / Dim);
    if (settings_.given("smoothingLength")) {
        if (properties_.found("smoothingLengthRatio"))
            throw properties_.error("smoothingLength",
                                    "give smoothingLength or smoothingLengthRatio, not both");
        h_ = settings_.scalar("smoothingLength");
    } else {
        h_ = settings_.scalar("smoothingLengthRatio") * spacing_;
    }
    // The reference holds for the rotation part alone with a prescribed rigid rotation from t = 0.
    reference_ = prescribed_ && rotation_;
    budget_ = euler_ || shear_;  // where U is measured
    if (euler_ || shear_) {      // this run's start, for the state-change measure
        rhoStart_ = rho_;
        pStart_ = *p_;
        vStart_ = v_;
    }
    radius0_.resize(n);
    for (std::size_t i = 0; i < n; ++i) radius0_[i] = (x_[i] - centre_).norm();  // at this run's start
    if (settings_.given("reference")) readFlowReference();

    std::ostringstream log;
    log << "fpmSolid: " << GlobalReduce::sum<double>(std::size_t(1), [&](std::size_t) { return double(n); })
        << " particles, spacing " << spacing_ << ", h " << h_ << " (" << h_ / spacing_
        << " spacings), fit order " << settings_.integer("order")
        << (settings_.given("shiftedFitOrder")
                ? " (shifted fits " + std::to_string(settings_.integer("shiftedFitOrder")) + ")"
                : std::string())
        << " (" << settings_.word("derivatives") << " derivatives), fitWeight " << fitWeight_->type()
        << (fitWeight_->squared() ? " squared" : "") << "; splitting " << splitting_->type()
        << ", subsystems:"
        << (shear_ ? std::string(shearPart_->options().central ? " shear (no upwinding: central; "
                                                               : " shear (dimensional upwinding, l = ") +
                         formatKeywordNumber(shearPart_->options().delta) +
                         (shearPart_->options().deltaIsTime ? " c_S" : " h") +
                         " <= " + formatKeywordNumber(shearPart_->options().maxShift) + " h, v_D " +
                         (shearPart_->options().correctedVelocity ? "corrected" : "printed") + ")"
                   : std::string())
        << (euler_ ? std::string(" euler (") +
                         (eulerPart_->options().direction == fpm::UpwindDirection::gradient ? "grad p"
                          : eulerPart_->options().direction == fpm::UpwindDirection::minimisation
                              ? "minimisation-direction"
                              : "no") +
                         " upwinding, l = "
                   : std::string())
        << (euler_ ? formatKeywordNumber(eulerPart_->options().delta) +
                         (eulerPart_->options().deltaIsTime ? " c" : " h") +
                         " <= " + formatKeywordNumber(eulerPart_->options().maxShift) + " h)"
                   : std::string())
        << (rotation_ ? " rotation (exact exp map)" : "") << "; motion: "
        << (prescribed_          ? "prescribed rigid rotation, omega " + formatKeywordNumber(omega_)
            : upwindMotion_      ? std::string("the Euler part's upwind velocity, x <- x + dt v_uw")
            : dimensionalMotion_ ? std::string("the shear part's dimensional velocity, x <- x + dt v_D") +
                                       (euler_ ? " + dt (v_uw - Pi^c v) (the Euler part's correction)" : "")
                                 : std::string("frozen"));
    Log::info(log.str());
}

template <int Dim>
TimeStepVote FpmSolver<Dim>::stableTimeStep() {
    // The vote names its particle: the lowest global id among those at the limit (the same
    // expression as the reduction, so the limit is one of its values exactly; one more reduction).
    const auto limitedBy = [&](auto&& speedOf, double speed) {
        double first = std::numeric_limits<double>::infinity();
        const std::vector<std::int64_t>& id = owner_->globalId();
        for (std::size_t i = 0; i < x_.size(); ++i)
            if (speedOf(i) >= speed) first = std::min(first, double(id[i]));
        first = globalMin(first);
        return std::isfinite(first) ? std::int64_t(first) : std::int64_t(-1);
    };
    if (euler_ || shear_) {
        // The note's [R] (doc/methods/fpm.md §3.5): dt = maxCo spacing / max (c_L + |v|), with
        // c_L^2 = c^2 + (2 - 2/d) mu / rho (c^2 the Euler part's, 0 without it; mu the shear part's),
        // the longitudinal wave of the full system (§1) in the particles' frame, plus their speed.
        const std::vector<std::int64_t>& material = owner_->integerField("material");
        const auto speedOf = [&](std::size_t i) {
            double c2 = 0;
            if (euler_) {
                const EquationOfState& eos = *(*materials_)[std::size_t(material[i])].eos;
                const double e = e_ ? (*e_)[i] : 0.0;
                c2 += literalSoundSpeed_ ? eos.densityDerivative(rho_[i], e)
                                         : eos.soundSpeedSquared(rho_[i], e);
            }
            if (shear_) c2 += (2.0 - 2.0 / Dim) * mu_[i] / rho_[i];
            return std::sqrt(std::max(c2, 0.0)) + v_[i].norm();
        };
        const double speed = GlobalReduce::max(x_.size(), speedOf);
        if (!(speed > 0)) return {std::numeric_limits<double>::infinity(), "Courant (c_L + |v|)"};
        return {time().maxCo() * spacing_ / speed, "Courant (c_L + |v|)", limitedBy(speedOf, speed)};
    }
    if (!prescribed_) return {std::numeric_limits<double>::infinity(), "frozen particles"};
    const auto speedOf = [&](std::size_t i) { return v_[i].squaredNorm(); };
    const double v2 = GlobalReduce::max(v_.size(), speedOf);
    if (!(v2 > 0)) return {std::numeric_limits<double>::infinity(), "Courant"};
    return {time().maxCo() * spacing_ / std::sqrt(v2), "Courant", limitedBy(speedOf, v2)};
}

template <int Dim>
void FpmSolver<Dim>::step(double dt) {
    if (decomposition_) {
        updateDecomposition();
        auto timed = phase("neighbours");
        decomposition_->appendHalo(*owner_, haloFields_);
    }
    // The particles this rank evaluates and advances; x_.size() - n are the halo's, read only.
    const std::size_t n = owner_->ownedCount();
    {
        auto timed = phase("neighbours");
        // growSupport refits within the rows it is given: they must reach its largest support
        rows_ = rowsWithin(centralReach() * h_);
    }
    {
        auto timed = phase("fit");
        hField_.assign(n, h_);
        points_.assign(x_.begin(), x_.begin() + std::ptrdiff_t(n));
        fit_.labelPoints(owner_->globalId().data());  // the first n particles are the points
        try {
            fit_.rebuild(points_, x_, rows_, hField_, *fitWeight_);
        } catch (const InputError&) {
            throw;
        } catch (const RunError&) {
            throw;
        } catch (const Error& e) {
            // The fit's own diagnosis (the point's index on this process and its global id, its
            // position and neighbour counts, the remedies), with the time and the solver's remedy.
            // Rank-local: with several ranks the run ends on this rank's error.
            throw RunError(
                "phase fit, step " + std::to_string(time().timeIndex() + 1) +
                ", t = " + formatKeywordNumber(time().value() + dt) + ": " + e.what() +
                " In constant/fpmProperties: a larger smoothingLength, or fitFallback growSupport | "
                "shepard.");
        }
        // the weights once per particle, applied to the Dim components of v
        gradV_ = fit_.gradientOf(v_);
        {
            SumArray<2> local;
            local.s = {double(rows_.offsets()[n]), double(n)};
            const SumArray<2> pairs = globalSum(local);
            neighboursPerParticle_ = pairs.s[1] > 0 ? pairs.s[0] / pairs.s[1] : 0.0;
        }
        if (surface_) {  // on the rows within h (growSupport's rows reach further: detection takes h)
            markVelocityHeld(time().value() + dt);
            surface_->detect(x_, rows_, h_, {},
                             [&](void* data, std::size_t bytes) { owner_->refreshHalo(data, bytes); });
            if (edgeAngle_ > 0) {
                edge_ = surface_->edges(rows_, edgeAngle_);
                edgeParticles_ += std::size_t(std::count(edge_.begin(), edge_.end(), 1));
            }
            surfaceParticles_ += surface_->surfaceCount();
            const double before = budget_ ? ownedEnergy(n) : 0.0;
            applyFreeSurface(std::nullopt);  // the step starts from a state that satisfies the conditions
            if (budget_) schemeDissipation_ -= ownedEnergy(n) - before;
            refreshHalo();  // the conditions changed p and S (the fits' values)
        }
        grown_ += fit_.fallbackCounts().grown;
        shepard_ += fit_.fallbackCounts().shepard;
    }
    // The parts in the splitting's stages, each on the previous one's results and this step's fit
    // (the particles move once, after the last stage, with the velocity the stages accumulated).
    const bool moving = upwindMotion_ || dimensionalMotion_;
    if (moving) motionVelocity_.assign(n, Vector<Dim>::Zero());
    divergence_.clear();
    wideBuilt_ = false;
    const std::vector<Tensor<Dim>> gradVStart = gradV_;
    bool first = true;
    for (const fpm::SplitStage& stage : splitting_->stages(parts_)) {
        if (!first) {  // the stage's start: the previous stage's v (and p, S), the halo's too
            refreshHalo();
            gradV_ = fit_.gradientOf(v_);
        }
        first = false;
        const double dts = stage.fraction * dt;
        const bool measured =
            budget_ && stage.part != fpm::Subsystem::rotation;  // the exact rotation keeps |v|, S : S
        if (measured) rememberStageStart(n);
        switch (stage.part) {
            case fpm::Subsystem::shear:
                shearStage(dts, stage.fraction);
                break;
            case fpm::Subsystem::euler:
                eulerStage(dts, stage.fraction);
                break;
            case fpm::Subsystem::rotation:
                rotationStage(dts);
                break;
        }
        // the free surface's conditions, then the velocity conditions on what the stage left (v at
        // the step's end time: a Dirichlet value holds on the boundary particles throughout, the
        // surface's characteristic velocity included: a clamped surface particle stays clamped)
        if (measured) schemeDissipation_ -= stageStartPower(n);
        if (stage.part != fpm::Subsystem::rotation && surface_) {
            const double before = budget_ ? ownedEnergy(n) : 0.0;
            applyFreeSurface(stage.part);
            if (budget_) schemeDissipation_ -= ownedEnergy(n) - before;
        }
        if (stage.part != fpm::Subsystem::rotation && !boundaryConditions_.empty()) {
            const double before = budget_ ? ownedKinetic(n) : 0.0;
            boundaryConditions_.constrainVelocity(*owner_, v_, time().value() + dt);
            if (budget_) externalWork_ += ownedKinetic(n) - before;
        }
    }
    {
        // V <- V (1 + dt div v): the Euler part's div v_uw where it runs (so that rho V stays the
        // mass to O(dt^2)), else the central div v of the step's start.
        auto timed = phase("volume");
        std::vector<double>& V = *V_;
        const double volumeBefore = budget_ && outerPressure_ != 0
                                        ? GlobalReduce::sum<double>(n, [&](std::size_t i) { return V[i]; })
                                        : 0.0;
        if (divergence_.empty())
            parallelFor(n, [&](std::size_t i) { V[i] *= 1.0 + dt * gradVStart[i].trace(); });
        else
            parallelFor(n, [&](std::size_t i) { V[i] *= 1.0 + dt * divergence_[i]; });
        if (budget_ && outerPressure_ != 0)  // the outer pressure's work on the body's change of volume
            externalWork_ -=
                outerPressure_ *
                (GlobalReduce::sum<double>(n, [&](std::size_t i) { return V[i]; }) - volumeBefore);
    }
    if (moving) {  // the velocity the stages accumulated (Euler: v_uw or its correction; shear: v_D)
        auto timed = phase("motion");
        // the velocity conditions hold for the motion too (a slip wall's particles slide along it)
        if (!boundaryConditions_.empty())
            boundaryConditions_.constrainVelocity(*owner_, motionVelocity_, time().value() + dt);
        parallelFor(n, [&](std::size_t i) { x_[i] += dt * motionVelocity_[i]; });
        if (!boundaryConditions_.empty()) boundaryConditions_.constrainPosition(*owner_, time().value() + dt);
    }
    if (prescribed_) {
        auto timed = phase("motion");
        const double before = budget_ ? ownedKinetic(n) : 0.0;
        const Tensor<3> Q3 = fpm::axisRotation(axis_, omega_, dt);
        const Tensor<Dim> Q = Q3.template topLeftCorner<Dim, Dim>();
        parallelFor(n, [&](std::size_t i) {
            x_[i] = centre_ + Q * (x_[i] - centre_);
            v_[i] = prescribedVelocity(x_[i]);
        });
        if (budget_) externalWork_ += ownedKinetic(n) - before;
    }
    checkState(
        "rotation", n,
        [&](std::size_t i) {
            const auto s = stressOf(i);
            for (double c : s.c)
                if (!std::isfinite(c)) return true;
            return !x_[i].allFinite() || !std::isfinite((*V_)[i]) || !v_[i].allFinite() ||
                   !std::isfinite(rho_[i]) || !std::isfinite((*p_)[i]);
        },
        [&](std::size_t i, double count) {
            return "particle " + std::to_string(owner_->globalId()[i]) +
                   " has a stress, position, volume, velocity, density or pressure that is not finite; " +
                   std::to_string(long(count)) + " particles affected";
        });
    if (checkPressure_ || stressBound_ > 0) {
        const std::vector<double>& p = *p_;
        const auto largest = [&](std::size_t i) {
            double m = 0;
            for (double c : stressOf(i).c) m = std::max(m, std::abs(c));
            return m;
        };
        checkState(
            "instabilityCheck", n,
            [&](std::size_t i) {
                return (checkPressure_ && !(p[i] >= pressureLow_ && p[i] <= pressureHigh_)) ||
                       (stressBound_ > 0 && !(largest(i) <= stressBound_));
            },
            [&](std::size_t i, double count) {
                return "instability detected: particle " + std::to_string(owner_->globalId()[i]) + " at (" +
                       formatKeywordNumber(x_[i](0)) + " ...) has pressure " + formatKeywordNumber(p[i]) +
                       " and largest |S_ij| " + formatKeywordNumber(largest(i)) +
                       ", outside instabilityCheck (pressure " +
                       (checkPressure_ ? "(" + formatKeywordNumber(pressureLow_) + " " +
                                             formatKeywordNumber(pressureHigh_) + ")"
                                       : std::string("unchecked")) +
                       ", stress " +
                       (stressBound_ > 0 ? formatKeywordNumber(stressBound_) : std::string("unchecked")) +
                       "); " + std::to_string(long(count)) +
                       " particles affected. Remedy: the upwinded schemes (euler { direction gradient; }, "
                       "shear { "
                       "scheme dimensional; }), a smaller deltaT, or a larger delta (more dissipation)";
            });
    }
    if (reference_) measureRotationError(time().value() + dt);
    if (flowReference_) measureFlowError(time().value() + dt);
    if (euler_ || shear_) {
        StateChange c;
        c.rho = GlobalReduce::max(n, [&](std::size_t i) { return std::abs(rho_[i] - rhoStart_[i]); });
        c.p = GlobalReduce::max(n, [&](std::size_t i) { return std::abs((*p_)[i] - pStart_[i]); });
        c.v = GlobalReduce::max(n, [&](std::size_t i) { return (v_[i] - vStart_[i]).norm(); });
        lastChange_ = c;
        worstChange_.rho = std::max(worstChange_.rho, c.rho);
        worstChange_.p = std::max(worstChange_.p, c.p);
        worstChange_.v = std::max(worstChange_.v, c.v);
    }
    // The halo is remade at the next step (its x are this step's start's): between steps the set
    // holds the owned particles only (what is written, what the time step and the function
    // objects read).
    if (decomposition_) owner_->clearGhosts();
    // last, on the moved and checked state: the next step's neighbours see the new particles
    if (management_ && (time().timeIndex() + 1) % managementInterval_ == 0) {
        const double before = budget_ ? ownedEnergy(owner_->ownedCount()) : 0.0;
        manageParticles();
        if (budget_) schemeDissipation_ -= ownedEnergy(owner_->ownedCount()) - before;
    }
}

// The Euler part (fpm/EulerPart.hpp) on the fit of this step: c from each particle's equation of
// state at (rho, e), checked (rho c^2 > 0, the bracket of Dp/Dt in the Euler part), the upwinded
// div v and grad p, then rho, v, p (and e) advanced together.
template <int Dim>
void FpmSolver<Dim>::eulerStage(double dt, double fraction) {
    auto timed = phase("euler");
    const std::size_t n = owner_->ownedCount();
    const std::vector<std::int64_t>& material = owner_->integerField("material");
    c_.resize(n);
    std::vector<double> c2(n), bracket(n);
    for (std::size_t i = 0; i < n; ++i) {
        const EquationOfState& eos = *(*materials_)[std::size_t(material[i])].eos;
        const double e = e_ ? (*e_)[i] : 0.0;
        // the bracket of (7.2), rho c_e^2 + g p / rho = rho times the isentropic c^2 of the EOS
        // (the thesis's "gains volume" where it is not positive, §4.7 setting 4)
        c2[i] = literalSoundSpeed_ ? eos.densityDerivative(rho_[i], e) : eos.soundSpeedSquared(rho_[i], e);
        bracket[i] = rho_[i] * c2[i] +
                     (literalSoundSpeed_ ? eos.energyDerivative(rho_[i], e) * (*p_)[i] / rho_[i] : 0.0);
        c_[i] = std::sqrt(std::max(c2[i], 0.0));
    }
    checkState(
        "euler", n, [&](std::size_t i) { return !(c2[i] > 0) || !(rho_[i] > 0) || !(bracket[i] > 0); },
        [&](std::size_t i, double count) {
            const std::string name = materials_->names()[std::size_t(material[i])];
            return "particle " + std::to_string(owner_->globalId()[i]) + " (material " + name +
                   "): the bracket rho c^2 + g p / rho of the pressure equation (doc/methods/fpm.md (7.2)) "
                   "or "
                   "the Euler part's c^2 is not positive (rho " +
                   formatKeywordNumber(rho_[i]) + ", p " + formatKeywordNumber((*p_)[i]) + ", c^2 " +
                   formatKeywordNumber(c2[i]) + " (" + (literalSoundSpeed_ ? "dp/drho|e" : "isentropic") +
                   "), bracket " + formatKeywordNumber(bracket[i]) + " from its equationOfState at e " +
                   formatKeywordNumber(e_ ? (*e_)[i] : 0.0) + "); " + std::to_string(long(count)) +
                   " particles affected: the body would gain volume without bound (the thesis's setting 4). "
                   "Remedy: an equationOfState with rho c^2 + g p / rho > 0 in this state (a larger c, a "
                   "smaller g, a positive outer pressure), or a smaller deltaT if the state ran away";
        });
    const std::vector<Vector<Dim>> gradP = fit_.gradientOf(*p_);
    // The shifted points' neighbours within h lie within (1 + maxShift) h of the particle: those
    // rows are searched only when some particle is shifted (a uniform p shifts none).
    bool anyShift = false;
    for (std::size_t i = 0; i < n && !anyShift; ++i)
        anyShift = eulerPart_->shifts(gradP[i].norm(), (*p_)[i], h_);
    anyShift = GlobalReduce::max(std::size_t(1), [&](std::size_t) { return anyShift ? 1.0 : 0.0; }) > 0;
    const NeighbourList& rows = anyShift ? shiftedRows() : rows_;
    eulerPart_->upwind(x_, rows, h_, *fitWeight_, rho_, *p_, v_, c_, gradP, gradV_);
    eulerPart_->advance(dt, rho_, v_, *p_, e_, c_);
    const auto& r = eulerPart_->result();
    if (divergence_.empty()) divergence_.assign(n, 0.0);
    for (std::size_t i = 0; i < n; ++i) divergence_[i] += fraction * r.divV[i];
    if (upwindMotion_)  // the Euler-only runs: v_uw
        for (std::size_t i = 0; i < n; ++i) motionVelocity_[i] += fraction * r.vUpwind[i];
    if (dimensionalMotion_)  // the coupled runs: the correction term only (§5.4)
        for (std::size_t i = 0; i < n; ++i) motionVelocity_[i] += fraction * r.vCorrect[i];
    flat_ += r.flat;
    tooFew_ += r.tooFew;
    eulerShortened_ += r.shortened;
    for (double l : r.shift) maxShift_ = std::max(maxShift_, l);
}

template <int Dim>
void FpmSolver<Dim>::readFreeSurface() {
    if (!settings_.given("freeSurface")) return;
    const KeywordValues& f = settings_.nested("freeSurface");
    typename SurfaceDetection<Dim>::Options o;
    o.normals = SurfaceDetection<Dim>::normalsNamed(f.word("normals"));
    o.offsetThreshold = f.scalar("offsetThreshold");
    o.scanLength = f.scalar("scanLength");
    surface_ = std::make_unique<SurfaceDetection<Dim>>(o);
    outerPressure_ = f.scalar("pressure");
    surfaceTraction_ = f.flag("traction");
    characteristicSurface_ = f.word("velocity") == "characteristic";
    totalStressSurface_ = f.word("condition") == "traction";
    edgeAngle_ = f.scalar("edgeAngle") * std::acos(-1.0) / 180.0;
    if (edgeAngle_ > 0 && !totalStressSurface_)
        throw settings_.dictionary("freeSurface")
            .error("edgeAngle",
                   "edgeAngle picks the particles that take the thesis's conditions under "
                   "condition traction (condition thesis applies them everywhere)");
    if (!euler_ && !shear_)
        throw properties_.error("freeSurface",
                                "freeSurface conditions act on p and S: subsystems with euler or shear");
    if (totalStressSurface_ && !(euler_ && shear_))
        throw settings_.dictionary("freeSurface")
            .error("condition",
                   "condition traction acts on the total stress S - p I: subsystems with both "
                   "shear and euler (or condition thesis)");
    if (totalStressSurface_ && !surfaceTraction_)
        throw settings_.dictionary("freeSurface")
            .error("traction",
                   "condition traction is the traction condition: traction yes (or condition thesis)");
}

// p = p_o and S n = 0 on the surface particles (fpm/FreeSurfaceCondition.hpp). After a part's stage,
// `velocity characteristic` keeps each particle's outgoing characteristic of that part; not at the
// step's start, where a particle may have just joined the surface with a state built inside.
template <int Dim>
void FpmSolver<Dim>::applyFreeSurface(std::optional<fpm::Subsystem> stage) {
    const std::size_t owned = owner_->ownedCount();  // the halo's particles are their owners'
    const auto& flag = surface_->surface();
    const auto& normal = surface_->normal();
    std::vector<double>& p = *p_;
    // Without a deviator (the Euler part alone) the conditions act on a zero one, per particle (a
    // scratch reset each call: a condition may write into it; its capacity is kept between steps).
    if (!S_) noStress_.assign(x_.size(), SymmTensor<Dim>{});
    std::vector<SymmTensor<Dim>>& S = S_ ? *S_ : noStress_;
    const bool projectStress = shear_ && surfaceTraction_;
    const bool eulerKick = characteristicSurface_ && stage == fpm::Subsystem::euler;
    const bool shearKick = characteristicSurface_ && stage == fpm::Subsystem::shear;
    if (totalStressSurface_) {
        // c of the last Euler stage (none before the first: the normal impedance is the shear part's)
        const bool kick = characteristicSurface_ && stage.has_value();
        const bool soundSpeed = c_.size() == owned;
        parallelFor(owned, [&](std::size_t i) {
            if (!flag[i] || (!edge_.empty() && edge_[i])) return;
            if (normal[i].squaredNorm() > 0)
                fpm::applySurfaceStress<Dim>(outerPressure_, normal[i], deviatorWeight_, mu_[i],
                                             soundSpeed ? c_[i] : 0.0, kick && !velocityHeld_[i], p[i], S[i],
                                             rho_[i], e_ ? &(*e_)[i] : nullptr, v_[i]);
            else
                p[i] = outerPressure_;  // no normal: the pressure condition alone
        });
        if (edge_.empty()) return;
    }
    // the thesis's pair (everywhere, or at the edges under condition traction)
    parallelFor(owned, [&](std::size_t i) {
        if (!flag[i] || (totalStressSurface_ && !edge_[i])) return;
        const bool oriented = normal[i].squaredNorm() > 0;
        fpm::applySurfacePressure<Dim>(outerPressure_, normal[i], eulerKick ? c_[i] : 0.0,
                                       eulerKick && oriented && !velocityHeld_[i], p[i], rho_[i],
                                       e_ ? &(*e_)[i] : nullptr, v_[i]);
        if (projectStress && oriented)
            fpm::applySurfaceTraction<Dim>(normal[i], mu_.empty() ? 0.0 : mu_[i], rho_[i],
                                           shearKick && !velocityHeld_[i], S[i], v_[i]);
    });
}

template <int Dim>
void FpmSolver<Dim>::readManagement() {
    if (!settings_.given("particleManagement")) return;
    const KeywordValues& k = settings_.nested("particleManagement");
    typename fpm::ParticleManagement<Dim>::Options o;
    o.insert = k.flag("insert");
    o.holeSize = k.scalar("holeSize");
    o.merge = k.flag("merge");
    o.mergeDistance = k.scalar("mergeDistance");
    o.surfaceOffset = k.scalar("surfaceOffset");
    managementInterval_ = long(k.integer("interval"));
    if (o.merge && o.mergeDistance >= o.holeSize)
        throw settings_.dictionary("particleManagement")
            .error("mergeDistance",
                   "mergeDistance must be below holeSize (a merged pair would leave a hole)");
    if (!o.insert && !o.merge) return;
    management_ = std::make_unique<fpm::ParticleManagement<Dim>>(o);
    Log::info("fpmSolid: particle management every " + std::to_string(managementInterval_) + " step(s): " +
              (o.insert ? "insertion where no particle lies within " + formatKeywordNumber(o.holeSize) +
                              " h of a point inside the body (centre-of-mass offset <= " +
                              formatKeywordNumber(o.surfaceOffset) + ")"
                        : std::string("no insertion")) +
              "; " +
              (o.merge ? "merging of pairs closer than " + formatKeywordNumber(o.mergeDistance) + " h"
                       : std::string("no merging")));
}

// The particles whose velocity a boundary condition sets (any component): those the constraint
// changes on a probe velocity no condition leaves alone. On them the free surface's characteristic
// velocity and its entropy wave are not applied (the condition, not the surface, sets v there).
template <int Dim>
void FpmSolver<Dim>::markVelocityHeld(double t) {
    velocityHeld_.assign(x_.size(), 0);
    if (boundaryConditions_.empty() || !characteristicSurface_) return;
    Vector<Dim> probe;
    const double components[3] = {1.0e10, 1.4142135623730951e10, 3.141592653589793e10};
    for (int d = 0; d < Dim; ++d) probe(d) = components[d];
    std::vector<Vector<Dim>> v(x_.size(), probe);
    boundaryConditions_.constrainVelocity(*owner_, v, t);
    for (std::size_t i = 0; i < v.size(); ++i) velocityHeld_[i] = v[i] != probe;
}

// Merging and insertion (fpm/ParticleManagement.hpp) on the moved particles; the solver's own
// per-particle arrays follow: a merged pair keeps its survivor's, an inserted particle starts its
// state-change measure from its inserted state and takes its material's mu and c.
template <int Dim>
void FpmSolver<Dim>::manageParticles() {
    if constexpr (Dim > 1) {
        auto timed = phase("particleManagement");
        // Several ranks: the merging and the insertion are sweeps in global-id order whose every
        // decision depends on the ones before (a particle merged, a hole filled), across the cuts:
        // they run on the whole set, gathered on every rank in id order (the serial run's order),
        // so that every rank makes the serial decisions and issues the serial ids; then the set is
        // cut again. Exact but not scalable (every rank holds the whole set at a management step).
        if (decomposition_) gatherWholeSet();
        const std::vector<std::int64_t> origin = management_->apply(*owner_, h_, *fitWeight_);
        const auto& last = management_->last();
        if (last.inserted == 0 && last.merged == 0) {
            if (decomposition_) redistribute();
            return;
        }
        const std::size_t n = x_.size();
        const std::vector<std::int64_t>* material = owner_->template findField<std::int64_t>("material");
        const auto remap = [&](auto& values, auto fresh) {
            if (values.empty()) return;
            std::remove_reference_t<decltype(values)> next(n);
            for (std::size_t i = 0; i < n; ++i)
                next[i] = origin[i] >= 0 ? values[std::size_t(origin[i])] : fresh(i);
            values.swap(next);
        };
        remap(rhoStart_, [&](std::size_t i) { return rho_[i]; });
        remap(pStart_, [&](std::size_t i) { return (*p_)[i]; });
        remap(vStart_, [&](std::size_t i) { return v_[i]; });
        remap(radius0_, [&](std::size_t i) { return (x_[i] - centre_).norm(); });
        remap(mu_, [&](std::size_t i) {
            const auto* strength = (*materials_)[std::size_t((*material)[i])].strength.get();
            return strength ? strength->shearModulus() : 0.0;
        });
        remap(c_, [&](std::size_t i) {
            const EquationOfState* eos = (*materials_)[std::size_t((*material)[i])].eos.get();
            return eos ? std::sqrt(std::max(eos->soundSpeedSquared(rho_[i], e_ ? (*e_)[i] : 0.0), 0.0)) : 0.0;
        });
        // The conditions' selections index the particles: the merged ones are gone and the
        // inserted ones are judged by the criteria (a particle inserted at a slip wall slides).
        if (decomposition_)
            redistribute();  // updates them on the new cut
        else
            boundaryConditions_.updateSelections(*owner_);
    }
}

// Several ranks: every rank's particles, every field and the solver's arrays, on every rank in
// global-id order, and the next id the largest of the ranks' (above every id any rank issued or
// held, as one process's). Each field travels as its 8-byte words (every element type is made of
// doubles or 64-bit integers), concatenated in rank order.
template <int Dim>
void FpmSolver<Dim>::gatherWholeSet() {
    carrySolverArrays(true);
    const std::size_t n = owner_->ownedCount();
    std::vector<std::string> names;
    for (const auto& f : owner_->fields()) names.push_back(f->name());
    std::sort(names.begin(), names.end());  // the same order on every rank
    std::vector<std::vector<std::int64_t>> whole;
    for (const std::string& name : names) {
        const FieldBase& f = owner_->field(name);
        if (f.elementBytes() % sizeof(std::int64_t) != 0)
            throw Error("fpmSolid: field '" + name + "' is not made of 8-byte values; it cannot be gathered");
        std::vector<std::int64_t> words(n * f.elementBytes() / sizeof(std::int64_t));
        if (!words.empty()) std::memcpy(words.data(), f.data(), words.size() * sizeof(std::int64_t));
        whole.push_back(globalConcatenation(words));
    }
    const std::int64_t next = std::int64_t(globalMax(double(owner_->nextGlobalId())));
    const std::size_t total = std::size_t(globalSum(double(n)));
    owner_->appendMigrated(total - n);
    for (std::size_t k = 0; k < names.size(); ++k) {
        FieldBase& f = owner_->field(names[k]);
        if (!whole[k].empty()) std::memcpy(f.data(), whole[k].data(), whole[k].size() * sizeof(std::int64_t));
    }
    const std::vector<std::int64_t>& id = owner_->globalId();
    std::vector<std::size_t> order(total);
    std::iota(order.begin(), order.end(), std::size_t(0));
    std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return id[a] < id[b]; });
    owner_->reorder(order);
    owner_->reserveGlobalIdsBelow(next);
    carrySolverArrays(false);
    if (shear_) assignShearModuli();  // the whole set's, for the remap of the new particles
}

// Several ranks, after a management step on the whole set: each rank keeps its share of a new cut,
// and the halo is planned again at the next step's start.
template <int Dim>
void FpmSolver<Dim>::redistribute() {
    carrySolverArrays(true);
    decomposition_->distribute(*owner_, "fpmSolid's particle management");
    carrySolverArrays(false);
    if (shear_) assignShearModuli();
    xAtMigration_.clear();  // a migration (none moves) and a new halo plan at the next step
    boundaryConditions_.updateSelections(*owner_);
}

// The reach of rows_, in h: growSupport refits within them up to its largest support.
template <int Dim>
double FpmSolver<Dim>::centralReach() const {
    return fit_.options().fallback == LeastSquaresOperators<Dim>::Fallback::growSupport
               ? fit_.options().maxSupportGrowth
               : 1.0;
}

// The reach of the shifted fits' rows, in h: the largest shift of the parts that run, plus h.
template <int Dim>
double FpmSolver<Dim>::shiftedReach() const {
    double reach = 1.0;
    if (eulerPart_) reach = std::max(reach, 1.0 + eulerPart_->options().maxShift);
    if (shearPart_) reach = std::max(reach, 1.0 + shearPart_->options().maxShift);
    return reach;
}

// The rows of the owned particles within `radius` (self included), in the order that gives the
// fits' sums their serial bits: by index on one rank (the particle file's order, the global ids'),
// by global id on several (whose numbering of owned and halo particles differs). The halo's own
// rows are dropped: a halo particle is read, never fitted (its rows would be cut by the halo's edge).
template <int Dim>
NeighbourList FpmSolver<Dim>::rowsWithin(double radius) {
    NeighbourList all = search_.build(x_, radius);
    if (!decomposition_) return all;
    const std::size_t n = owner_->ownedCount();
    std::vector<std::size_t> offsets(all.offsets().begin(), all.offsets().begin() + std::ptrdiff_t(n + 1));
    std::vector<NeighbourList::Index> indices(all.indices().begin(),
                                              all.indices().begin() + std::ptrdiff_t(offsets[n]));
    NeighbourList rows(std::move(offsets), std::move(indices));
    rows.sortRowsBy(owner_->globalId().data());
    return rows;
}

// Several ranks: the fields the fits read of a neighbour (haloFields_), refreshed in the halo
// after a stage or a surface condition changed them on their owners. Nothing on one rank.
template <int Dim>
void FpmSolver<Dim>::refreshHalo() {
    if (!decomposition_) return;
    owner_->copyToGhosts(v_);
    owner_->copyToGhosts(*p_);
    if (S_) owner_->copyToGhosts(*S_);
}

// The solver's per-particle arrays that outlive a step, as temporary fields of the set (toFields)
// or back (and the fields removed): what carries them through a migration or a gather. Collective.
template <int Dim>
void FpmSolver<Dim>::carrySolverArrays(bool toFields) {
    const auto carry = [&](const char* name, auto& values) {
        using T = typename std::remove_reference_t<decltype(values)>::value_type;
        if (!toFields) {
            if (auto* f = owner_->template findField<T>(name)) {
                values = *f;
                owner_->removeField(name);
            }
            return;
        }
        // decided alike on every rank (the set's fields must agree), from the ranks that have any
        const bool carried =
            GlobalReduce::max(std::size_t(1), [&](std::size_t) { return values.empty() ? 0.0 : 1.0; }) > 0;
        if (!carried) return;
        std::vector<T>& field = owner_->template field<T>(name);
        if (values.size() == field.size()) field = values;
    };
    carry("fpmStartDensity", rhoStart_);
    carry("fpmStartPressure", pStart_);
    carry("fpmStartVelocity", vStart_);
    carry("fpmStartRadius", radius0_);
    carry("fpmSoundSpeed", c_);
}

// Several ranks (issue 21). The halo is planned with width w = R + skin around each rank's part,
// R the widest rows' reach (h, 2 h under growSupport, (1 + maxShift) h for the shifted fits; h is
// constant) and the skin half an h: a pair within R of particles that moved d_i and d_j since is
// covered while R + d_i + d_j <= w, so the particles migrate to their owners (and the halo is
// planned again) when 2 max d + R > w, tested at the start of a step (the particles move at its
// end, after every fit). After a migration the owned particles are in global-id order and the
// halo in rank order (Decomposition.hpp); rowsWithin orders each row by global id, so every fit
// sums its row in the serial order and the state has the serial bits on any number of ranks.
// The solver's own per-particle arrays that outlive a step (the state-change measure's start
// values, the rotation reference's radii, c of the last Euler stage) travel with their particles
// as temporary fields; mu is assigned again from the materials.
template <int Dim>
void FpmSolver<Dim>::updateDecomposition() {
    auto timed = phase("neighbours");
    const std::size_t n = owner_->ownedCount();
    const double reach = std::max(centralReach(), shiftedReach()) * h_;
    const double skin = 0.5 * h_;
    bool due = xAtMigration_.size() != n || haloWidth_ == 0;
    if (!due) {
        const double dMax =
            GlobalReduce::max(n, [&](std::size_t i) { return (x_[i] - xAtMigration_[i]).norm(); });
        due = 2 * dMax + reach > haloWidth_;
    }
    due = GlobalReduce::max(std::size_t(1), [&](std::size_t) { return due ? 1.0 : 0.0; }) > 0;
    if (!due) return;
    const bool first = haloWidth_ == 0;
    const int rebalancesBefore = decomposition_->rebalances();
    carrySolverArrays(true);
    decomposition_->migrate(*owner_, {});
    carrySolverArrays(false);
    if (shear_) assignShearModuli();
    haloWidth_ = reach + skin;
    decomposition_->planHalo(*owner_, haloWidth_);
    boundaryConditions_.updateSelections(*owner_);
    xAtMigration_.assign(x_.begin(), x_.begin() + std::ptrdiff_t(owner_->ownedCount()));
    if (first || decomposition_->rebalances() != rebalancesBefore)
        Log::info(decomposition_->report(*owner_, {}));
}

template <int Dim>
const NeighbourList& FpmSolver<Dim>::shiftedRows() {
    const double central = centralReach();  // the reach of rows_, in h
    const double reach = shiftedReach();
    if (reach <= central) return rows_;
    if (!wideBuilt_) wideRows_ = rowsWithin(reach * h_);
    wideBuilt_ = true;
    return wideRows_;
}

// The shear part (fpm/ShearPart.hpp) on this step's fit: mu per particle (its strength law), g =
// dp/de|rho from its equation of state at (rho, e) (0 without one), the dimensionally upwinded
// grad v_D and div S_D, then v, p, S (and e) advanced together, and where a strength law yields,
// S returned to its yield surface.
template <int Dim>
void FpmSolver<Dim>::shearStage(double dt, double fraction) {
    auto timed = phase("shear");
    const std::size_t n = owner_->ownedCount();
    const std::vector<std::int64_t>& material = owner_->integerField("material");
    g_.assign(n, 0.0);
    for (std::size_t i = 0; i < n; ++i) {
        const EquationOfState* eos = (*materials_)[std::size_t(material[i])].eos.get();
        if (eos) g_[i] = eos->energyDerivative(rho_[i], e_ ? (*e_)[i] : 0.0);
    }
    if (!euler_) {
        // The shear part alone: its pressure equation's bracket is g p / rho (the rho c^2 part is
        // the Euler part's; Remark 7.1: an outer pressure p_o = 10 keeps it positive).
        checkState(
            "shear", n, [&](std::size_t i) { return g_[i] != 0 && !(g_[i] * (*p_)[i] / rho_[i] > 0); },
            [&](std::size_t i, double count) {
                return "particle " + std::to_string(owner_->globalId()[i]) + " (material " +
                       materials_->names()[std::size_t(material[i])] +
                       "): the bracket g p / rho of the shear part's pressure equation is not positive (g " +
                       formatKeywordNumber(g_[i]) + ", p " + formatKeywordNumber((*p_)[i]) + ", rho " +
                       formatKeywordNumber(rho_[i]) + "); " + std::to_string(long(count)) +
                       " particles affected: the body would gain volume without bound. Remedy: a positive "
                       "outer pressure (the thesis's p_o = 10 for the shear part alone, Remark 7.1), g = 0, "
                       "or subsystems with euler";
            });
    }
    const std::vector<Vector<Dim>> divS = fpm::ShearPart<Dim>::divergence(fit_, *S_);
    shearPart_->upwind(x_, shiftedRows(), h_, *fitWeight_, rho_, v_, *S_, mu_, gradV_, divS);
    shearPart_->advance(dt, rho_, v_, *p_, *S_, e_, g_, mu_, deviatorWeight_);
    const auto& r = shearPart_->result();
    if (plastic_) {
        // the return to each particle's yield surface (the thesis's named future work; the
        // strength family's radial return for vonMises)
        std::vector<SymmTensor<Dim>>& S = *S_;
        parallelFor(n, [&](std::size_t i) {
            const auto* strength = (*materials_)[std::size_t(material[i])].strength.get();
            if (!strength) return;
            typename Strength<Dim>::Fields f;
            f.size = 1;
            f.velocityGradient = &r.gradV[i];
            f.density = &rho_[i];
            f.tau = &S[i];
            f.plasticStrain = &(*plasticStrain_)[i];
            strength->returnToYieldSurface(f, dt);
        });
    }
    if (dimensionalMotion_)
        for (std::size_t i = 0; i < n; ++i) motionVelocity_[i] += fraction * r.vD[i];
    shearTooFew_ += r.tooFew;
    unstrained_ += r.unstrained;
    shortened_ += r.shortened;
    for (double l : r.shift) maxShearShift_ = std::max(maxShearShift_, l);
}

template <int Dim>
void FpmSolver<Dim>::rotationStage(double dt) {
    auto timed = phase("rotation");
    std::vector<SymmTensor<Dim>>& S = *S_;
    parallelFor(gradV_.size(),  // the owned particles
                [&](std::size_t i) { S[i] = fpm::rotated(S[i], fpm::spinExponential<Dim>(gradV_[i], dt)); });
}

// reference { type linearFlow; }: the ODE of the uniform state (fpm/LinearFlowReference.hpp) from
// this run's start, with the initial state's gradient A, the particles' (uniform) state, their
// material's equation of state and shear modulus, and the parts that run.
template <int Dim>
void FpmSolver<Dim>::readFlowReference() {
    const Dictionary& dict = settings_.dictionary("reference");
    const std::string type = dict.get<std::string>("type");
    if (type != "linearFlow")
        throw dict.error("type", "unknown reference type '" + type + "'; valid choices: linearFlow");
    const auto state = settings_.given("initialState")
                           ? InitialState<Dim>::New(settings_.dictionary("initialState"))
                           : nullptr;
    const auto* linear = dynamic_cast<const LinearVelocity<Dim>*>(state.get());
    if (!linear)
        throw dict.error("type",
                         "reference linearFlow needs initialState { type linearVelocity; gradient (...); }");
    if (prescribed_)
        throw dict.error("type",
                         "reference linearFlow is for frozen or moving particles, not a prescribed motion");
    const Tensor<Dim> A = linear->gradient();
    const std::size_t n = x_.size();
    fpm::UniformState<Dim> start;
    if (n > 0) {
        start.rho = rho_[0];
        start.p = (*p_)[0];
        start.e = e_ ? (*e_)[0] : 0.0;
        start.S = stressOf(0);
    }
    const std::vector<std::int64_t>* material = owner_->template findField<std::int64_t>("material");
    for (std::size_t i = 0; i < n; ++i) {
        double spread = std::abs(rho_[i] - start.rho) + std::abs((*p_)[i] - start.p) +
                        std::abs((e_ ? (*e_)[i] : 0.0) - start.e);
        for (int k = 0; k < SymmTensor<Dim>::size; ++k)
            spread += std::abs(stressOf(i).c[std::size_t(k)] - start.S.c[std::size_t(k)]);
        if (spread > 1e-12 * (1 + std::abs(start.rho) + std::abs(start.p) + std::abs(start.e)) ||
            (material && (*material)[i] != (*material)[0]))
            throw dict.error("type",
                             "reference linearFlow needs one material and a uniform rho, p, e and S at the "
                             "start; particle " +
                                 std::to_string(owner_->globalId()[i]) + " differs from particle " +
                                 std::to_string(owner_->globalId()[0]));
    }
    const EquationOfState* eos = nullptr;
    if (materials_ && material && n > 0) eos = (*materials_)[std::size_t((*material)[0])].eos.get();
    typename fpm::LinearFlowReference<Dim>::Parts parts;
    parts.euler = euler_;
    parts.shear = shear_;
    parts.rotation = rotation_;
    parts.literal = literalSoundSpeed_;
    flowReference_ = std::make_unique<fpm::LinearFlowReference<Dim>>(
        A, upwindMotion_ || dimensionalMotion_, parts, eos, shear_ && n > 0 ? mu_[0] : 0.0, deviatorWeight_,
        start);
    flowState_ = start;
    flowTime_ = time().value();
    if (flowTime_ != 0)
        Log::info("fpmSolid: reference linearFlow from this run's start at t = " +
                  formatKeywordNumber(flowTime_) + " with the gradient of t = 0 carried to it");
}

template <int Dim>
typename FpmSolver<Dim>::FlowError FpmSolver<Dim>::flowRunRelative() const {
    const auto ratio = [](double e, double x) { return x > 0 ? e / x : 0.0; };
    return {ratio(worstFlowError_.rho, largestExact_.rho), ratio(worstFlowError_.p, largestExact_.p),
            ratio(worstFlowError_.S, largestExact_.S)};
}

template <int Dim>
void FpmSolver<Dim>::measureFlowError(double t) {
    flowState_ = flowReference_->advanced(flowState_, flowTime_, t);
    flowTime_ = t;
    const fpm::UniformState<Dim>& ex = flowState_;
    const std::size_t n = owner_->ownedCount();
    FlowError a;
    a.rho = GlobalReduce::max(n, [&](std::size_t i) { return std::abs(rho_[i] - ex.rho); });
    a.p = GlobalReduce::max(n, [&](std::size_t i) { return std::abs((*p_)[i] - ex.p); });
    a.S = GlobalReduce::max(n, [&](std::size_t i) {
        double e = 0;
        for (int k = 0; k < SymmTensor<Dim>::size; ++k)
            e = std::max(e, std::abs(stressOf(i).c[std::size_t(k)] - ex.S.c[std::size_t(k)]));
        return e;
    });
    double sScale = 0;
    for (double c : ex.S.c) sScale = std::max(sScale, std::abs(c));
    flowError_ = a;
    flowRelative_.rho = a.rho / std::abs(ex.rho);
    flowRelative_.p = std::abs(ex.p) > 0 ? a.p / std::abs(ex.p) : 0.0;
    flowRelative_.S = sScale > 0 ? a.S / sScale : 0.0;
    worstFlowError_.rho = std::max(worstFlowError_.rho, a.rho);
    worstFlowError_.p = std::max(worstFlowError_.p, a.p);
    worstFlowError_.S = std::max(worstFlowError_.S, a.S);
    largestExact_.rho = std::max(largestExact_.rho, std::abs(ex.rho));
    largestExact_.p = std::max(largestExact_.p, std::abs(ex.p));
    largestExact_.S = std::max(largestExact_.S, sScale);
}

// After the step, at t + dt: the exact stress of the particle now at x is Q(t + dt) S0(X) Q^T with
// X = c + Q^T (x - c) its start position (the motion is the exact rotation by Q). Global maxima:
// every rank reports the same figures.
template <int Dim>
void FpmSolver<Dim>::measureRotationError(double t) {
    const std::size_t n = owner_->ownedCount();
    const Tensor<3> Q3 = fpm::axisRotation(axis_, omega_, t);
    const Tensor<Dim> Q = Q3.template topLeftCorner<Dim, Dim>();
    const std::vector<SymmTensor<Dim>>& S = *S_;
    RotationError r;
    r.stress = GlobalReduce::max(n, [&](std::size_t i) {
        const SymmTensor<Dim> exact =
            fpm::rotated(initialStressAt(centre_ + Q.transpose() * (x_[i] - centre_)), Q);
        double e = 0;
        for (int k = 0; k < SymmTensor<Dim>::size; ++k) e = std::max(e, std::abs(S[i].c[k] - exact.c[k]));
        return e;
    });
    r.zeroStress = GlobalReduce::max(n, [&](std::size_t i) {
        const SymmTensor<Dim> S0 = initialStressAt(centre_ + Q.transpose() * (x_[i] - centre_));
        double e = 0;
        for (int k = 0; k < SymmTensor<Dim>::size; ++k) {
            if (S0.c[k] != 0) return 0.0;
            e = std::max(e, std::abs(S[i].c[k]));
        }
        return e;
    });
    r.radius =
        GlobalReduce::max(n, [&](std::size_t i) { return std::abs((x_[i] - centre_).norm() - radius0_[i]); });
    last_ = r;
    worst_.stress = std::max(worst_.stress, r.stress);
    worst_.radius = std::max(worst_.radius, r.radius);
    worst_.zeroStress = std::max(worst_.zeroStress, r.zeroStress);
}

template <int Dim>
double FpmSolver<Dim>::internalEnergyOf(std::size_t i, const std::vector<double>& m) const {
    if (e_) return m[i] * (*e_)[i];
    double u = 0;
    if (shear_ && mu_[i] > 0) {
        const Tensor<Dim> S = (*S_)[i].full();
        u += (S.array() * S.array()).sum() / (4.0 * mu_[i]);
    }
    const double K = c_.size() > i ? rho_[i] * c_[i] * c_[i] : 0.0;
    if (K > 0) u += (*p_)[i] * (*p_)[i] / (2.0 * K);
    return (*V_)[i] * u;
}

template <int Dim>
std::optional<double> FpmSolver<Dim>::internalEnergy() const {
    if (!euler_ && !shear_) return std::nullopt;
    const std::vector<double>& m = owner_->scalarField("mass");
    return GlobalReduce::sum<double>(x_.size(), [&](std::size_t i) { return internalEnergyOf(i, m); });
}

// The energy budget. K + U (U as internalEnergy() says) changes in a step by
//   - each stage's advance (forward Euler on its rates r = (a, dp/dt, dS/dt, de/dt) at the stage's
//     start state y0): the integrator's own quadrature of the stage's power is the left point,
//     dt P(y0) = sum_i [m v0 . dv + V (p0 dp / K + S0 : dS / (2 mu))] (or m de where e is evolved),
//     dv, dp, dS, de the stage's changes (the plastic return's within the shear stage's dS). The
//     semi-discrete scheme's loss -dt P is D: the upwinding's dissipation and the central
//     operators' error together (they are not skew-adjoint, so no pair form separates them);
//   - the free surface's resets (p = p_o, S n = 0, the characteristic velocity): their change of
//     K + U is the condition's own loss, in D; with p_o != 0 the outer pressure's work on the body,
//     -p_o sum_i dV_i at the volume update, is in W;
//   - the velocity conditions (and a prescribed motion): their change of K is in W;
//   - particle management's merging and insertion: their change of K + U is in D.
// What is left in the imbalance: the forward Euler stages' own gain, exactly
// sum_i [m |dv|^2 / 2 + V (dp^2 / (2K) + dS : dS / (4 mu))] per stage where K, V and mu hold (first
// order in dt over a run), and the linearised elastic energy's own mismatch (U is not an invariant
// of the hypo-elastic model: V's update, K = rho c^2 following rho, O(strain) of U).
template <int Dim>
double FpmSolver<Dim>::ownedKinetic(std::size_t n) const {
    const std::vector<double>& m = owner_->scalarField("mass");
    return GlobalReduce::sum<double>(n, [&](std::size_t i) { return 0.5 * m[i] * v_[i].squaredNorm(); });
}

template <int Dim>
double FpmSolver<Dim>::ownedEnergy(std::size_t n) const {
    const std::vector<double>& m = owner_->scalarField("mass");
    return GlobalReduce::sum<double>(
        n, [&](std::size_t i) { return 0.5 * m[i] * v_[i].squaredNorm() + internalEnergyOf(i, m); });
}

template <int Dim>
void FpmSolver<Dim>::rememberStageStart(std::size_t n) {
    stageStart_.v.assign(v_.begin(), v_.begin() + std::ptrdiff_t(n));
    stageStart_.rho.assign(rho_.begin(), rho_.begin() + std::ptrdiff_t(n));
    stageStart_.p.assign(p_->begin(), p_->begin() + std::ptrdiff_t(n));
    if (e_) stageStart_.e.assign(e_->begin(), e_->begin() + std::ptrdiff_t(n));
    if (S_) stageStart_.S.assign(S_->begin(), S_->begin() + std::ptrdiff_t(n));
}

template <int Dim>
double FpmSolver<Dim>::stageStartPower(std::size_t n) const {
    const std::vector<double>& m = owner_->scalarField("mass");
    const StageStart& s = stageStart_;
    return GlobalReduce::sum<double>(n, [&](std::size_t i) {
        double power = m[i] * s.v[i].dot(v_[i] - s.v[i]);
        if (e_) return power + m[i] * ((*e_)[i] - s.e[i]);
        double u = 0;
        if (shear_ && mu_[i] > 0) {
            const Tensor<Dim> S0 = s.S[i].full(), dS = (*S_)[i].full() - S0;
            u += (S0.array() * dS.array()).sum() / (2.0 * mu_[i]);
        }
        const double K = c_.size() > i ? s.rho[i] * c_[i] * c_[i] : 0.0;
        if (K > 0) u += s.p[i] * ((*p_)[i] - s.p[i]) / K;
        return power + (*V_)[i] * u;
    });
}

template <int Dim>
std::optional<double> FpmSolver<Dim>::schemeDissipation() const {
    if (!budget_) return std::nullopt;
    return schemeDissipation_;
}

template <int Dim>
std::optional<double> FpmSolver<Dim>::externalWork() const {
    if (!budget_) return std::nullopt;
    return externalWork_;
}

template <int Dim>
std::vector<HealthIndicator> FpmSolver<Dim>::healthIndicators() const {
    // The fit the next step makes (the particles where they are now, the rows within h): per
    // particle the neighbours of positive fit weight (self included: the value form fits the
    // point's own value) and the reciprocal condition number lambda_min / lambda_max of its moment
    // matrix M = sum_b w_b p_b p_b^T (weights normalised, basis p of scaled offsets s = (x_b -
    // x_a) / h, the Tikhonov shift as the fit applies it: LeastSquaresOperators.cpp, fitPoint).
    // The thresholds are the fit's own: fewer than max(basis size, 2(d + 1)) neighbours (the
    // note's minimum, §2) or lambda_min / lambda_max below minReciprocalCondition fail the fit at
    // h: the step then stops, or falls back (fitFallback: a grown support, or Shepard's order 0,
    // which loses the gradient's consistency). Computed at the health check's writes only.
    HealthIndicator neighbours{
        "neighbourDeficiency", 0.0, 0, -1,
        "smallest count of neighbours of positive fit weight within h (self "
        "included); counted: particles below the fit's minimum max(basis size, 2(d + 1))"};
    HealthIndicator conditioning{
        "fitConditioning", 0.0, 0, -1,
        "smallest reciprocal condition number lambda_min / lambda_max of the fit's "
        "moment matrix at h; counted: particles below the fit's minReciprocalCondition "
        "(there the fit fails or falls back)"};
    const std::size_t n = ownedParticles();
    const auto& options = fit_.options();
    const int m = fit_.basisSize();
    const int minimum = std::max(m, options.minNeighbours);
    NeighbourSearch<Dim> search(NeighbourDomain<Dim>{}, searchOptions());
    // Several ranks: the particles near a cut count their neighbours on the other side too (the
    // halo's positions, appended for the count and removed again; the set is the owner's).
    if (decomposition_) decomposition_->appendHalo(*owner_, {"position"});
    const NeighbourList rows = search.build(x_, h_);
    if (decomposition_) owner_->clearGhosts();
    std::vector<double> count(n, 0.0), reciprocal(n, 0.0);
    parallelFor(n, [&](std::size_t a) {
        Eigen::MatrixXd M = Eigen::MatrixXd::Zero(m, m);
        Eigen::VectorXd p(m);
        double sum = 0;
        int used = 0;
        for (std::size_t k = rows.offsets()[a]; k < rows.offsets()[a + 1]; ++k) {
            const std::size_t b = rows.indices()[k];
            const double w = fitWeight_->fitWeight((x_[b] - x_[a]).norm(), h_);
            if (!(w > 0)) continue;
            ++used;
            sum += w;
            const Vector<Dim> s = (x_[b] - x_[a]) / h_;
            int j = 0;
            p(j++) = 1.0;
            for (int d = 0; d < Dim; ++d) p(j++) = s(d);
            if (options.order == 2) {
                for (int d = 0; d < Dim; ++d) p(j++) = 0.5 * s(d) * s(d);
                for (int d = 0; d < Dim; ++d)
                    for (int e = d + 1; e < Dim; ++e) p(j++) = s(d) * s(e);
            }
            M.noalias() += w * p * p.transpose();
        }
        count[a] = used;
        if (used < m || !(sum > 0)) return;  // M is singular: reciprocal condition 0
        M /= sum;
        if (options.tikhonov > 0) M.diagonal().array() += options.tikhonov * M.trace();
        const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eigen(M, Eigen::EigenvaluesOnly);
        const auto& lambda = eigen.eigenvalues();
        if (eigen.info() == Eigen::Success && lambda(m - 1) > 0)
            reciprocal[a] = std::max(lambda(0), 0.0) / lambda(m - 1);
    });
    const std::vector<std::int64_t>& id = owner_->globalId();
    // The worst particle: the lowest global id at the worst value, over every rank.
    auto fill = [&](HealthIndicator& indicator, const std::vector<double>& value, double threshold) {
        indicator.value = GlobalReduce::min(n, [&](std::size_t i) { return value[i]; });
        indicator.count = std::size_t(
            GlobalReduce::sum<double>(n, [&](std::size_t i) { return value[i] < threshold ? 1.0 : 0.0; }));
        double first = std::numeric_limits<double>::infinity();
        for (std::size_t i = 0; i < n; ++i)
            if (value[i] <= indicator.value) first = std::min(first, double(id[i]));
        first = globalMin(first);
        if (std::isfinite(first)) indicator.worst = std::int64_t(first);
    };
    fill(neighbours, count, double(minimum));
    fill(conditioning, reciprocal, options.minReciprocalCondition);
    return {neighbours, conditioning};
}

template <int Dim>
std::vector<ExtraFile> FpmSolver<Dim>::extraOutput() const {
    std::vector<ExtraFile> files;
    if (euler_ || shear_) {
        char text[512];
        std::snprintf(text, sizeof text,
                      "// the change from this run's start (the frozen Euler validation, doc/methods/fpm.md "
                      "§4.4: 0): this time, and the largest over the run\n"
                      "maxDensityChange %.6e;\nmaxPressureChange %.6e;\nmaxVelocityChange %.6e;\n"
                      "runMaxDensityChange %.6e;\nrunMaxPressureChange %.6e;\nrunMaxVelocityChange %.6e;\n",
                      lastChange_.rho, lastChange_.p, lastChange_.v, worstChange_.rho, worstChange_.p,
                      worstChange_.v);
        files.push_back({"stateChange", text});
    }
    if (flowReference_) {
        const FlowError runRelative = flowRunRelative();
        const fpm::UniformState<Dim>& ex = flowState_;
        std::string text =
            "// the exact uniform state of the linear flow (doc/methods/fpm.md §4.4, §4.6, §4.10; "
            "fpm/LinearFlowReference.hpp) at this time, the largest differences over the particles, and "
            "the relative ones (to |rho|, |p|, max |S_k| exact; 0 where the exact is 0); runMax: the largest "
            "difference over the run over the largest |exact| of the run\n";
        char line[160];
        std::snprintf(line, sizeof line, "exactDensity %.12e;\nexactPressure %.12e;\n", ex.rho, ex.p);
        text += line;
        text += "exactStress (";
        for (int k = 0; k < SymmTensor<Dim>::size; ++k) {
            std::snprintf(line, sizeof line, "%s%.12e", k ? " " : "", ex.S.c[std::size_t(k)]);
            text += line;
        }
        text += ");\n";
        std::snprintf(line, sizeof line, "densityError %.6e;\npressureError %.6e;\nstressError %.6e;\n",
                      flowError_.rho, flowError_.p, flowError_.S);
        text += line;
        std::snprintf(line, sizeof line,
                      "relativeDensityError %.6e;\nrelativePressureError %.6e;\nrelativeStressError %.6e;\n",
                      flowRelative_.rho, flowRelative_.p, flowRelative_.S);
        text += line;
        std::snprintf(line, sizeof line,
                      "runMaxRelativeDensityError %.6e;\nrunMaxRelativePressureError %.6e;\n"
                      "runMaxRelativeStressError %.6e;\n",
                      runRelative.rho, runRelative.p, runRelative.S);
        text += line;
        files.push_back({"referenceError", text});
    }
    if (!reference_) return files;
    char text[512];
    std::snprintf(
        text, sizeof text,
        "// the rotation-only reference (doc/methods/fpm.md §4.9): this time, and the largest over the run\n"
        "maxStressError %.6e;\nmaxRadiusChange %.6e;\nmaxZeroStress %.6e;\n"
        "runMaxStressError %.6e;\nrunMaxRadiusChange %.6e;\nrunMaxZeroStress %.6e;\n",
        last_.stress, last_.radius, last_.zeroStress, worst_.stress, worst_.radius, worst_.zeroStress);
    files.push_back({"rotationError", text});
    return files;
}

template <int Dim>
std::vector<std::string> FpmSolver<Dim>::summary(double) const {
    std::vector<std::string> lines;
    char line[256];
    // The counters are per rank: summed (the largest shifts: the largest) over the ranks, so that
    // the summary is the run's, as one process would give it.
    SumArray<12> local;
    local.s = {double(grown_),         double(shepard_),        double(flat_),
               double(tooFew_),        double(eulerShortened_), double(shearTooFew_),
               double(unstrained_),    double(shortened_),      double(surfaceParticles_),
               double(edgeParticles_), double(x_.size()),       0.0};
    const SumArray<12> total = globalSum(local);
    const auto count = [&](int k) { return std::size_t(total.s[std::size_t(k)]); };
    const std::size_t grown_ = count(0), shepard_ = count(1), flat_ = count(2), tooFew_ = count(3),
                      eulerShortened_ = count(4), shearTooFew_ = count(5), unstrained_ = count(6),
                      shortened_ = count(7), surfaceParticles_ = count(8), edgeParticles_ = count(9),
                      particles = count(10);
    const double maxShift_ = globalMax(this->maxShift_), maxShearShift_ = globalMax(this->maxShearShift_);
    std::snprintf(
        line, sizeof line,
        "fit                  %.1f neighbours per particle (rows), fallbacks: %zu grown supports, %zu "
        "Shepard fits (particle-steps)",
        neighboursPerParticle_, grown_, shepard_);
    lines.push_back(line);
    if (euler_) {
        std::snprintf(
            line, sizeof line,
            "euler                central evaluations (particle-steps): %zu with |grad p| ~ 0, %zu "
            "with a shifted fit short of neighbours; %zu with a shortened shift; largest shift %.4g (h %.4g)",
            flat_, tooFew_, eulerShortened_, maxShift_, h_);
        lines.push_back(line);
        std::snprintf(
            line, sizeof line,
            "state change         max |rho - rho_0| %.3e, max |p - p_0| %.3e, max |v - v_0| %.3e (over "
            "the run, from its start)",
            worstChange_.rho, worstChange_.p, worstChange_.v);
        lines.push_back(line);
    }
    if (shear_) {
        std::snprintf(
            line, sizeof line,
            "shear                central evaluations (particle-steps): %zu with a shifted fit short of "
            "neighbours, %zu with mu = 0; %zu with a shortened shift; largest shift %.4g (h %.4g)",
            shearTooFew_, unstrained_, shortened_, maxShearShift_, h_);
        lines.push_back(line);
    }
    if (surface_) {
        const double steps = time().timeIndex() > 0 ? double(time().timeIndex()) : 1.0;
        std::snprintf(
            line, sizeof line, "free surface         %.1f particles per step detected (%s), normals %s%s",
            double(surfaceParticles_) / steps,
            totalStressSurface_
                ? ("sigma n = -p_o n, p_o = " + formatKeywordNumber(outerPressure_) +
                   ", the tangential stress kept")
                      .c_str()
                : ("p = " + formatKeywordNumber(outerPressure_) + (shear_ ? ", S n = 0" : "")).c_str(),
            settings_.nested("freeSurface").word("normals").c_str(),
            edgeAngle_ > 0 ? (", " + formatKeywordNumber(double(edgeParticles_) / steps) +
                              " per step at edges (p = p_o, S n = 0)")
                                 .c_str()
                           : "");
        lines.push_back(line);
    }
    if (management_) {
        const auto& t = management_->total();
        std::snprintf(
            line, sizeof line,
            "particle management  %zu inserted, %zu pairs merged (over the run; %zu particles now); "
            "hole candidates rejected: %zu beyond a surface, %zu unfitted; mass change %.3e, "
            "momentum change %.3e",
            t.inserted, t.merged, particles, t.surface, t.unfitted, t.mass, t.momentum.norm());
        lines.push_back(line);
    }
    if (flowReference_) {
        const FlowError runRelative = flowRunRelative();
        std::snprintf(line, sizeof line,
                      "linear-flow reference  largest errors over the run / largest |exact|: rho %.3e, p "
                      "%.3e, S %.3e; at "
                      "the end (relative) rho %.3e, p %.3e, S %.3e",
                      runRelative.rho, runRelative.p, runRelative.S, flowRelative_.rho, flowRelative_.p,
                      flowRelative_.S);
        lines.push_back(line);
    }
    if (decomposition_)  // the shared two lines: migrations, halo, its traffic per step (bench/mpi)
        for (auto& l : decomposition_->summary(*owner_, double(time().timeIndex()), "step"))
            lines.push_back(l);
    if (reference_) {
        std::snprintf(
            line, sizeof line,
            "rotation reference   max |S - S_exact| %.3e, max ||x-c| - |x0-c|| %.3e, max |S| unstressed %.3e "
            "(over the run)",
            worst_.stress, worst_.radius, worst_.zeroStress);
        lines.push_back(line);
    }
    return lines;
}

template class FpmSolver<1>;
template class FpmSolver<2>;
template class FpmSolver<3>;

MFDYN_REGISTER_SOLVER(
    FpmSolver, "fpmSolid",
    "Finite pointset method for hypo-elastic solids (von Nida 2005): shear, Euler and rotation parts");

}  // namespace mfdyn
