// fpmSolid: the finite pointset method for the dynamics of hypo-elastic solids (von Nida 2005;
// the method as engineered is doc/methods/fpm.md). Particles are the nodes of a moving
// least-squares fit in the current configuration (meshfreeOperators/LeastSquaresOperators, fit
// weights by name); the system is split into a volumetric (Euler), a deviatoric (shear) and a
// rotation part (§3.1). Built: the rotation part (§3.4) with prescribed or frozen particle motion
// (the rotation-only test, §4.9, R4 of §4b) and the Euler part (§3.2, fpm/EulerPart.hpp: the
// pressure-gradient upwinding) on frozen particles (the Euler validation, §4.4, R6) or moving them
// with its upwind velocity v_uw (the thesis's Euler-only runs, R6L); the shear part is refused at
// its entry until it is built. A step:
//
//     neighbours (cell list, radius h, self included; (1 + maxShift) h for the Euler part's
//     shifted fits when a particle is shifted) -> fit (weights once per particle, applied to the
//     components of v and to p) -> euler (n = grad p / |grad p|, c^2 from the particle's
//     equationOfState at (rho, e), the fits at x -+ l n, rho, v, p, e updated by forward Euler)
//     -> rotation (on the Euler part's v: grad v refitted; W = skew grad v,
//     S <- exp(dt W) S exp(dt W)^T) -> volume (V <- V (1 + dt div v), the note's §4b remark)
//     -> motion (prescribed: the exact rigid rotation of x, v = omega a x (x - c); upwind:
//     x <- x + dt v_uw of the step's start; frozen: none)
//
// constant/fpmProperties:
//     subsystems (euler rotation);      // euler | shear | rotation (shear is not built); the order
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
//
// S is given as (xx yy zz xy yz xz); initialStress is applied at a fresh start to the particles
// inside its shape (all of them without one).
// system/controlDict: a fixed deltaT (adjustTimeStep no; the thesis's 0.001), or adjustTimeStep yes
// with maxCo: dt = maxCo x spacing / max |v| (prescribed motion).
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
#include "fpm/RotationPart.hpp"
#include "solver/InitialState.hpp"
#include "solver/MaterialAssignment.hpp"
#include "solver/SolverRegistry.hpp"
#include "solver/SolverRun.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <sstream>

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

template <int Dim>
KeywordSchema FpmSolver<Dim>::motionKeywords() {
    return KeywordSchema("solver", "fpmSolid/motion")
        .word("velocity", {"prescribed", "frozen", "upwind"},
              "the particles' motion: the rigid rotation v = omega axis x (x - centre), moved exactly "
              "(x <- c + Q (x - c), |x - c| kept to round-off), none, or the Euler part's upwind "
              "velocity v_uw (x <- x + dt v_uw, the thesis's Euler-only runs; subsystems with euler)")
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
        .orDefault(0.5);
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
               "the parts of the split that run (doc/methods/fpm.md §3.1): euler | shear | rotation; euler "
               "and rotation are built (euler on frozen particles)")
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
        .dictionary("euler", "the Euler part's upwinding: delta (a time) or deltaFraction (of h), maxShift")
        .optional()
        .nested(&FpmSolver<Dim>::eulerKeywords)
        .dictionary("motion", "the particle motion: a prescribed rigid rotation, or frozen")
        .nested(&FpmSolver<Dim>::motionKeywords)
        .dictionary("initialState",
                    "with velocity frozen: the velocity set at a fresh start (an initialState type, e.g. "
                    "rigidRotation: the rotation part on fixed particles, as in the thesis's coupled run)")
        .optional()
        .dictionary("initialStress", "a uniform deviatoric stress set at a fresh start inside a shape")
        .optional()
        .nested(&FpmSolver<Dim>::initialStressKeywords);
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
    declarePhases({"neighbours", "fit", "euler", "rotation", "volume", "motion"});
    readSubsystems();
    fitWeight_ = FitWeight::New(settings_.dictionary("fitWeight"));
    readMotion();
    readEuler();
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
        if (materials_->needsEnergy()) e_ = &owner_->scalarField("specificInternalEnergy");
    }
    Log::info("fpmSolid: " + std::to_string(materials_->size()) + " material(s) read; " +
              (euler_ ? "the Euler part takes c^2 from their equationOfState"
                      : "the rotation part uses none of their models"));
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
        const Dictionary& dict = settings_.dictionary("euler");
        if (e.given("delta") && e.given("deltaFraction"))
            throw dict.error("deltaFraction", "give delta (a time) or deltaFraction (of h), not both");
        if (e.given("deltaFraction")) {
            upwind.deltaIsTime = false;
            upwind.delta = e.scalar("deltaFraction");
        } else if (e.given("delta")) {
            upwind.delta = e.scalar("delta");
        }
        upwind.maxShift = e.scalar("maxShift");
    }
    eulerPart_ = std::make_unique<fpm::EulerPart<Dim>>(fitOptions<Dim>(settings_), upwind);
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
        if (name == "shear")
            throw properties_.error("subsystems",
                                    "the shear part is not built yet (issue 19: the rotation part, "
                                    "doc/methods/fpm.md §3.4, and the Euler part, §3.2, are built); use "
                                    "subsystems (euler rotation); or a part of it");
        if (name == "euler") euler_ = true;
        if (name == "rotation") rotation_ = true;
    }
    if (!euler_ && !rotation_)
        throw properties_.error("subsystems", "no subsystem to run: euler | rotation are built");
}

template <int Dim>
void FpmSolver<Dim>::readMotion() {
    const KeywordValues& motion = settings_.nested("motion");
    const Dictionary& dict = settings_.dictionary("motion");
    prescribed_ = motion.word("velocity") == "prescribed";
    upwindMotion_ = motion.word("velocity") == "upwind";
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
    S_ = &owner_->symmTensorField("deviatoricStress");
    if (!hadVolume)
        for (std::size_t i = 0; i < n; ++i) (*V_)[i] = m[i] / rho_[i];
    if (fresh || !hadStress)
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
    if (euler_) {  // this run's start, for the state-change measure
        rhoStart_ = rho_;
        pStart_ = *p_;
        vStart_ = v_;
    }
    radius0_.resize(n);
    for (std::size_t i = 0; i < n; ++i) radius0_[i] = (x_[i] - centre_).norm();  // at this run's start

    std::ostringstream log;
    log << "fpmSolid: " << n << " particles, spacing " << spacing_ << ", h " << h_ << " (" << h_ / spacing_
        << " spacings), fit order " << settings_.integer("order") << " (" << settings_.word("derivatives")
        << " derivatives), fitWeight " << fitWeight_->type() << (fitWeight_->squared() ? " squared" : "")
        << "; subsystems:" << (euler_ ? " euler (grad p upwinding, l = " : "")
        << (euler_ ? formatKeywordNumber(eulerPart_->options().delta) +
                         (eulerPart_->options().deltaIsTime ? " c" : " h") +
                         " <= " + formatKeywordNumber(eulerPart_->options().maxShift) + " h)"
                   : std::string())
        << (rotation_ ? " rotation (exact exp map)" : "") << "; motion: "
        << (prescribed_     ? "prescribed rigid rotation, omega " + formatKeywordNumber(omega_)
            : upwindMotion_ ? std::string("the Euler part's upwind velocity, x <- x + dt v_uw")
                            : std::string("frozen"));
    Log::info(log.str());
}

template <int Dim>
TimeStepVote FpmSolver<Dim>::stableTimeStep() {
    if (!prescribed_)
        return {std::numeric_limits<double>::infinity(), upwindMotion_ ? "fixed deltaT" : "frozen particles"};
    const double vmax =
        std::sqrt(GlobalReduce::max(v_.size(), [&](std::size_t i) { return v_[i].squaredNorm(); }));
    return {vmax > 0 ? time().maxCo() * spacing_ / vmax : std::numeric_limits<double>::infinity(), "Courant"};
}

template <int Dim>
void FpmSolver<Dim>::step(double dt) {
    const std::size_t n = x_.size();
    {
        auto timed = phase("neighbours");
        // growSupport refits within the rows it is given: they must reach its largest support
        rows_ = search_.build(x_, fit_.options().fallback == LeastSquaresOperators<Dim>::Fallback::growSupport
                                      ? fit_.options().maxSupportGrowth * h_
                                      : h_);
    }
    {
        auto timed = phase("fit");
        hField_.assign(n, h_);
        try {
            fit_.rebuild(x_, x_, rows_, hField_, *fitWeight_);
        } catch (const InputError&) {
            throw;
        } catch (const RunError&) {
            throw;
        } catch (const Error& e) {
            // The fit's own diagnosis (point = particle index on this process, its position and
            // neighbour counts, the remedies), with the time and the solver's remedy. Rank-local:
            // with several ranks the others would wait (no rank decomposition yet).
            throw RunError(
                "phase fit, step " + std::to_string(time().timeIndex() + 1) +
                ", t = " + formatKeywordNumber(time().value() + dt) + ": " + e.what() +
                " In constant/fpmProperties: a larger smoothingLength, or fitFallback growSupport | "
                "shepard.");
        }
        // the weights once per particle, applied to the Dim components of v
        gradV_ = fit_.gradientOf(v_);
        neighboursPerParticle_ = n ? double(rows_.offsets()[n]) / double(n) : 0.0;
        grown_ += fit_.fallbackCounts().grown;
        shepard_ += fit_.fallbackCounts().shepard;
    }
    if (euler_) {
        eulerStep(dt);
        if (rotation_) gradV_ = fit_.gradientOf(v_);  // the rotation part on the Euler part's results
    }
    if (rotation_) {
        auto timed = phase("rotation");
        std::vector<SymmTensor<Dim>>& S = *S_;
        parallelFor(
            n, [&](std::size_t i) { S[i] = fpm::rotated(S[i], fpm::spinExponential<Dim>(gradV_[i], dt)); });
    }
    {
        auto timed = phase("volume");
        std::vector<double>& V = *V_;
        parallelFor(n, [&](std::size_t i) { V[i] *= 1.0 + dt * gradV_[i].trace(); });
    }
    if (upwindMotion_) {  // with the v_uw of the step's start (EulerPart::upwind)
        auto timed = phase("motion");
        const auto& vUw = eulerPart_->result().vUpwind;
        parallelFor(n, [&](std::size_t i) { x_[i] += dt * vUw[i]; });
    }
    if (prescribed_) {
        auto timed = phase("motion");
        const Tensor<3> Q3 = fpm::axisRotation(axis_, omega_, dt);
        const Tensor<Dim> Q = Q3.template topLeftCorner<Dim, Dim>();
        parallelFor(n, [&](std::size_t i) {
            x_[i] = centre_ + Q * (x_[i] - centre_);
            v_[i] = prescribedVelocity(x_[i]);
        });
    }
    checkState(
        "rotation", n,
        [&](std::size_t i) {
            const auto& s = (*S_)[i];
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
    if (reference_) measureRotationError(time().value() + dt);
    if (euler_) {
        StateChange c;
        c.rho = GlobalReduce::max(n, [&](std::size_t i) { return std::abs(rho_[i] - rhoStart_[i]); });
        c.p = GlobalReduce::max(n, [&](std::size_t i) { return std::abs((*p_)[i] - pStart_[i]); });
        c.v = GlobalReduce::max(n, [&](std::size_t i) { return (v_[i] - vStart_[i]).norm(); });
        lastChange_ = c;
        worstChange_.rho = std::max(worstChange_.rho, c.rho);
        worstChange_.p = std::max(worstChange_.p, c.p);
        worstChange_.v = std::max(worstChange_.v, c.v);
    }
}

// The Euler part (fpm/EulerPart.hpp) on the fit of this step: c from each particle's equation of
// state at (rho, e), checked (rho c^2 > 0, the bracket of Dp/Dt in the Euler part), the upwinded
// div v and grad p, then rho, v, p (and e) advanced together.
template <int Dim>
void FpmSolver<Dim>::eulerStep(double dt) {
    auto timed = phase("euler");
    const std::size_t n = x_.size();
    const std::vector<std::int64_t>& material = owner_->integerField("material");
    c_.resize(n);
    std::vector<double> c2(n);
    for (std::size_t i = 0; i < n; ++i) {
        c2[i] = (*materials_)[std::size_t(material[i])].eos->soundSpeedSquared(rho_[i], e_ ? (*e_)[i] : 0.0);
        c_[i] = std::sqrt(std::max(c2[i], 0.0));
    }
    checkState(
        "euler", n, [&](std::size_t i) { return !(c2[i] > 0) || !(rho_[i] > 0); },
        [&](std::size_t i, double count) {
            const std::string name = materials_->names()[std::size_t(material[i])];
            return "particle " + std::to_string(owner_->globalId()[i]) + " (material " + name +
                   "): the bracket rho c^2 of the Euler part's pressure equation is not positive (rho " +
                   formatKeywordNumber(rho_[i]) + ", c^2 " + formatKeywordNumber(c2[i]) + " from its " +
                   "equationOfState at e " + formatKeywordNumber(e_ ? (*e_)[i] : 0.0) + "); " +
                   std::to_string(long(count)) +
                   " particles affected. Remedy: an equationOfState with c^2 > 0 in this state (rho0, "
                   "the initial e), or a smaller deltaT if the state ran away";
        });
    const std::vector<Vector<Dim>> gradP = fit_.gradientOf(*p_);
    // The shifted points' neighbours within h lie within (1 + maxShift) h of the particle: those
    // rows are searched only when some particle is shifted (a uniform p shifts none).
    bool anyShift = false;
    for (std::size_t i = 0; i < n && !anyShift; ++i)
        anyShift = eulerPart_->shifts(gradP[i].norm(), (*p_)[i], h_);
    anyShift = GlobalReduce::max(std::size_t(1), [&](std::size_t) { return anyShift ? 1.0 : 0.0; }) > 0;
    const double central = fit_.options().fallback == LeastSquaresOperators<Dim>::Fallback::growSupport
                               ? fit_.options().maxSupportGrowth
                               : 1.0;  // the reach of rows_, in h
    const bool wider = anyShift && 1.0 + eulerPart_->options().maxShift > central;
    if (wider) wideRows_ = search_.build(x_, (1.0 + eulerPart_->options().maxShift) * h_);
    const NeighbourList& rows = wider ? wideRows_ : rows_;
    eulerPart_->upwind(x_, rows, h_, *fitWeight_, rho_, *p_, v_, c_, gradP, gradV_);
    eulerPart_->advance(dt, rho_, v_, *p_, e_, c_);
    const auto& r = eulerPart_->result();
    flat_ += r.flat;
    tooFew_ += r.tooFew;
    for (double l : r.shift) maxShift_ = std::max(maxShift_, l);
}

// After the step, at t + dt: the exact stress of the particle now at x is Q(t + dt) S0(X) Q^T with
// X = c + Q^T (x - c) its start position (the motion is the exact rotation by Q). Global maxima:
// every rank reports the same figures.
template <int Dim>
void FpmSolver<Dim>::measureRotationError(double t) {
    const std::size_t n = x_.size();
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
std::vector<ExtraFile> FpmSolver<Dim>::extraOutput() const {
    std::vector<ExtraFile> files;
    if (euler_) {
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
    std::snprintf(
        line, sizeof line,
        "fit                  %.1f neighbours per particle (rows), fallbacks: %zu grown supports, %zu "
        "Shepard fits (particle-steps)",
        neighboursPerParticle_, grown_, shepard_);
    lines.push_back(line);
    if (euler_) {
        std::snprintf(line, sizeof line,
                      "euler                central evaluations (particle-steps): %zu with |grad p| ~ 0, %zu "
                      "with a shifted fit short of neighbours; largest shift %.4g (h %.4g)",
                      flat_, tooFew_, maxShift_, h_);
        lines.push_back(line);
        std::snprintf(
            line, sizeof line,
            "state change         max |rho - rho_0| %.3e, max |p - p_0| %.3e, max |v - v_0| %.3e (over "
            "the run, from its start)",
            worstChange_.rho, worstChange_.p, worstChange_.v);
        lines.push_back(line);
    }
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
    "Finite pointset method for hypo-elastic solids (von Nida 2005): the Euler and rotation parts");

}  // namespace mfdyn
