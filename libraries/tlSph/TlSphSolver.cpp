// tlSph (Lee, Gil, Greto, Kulasegaram, Bonet 2016, CMAME 311; doc/methods/tl-jst-sph.md 2.3-2.8). With
// g_ab = grad~W_b(X_a) the corrected kernel gradient in the reference configuration, V_a the
// reference volume, p = rho0 v:
//
//   G_a   = sum_b V_b (v_b - v_a) (x) g_ab                    grad0(p/rho0), the velocity gradient
//   T_a   = sum_b V_b [P_b g_ba - P_a g_ab]                   (29c) internal force, ~ -DIV P
//   dp/dt = -T_a + D(p_a) + E_a,   E_a = rho0 a(x, t) + (boundary force)/V_a               (41)
//   dF/dt = G_a,   dH/dt = F_a x G_a,   dJ/dt = H_a : G_a + D(J_a),   dx/dt = v_a
//   D(U)  = eps2 c_p h L[U] - eps4 c_p h^3 L^2[U],  L[U]_a = sum_b V_b (U_b - U_a) Lap~W_b(X_a)
//
// Projections at each stage (eqs. 45-51): -T + D(p) is projected to zero total force and zero
// total moment about x~ (x~ = x^n at stage 1, x^n + dt/2 (v^n + v*) = x^{n+1} at stage 2, which
// makes the step's angular momentum change (dt/2)[sum V x^n x p'^n + sum V x^{n+1} x p'^*]
// vanish exactly); D(J) has its volume mean removed. Then the essential boundary conditions act
// on dp/dt (and on p after each update): the direct method of 2.7.
//
// TVD RK2 (43-44) on U = {p, F, H, J, x}:  U* = U^n + dt U'(U^n);  U** = U* + dt U'(U*);
// U^{n+1} = (U^n + U**)/2; then P^{n+1} from (F, H, J)^{n+1}, advancing the plastic state.
//
// The energy-growth check (issue 16): E = sum_a V_a (rho0 |v_a|^2 / 2 + W_a) against the energy
// put in, E_in = E(t0) + W_ext, W_ext the work of everything that is not the internal force
// -T + D(p): the essential conditions' reactions, tractions and body forces, integrated as
// dt/2 (P* + P**) with P the stage's sum_a m_a (a_a - (-T + D(p))_a / rho0) . v_a. A stable run
// dissipates (JST) and keeps E <= E_in up to the time error; an unstable one grows E by orders of
// magnitude (the 4 mm plate at maxCo 0.8: 1.9e5-fold by 0.1 s with no particle inverted, so the
// state check never fired). E > energyGrowthLimit x max_t E_in stops the run with a diagnosis.
//
// The energy budget (the health check's K + U + D - W, RunContext.hpp). With E = sum_a V_a
// (rho0 |v_a|^2 / 2 + W(F_a, H_a, J_a)), P = Sigma_F + Sigma_H x F + Sigma_J H (the law's
// conjugate stresses, doc/methods/tl-jst-sph.md 1) and the rates above, dW_a/dt = P_a : G_a +
// Sigma_J,a D(J_a) (dH/dt = F x G and dJ/dt = H : G + D(J)). The pair form of T makes
// sum_a V_a v_a . T_a = sum_a V_a P_a : G_a exactly (exchange a and b: T is variationally
// consistent with G, doc/methods/tl-jst-sph.md 2.3), so the semi-discrete energy equation is
//     dE/dt = sum_a V_a v_a . [rho0 a_a - f_a]  +  sum_a V_a [v_a . (f_a + T_a) + Sigma_J,a D(J_a)]
//           =          dW_ext/dt                 -            dD/dt
// with f_a = P(-T_a + D(p_a)) the internal force after the stabilisation and the projections P
// (eqs. 45-51) and a_a the acceleration after the body forces, tractions and essential conditions:
// W_ext is what the energy-growth check integrates, D (schemeDissipation) what the JST terms (or
// the artificial viscosity) and the projections of the force remove from K + U; Sigma_J = dU/dJ,
// the law's pressure (readMaterials: the laws for which it is). Both are integrated as the step
// is, dt/2 (stage 1 + stage 2) of the TVD RK2, so that K + U + D - W changes by the scheme's time
// error alone: O(dt^3) a step for a smooth solution (the trapezoid of the stage powers against the
// energy of the RK2 update: exact to O(dt^4) for a quadratic energy, O(dt^3) through the third
// derivative of W), O(dt^2) per unit time. The identity holds with the symmetry planes' mirror
// ghosts too (measured on the swinging cube: sum_a V_a (P_a : G_a - v_a . T_a) over the real
// particles integrates to 3e-16 J of 7.9 J), so the planes do no work, as in the continuum. The
// plastic dissipation is added to D where the step's plastic state is advanced (computeStress(true)):
// the law's plasticDissipation per reference volume (J2Plasticity: the returned Kirchhoff deviator
// times the plastic increment, |s| dgamma; W_trial - W_returned exceeds it by mu dgamma^2, which
// overcounted the 500 m/s Taylor bar's loss by 23%), times V0. With it the budget closes on that bar
// to -0.23% of the initial energy (-0.29% at 227 m/s; tests/cases/extreme). D need not grow monotonically: the corrected Laplacian is not
// self-adjoint (doc/methods/tl-jst-sph.md 2.2), so sum V v . D(p) is not of one sign (the tutorial
// plate's D falls by 1% of itself in some half periods).
//
// Below three dimensions the body is in plane strain (2D) or uniaxial strain (1D): F is embedded
// in 3x3 with unit out-of-plane stretch, H's out-of-plane diagonal is that of cof(F) (in plane
// strain H_zz = det F_2D exactly), and the laws see 3x3 tensors.
//
// Several ranks (issue 21). Neighbourhoods are of X and never change, so the body is cut once, in
// X (Decomposition::distribute cuts by referencePosition when the file carries it), nothing
// migrates, and the halo is planned once. Its depth is two supports 2R: the pair loop of an owned
// particle a reads, at each neighbour b (within R), b's own corrected gradient g_ba and its
// Laplacian weight at a (the corrections of b's row), and the dissipation reads L[p]_b, L[J]_b;
// all of b's row lies within 2R of a. So the operators are built over [owned][halo][images] with
// the rows of the owned particles and of their neighbours computed (ReferenceOperators::Options::
// interior), each row in the serial run's order (Options::order: global ids, then the images in
// the order a serial run makes them), which gives every pair sum the serial run's bits. The one
// support deep alternative, the halo rows' correction data exchanged, cannot give those bits at
// the images: an image's row is its own sum over the extended body, not its source's row mirrored.
// The images are made from owned and halo sources, sorted by global id (so that they come in the
// serial order); an image within 2R of an owned particle has its source within 2R too (a
// reflection through a plane with both on the body's side only lengthens the distance, and so do
// the orthogonal planes' images of images). Each stage the halo is appended with what the pair
// loops read at b (v, P, rho0, J), then the images; L[p], L[J] and the kinematic flags are
// refreshed from their owners (imagesOf, updateKinematic). Every figure the ranks share (time
// step, projections, energies, health) is a global reduction over the owned particles; the
// Lagrange-multiplier projection, one system over every constrained particle, is refused.
#include "tlSph/TlSphSolver.hpp"

#include "boundaryConditions/Fixed.hpp"
#include "core/KeywordSchema.hpp"
#include "core/Log.hpp"
#include "core/Parallel.hpp"
#include "materials/Embedding.hpp"
#include "particles/Decomposition.hpp"
#include "solver/BodyForce.hpp"
#include "solver/InitialState.hpp"
#include "solver/MaterialAssignment.hpp"
#include "solver/SolverRegistry.hpp"
#include "solver/SolverRun.hpp"
#include "tlSph/LagrangeMultiplierProjection.hpp"
#include "tlSph/MomentumProjection.hpp"
#include "tlSph/TlSphHealth.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <numeric>
#include <sstream>

namespace mfdyn {

template <int Dim>
KeywordSchema TlSphSolver<Dim>::projectionKeywords() {
    return KeywordSchema("solver", "tlSph/projection")
        .flag("momentum", "project the internal force to zero total force and moment about x~ (eqs. 45-50)")
        .orDefault(true)
        .flag("dissipation", "project the momentum dissipation D(p) likewise")
        .orDefault(true)
        .flag("jacobian", "remove the volume mean of the Jacobian dissipation D(J) (eq. 51)")
        .orDefault(true);
}

// constant/tlSphProperties. Every keyword the solver reads is declared here (the defaults are
// those the solver always had); the models' sub-dictionaries are read by their own families.
template <int Dim>
KeywordSchema TlSphSolver<Dim>::keywords() {
    return KeywordSchema("solver", "tlSph")
        .word("formulation", {"pF", "pFJ", "pFHJ", "displacement"},
              "the conservation laws integrated: {p, F}, {p, F, J}, {p, F, H, J}, or p with F = I + grad~ u")
        .dictionary("kernel", "the smoothing kernel (a kernel type; support 2h)")
        .dictionary("dissipation", "the stabilisation D(p), D(J) (a dissipation (tlSph) type)")
        .dictionary("bodyForce", "body force per unit mass a(x, t), E = rho0 a (a bodyForce type)")
        .optional()
        .scalar("smoothingLengthRatio", "-", "h = smoothingLengthRatio x spacing")
        .greaterThan(0)
        .orDefault(1.3)
        .scalar("spacing", "m", "the particle spacing h_min (default: the largest V^(1/d))")
        .greaterThan(0)
        .optional()
        .word("gradient", {"corrected", "uncorrected", "correctedKernel"},
              "the reference gradient (default corrected; correctedKernel under lagrangeMultiplier)")
        .optional()
        .dictionary("projection", "the conservation projections of the rates (all on by default)")
        .optional()
        .nested(&TlSphSolver<Dim>::projectionKeywords)
        .word("waveSpeed", {"current", "reference"},
              "the CFL wave speed: c_p scaled by the largest stretch of F, H (current), or c_p")
        .orDefault("current")
        .scalar("deformedCourant", "-",
                "with waveSpeed current: the Courant number of the deformed wave speed c_p x stretch "
                "(in [maxCo, 1]; the step is min(maxCo h / c_p, deformedCourant h / (c_p x stretch)); "
                "default maxCo)")
        .greaterThan(0)
        .atMost(1)
        .optional()
        .scalar("energyGrowthLimit", "-",
                "stop the run (exit status 1, the state written) when the total energy (kinetic + internal) "
                "exceeds this factor times the energy put in: the largest so far of the initial energy plus "
                "the work of the boundary conditions and body forces (checked every 10 steps)")
        .greaterThan(1)
        .orDefault(1.5)
        .flag("mirrorGhosts", "mirror the body across its symmetryPlane and skewSymmetricPlane conditions")
        .orDefault(true)
        .word("essentialBoundaryConditions", {"direct", "lagrangeMultiplier"},
              "fixed and prescribed motion imposed on p and dp/dt (direct) or by the App. B projection")
        .orDefault("direct")
        .dictionary("initialState", "a state applied at a fresh start (an initialState type)")
        .optional();
}

// The formulation is a solver option, not a plug-in model: it selects which conservation laws the
// solver integrates (Lee et al. 2016 eqs. 1, 6; eq. 34 for displacement), and their update rules
// (dF/dt = G, dH/dt = F x G, dJ/dt = H : G + D(J), or F from the positions) are the solver's own,
// inseparable from its stages, its stress evaluation and its fields, so a model outside the
// solver could add nothing but a name.
//
//     formulation   evolves               computed from F each evaluation
//     pF            p, F                  H = cof F, J = det F
//     pFJ           p, F, J               H = cof F (near incompressibility: no checkerboarding)
//     pFHJ          p, F, H, J            -   (the polyconvex laws' natural arguments)
//     displacement  p (and x)             F = I + grad~ u, u = x - X (Remark 5: the classical
//                                         displacement-based TL-SPH, for comparison)
template <int Dim>
typename TlSphSolver<Dim>::Formulation TlSphSolver<Dim>::formulationNamed(const std::string& name) {
    if (name == "displacement") return {name, false, false, false};
    return {name, true, name == "pFHJ", name == "pFJ" || name == "pFHJ"};
}

template <int Dim>
KeywordValues TlSphSolver<Dim>::readSettings(const Dictionary& properties) {
    // One syntax: the old family form `formulation { type pFJ; }` is refused at its line.
    if (properties.isDict("formulation"))
        throw properties.error(
            "formulation",
            "formulation is now a word of tlSphProperties, `formulation pFJ;` (one of pF | "
            "pFJ | pFHJ | displacement), not a dictionary");
    return keywords().read(properties);
}

template <int Dim>
TlSphSolver<Dim>::TlSphSolver(SolverRun& run)
    : Solver(run),
      owner_(adoptParticleSet<Dim>(run.takeParticles())),
      particles_(owner_.get()),
      properties_(openConstant("tlSphProperties")),
      materialProperties_(openConstant("materialProperties")),
      settings_(readSettings(properties_)),
      kernel_(Kernel::New(settings_.dictionary("kernel"))),
      formulation_(formulationNamed(settings_.word("formulation"))),
      dissipationModel_(TlDissipation::New(settings_.dictionary("dissipation"))),
      x_(particles_->position()),
      v_(particles_->vectorField("velocity")),
      m_(requireScalarField(*particles_, "mass", "particle masses")),
      rho0_(requireScalarField(*particles_, "density", "the reference density rho0")) {
    declarePhases({"computeStress", "computeRates", "dissipation", "projections", "integrate"});
    decomposition_ = run.decomposition();
    if (settings_.given("projection")) {
        const KeywordValues& projection = settings_.nested("projection");
        projectMomentum_ = projection.flag("momentum");
        projectDissipation_ = projection.flag("dissipation");
        projectJacobian_ = projection.flag("jacobian");
    }
    currentWaveSpeed_ = settings_.word("waveSpeed") == "current";
    // The deformed wave speed's own Courant number (tutorials/tlSph/taylorBar/README.md): only
    // with the current wave speed, and never below maxCo (the undeformed body's step is maxCo's).
    if (settings_.given("deformedCourant")) {
        deformedCourant_ = settings_.scalar("deformedCourant");
        if (!currentWaveSpeed_)
            throw properties_.error(
                "deformedCourant",
                "deformedCourant needs `waveSpeed current;` (with waveSpeed reference the "
                "step is maxCo h / c_p): remove it or use waveSpeed current");
    }
    // One Courant keyword for every method: controlDict's maxCo (tlSph's default 0.3 when the
    // controlDict gives none, the paper's alpha_CFL). The old tlSphProperties keyword is refused
    // at its line rather than silently ignored.
    if (properties_.found("alphaCFL"))
        throw properties_.error(
            "alphaCFL", "alphaCFL is now maxCo in system/controlDict: move the value there as `maxCo ...;`");
    if (!(courant() <= 1))
        throw run.controlDict().error("maxCo",
                                      "tlSph needs maxCo in (0, 1] (the TVD RK2 is unstable above "
                                      "1), found " +
                                          formatKeywordNumber(courant()));
    if (deformedCourant_ && *deformedCourant_ < courant())
        throw properties_.error("deformedCourant", "deformedCourant must lie in [maxCo, 1] = [" +
                                                       formatKeywordNumber(courant()) + ", 1], found " +
                                                       formatKeywordNumber(*deformedCourant_));
    // Body forces per unit mass a(x, t) come from the shared bodyForce family (solver/BodyForce.hpp),
    // as for every method; the old tlSph-only `gravity` vector is refused at its line.
    if (properties_.found("gravity")) {
        std::string types;
        for (const auto& name : BodyForce::Selector::names()) types += (types.empty() ? "" : " | ") + name;
        throw properties_.error("gravity",
                                "gravity is now the bodyForce sub-dictionary of tlSphProperties: "
                                "`bodyForce { type uniformGravity; g (...); }` (valid types: " +
                                    types + ")");
    }
    if (settings_.given("bodyForce")) bodyForce_ = BodyForce::New(settings_.dictionary("bodyForce"), Dim);
    energyGrowthLimit_ = settings_.scalar("energyGrowthLimit");
    readMaterials();
    initialiseFields();
}

template <int Dim>
TlSphSolver<Dim>::~TlSphSolver() = default;

template <int Dim>
void TlSphSolver<Dim>::readMaterials() {
    // A constitutive law per material, nothing else (an equation of state or a strength law is the
    // updated-Lagrangian methods' model: refused at its entry); one log line per material.
    MaterialModels models;
    models.method = "tlSph";
    models.constitutiveLaw = ModelUse::required;
    materials_ = std::make_unique<MaterialSet<Dim>>(materialProperties_, models);
    plastic_ = materials_->usesPlasticState();
    // {p,F,J}: the evolved J carries the volumetric response and F the isochoric one. A law whose
    // isochoric part reads J as well (neoHookean, mooneyRivlin: mu/2 J^-2/3 F:F) gives, with J
    // apart from det F, a volumetric stiffness of F alone that is negative (linearised in plane
    // strain, P = mu (e + e^T) - 5/3 mu tr(e) I + (mu + kappa)(J - 1) I: -4/3 mu per unit tr(e)
    // at fixed J). D(J) smooths J at the particle scale while F keeps its own short waves, so
    // those waves of det F grow: the oscillating plate at nu = 0.45 with jacobian (0 0.125) grew
    // its energy 1e5-fold in 0.04 s (issue 16). Such a law is evaluated at J = det F and its
    // volumetric part moved to J (computeStress). Which laws need it is measured here, once:
    // P(J1) - P(J0) = (p(J1) - p(J0)) H at a sheared, stretched state holds for a law whose
    // isochoric part is F's alone (j2Plasticity, linearElastic: evaluated as they are).
    if (formulation_.evolvesJ() && !formulation_.evolvesH()) {
        splitJacobian_.assign(materials_->size(), 0);
        Tensor<3> F = Tensor<3>::Identity();
        F(0, 0) = 1.05, F(1, 1) = 0.97, F(0, 1) = 0.03;
        const Tensor<3> H = cofactor(F);
        for (std::size_t k = 0; k < materials_->size(); ++k) {
            Tensor<3> P[2];
            double p[2], J[2] = {F.determinant(), 1.02 * F.determinant()};
            for (int s = 0; s < 2; ++s) {
                SymmTensor<3> cp = SymmTensor<3>::fromFull(Tensor<3>::Identity());
                double epsP = 0;
                ConstitutiveLaw::Fields f;
                f.size = 1, f.F = &F, f.H = &H, f.J = &J[s], f.P = &P[s], f.pressure = &p[s];
                f.plasticState = &cp, f.plasticStrain = &epsP;
                law(k).stress(f, false);
            }
            const double scale = P[0].norm() + std::abs(p[1] - p[0]) * H.norm() + law(k).shearModulus();
            splitJacobian_[k] = (P[1] - P[0] - (p[1] - p[0]) * H).norm() > 1e-9 * scale;
            if (splitJacobian_[k])
                Log::info("formulation pFJ: material " + materials_->names()[k] + "'s " + law(k).type() +
                          " law is evaluated at J = det F, its pressure at the evolved J");
        }
    }
    // How D(J) changes each material's stored energy (the energy budget): dU/dt = P : G + Sigma_J
    // D(J), Sigma_J = dW/dJ at fixed F, H. For a split law (above) and a law whose energy reads J
    // through U(J) alone Sigma_J is the law's pressure dU/dJ; a law whose energy does not read J
    // (linearElastic) has Sigma_J = 0. Measured once: W(J1) - W(J0) against the trapezoid of p.
    if (formulation_.evolvesJ()) {
        jacobianWork_.assign(materials_->size(), 1);
        Tensor<3> F = Tensor<3>::Identity();
        F(0, 0) = 1.05, F(1, 1) = 0.97, F(0, 1) = 0.03;
        const Tensor<3> H = cofactor(F);
        for (std::size_t k = 0; k < materials_->size(); ++k) {
            if (!splitJacobian_.empty() && splitJacobian_[k]) continue;
            double w[2], p[2], J[2] = {F.determinant(), 1.02 * F.determinant()};
            for (int s = 0; s < 2; ++s) {
                Tensor<3> P;
                SymmTensor<3> cp = SymmTensor<3>::fromFull(Tensor<3>::Identity());
                double epsP = 0;
                ConstitutiveLaw::Fields f;
                f.size = 1, f.F = &F, f.H = &H, f.J = &J[s], f.P = &P, f.pressure = &p[s],
                f.energyDensity = &w[s];
                f.plasticState = &cp, f.plasticStrain = &epsP;
                law(k).stress(f, false);
            }
            const double trapezoid = 0.5 * (p[0] + p[1]) * (J[1] - J[0]);
            const double scale = std::abs(trapezoid) + 1e-6 * law(k).shearModulus() * (J[1] - J[0]);
            if (std::abs(w[1] - w[0]) <= 1e-9 * scale)
                jacobianWork_[k] = 0;
            else if (std::abs(w[1] - w[0] - trapezoid) > 1e-4 * scale) {
                jacobianWork_[k] = -1;
                if (dissipationModel_->actsOnJacobian())
                    Log::warning("health: material " + materials_->names()[k] + "'s " + law(k).type() +
                                 " law reads J beyond U(J): the work of D(J) on it is not in the energy "
                                 "budget's dissipation (it stays in the imbalance)");
            }
        }
    }
    assignMaterials(*particles_, materials_->names(), materialProperties_);
    material_ = &particles_->integerField("material");
}

template <int Dim>
void TlSphSolver<Dim>::initialiseFields() {
    const std::size_t n = x_.size();
    V_.resize(n);
    checkPositiveMassAndDensity(*particles_, m_, rho0_);
    for (std::size_t i = 0; i < n; ++i) {
        const double lawRho0 = law((*material_)[i]).referenceDensity();
        if (std::abs(rho0_[i] - lawRho0) > 1e-9 * lawRho0)
            throw materialProperties_.error(
                "materials", "particle " + std::to_string(particles_->globalId()[i]) + " has density " +
                                 std::to_string(rho0_[i]) + " but its material '" +
                                 materials_->names()[(*material_)[i]] + "' has rho0 " +
                                 std::to_string(lawRho0) +
                                 ": generate the particles with the material's density");
        V_[i] = m_[i] / rho0_[i];
    }
    // A fresh start has no reference configuration yet: X is where the particles were generated.
    const bool fresh = !particles_->hasField("referencePosition");
    X_ = &particles_->vectorField("referencePosition");
    if (fresh) *X_ = x_;
    const bool hadF = particles_->hasField("deformationGradient");
    F_ = &particles_->tensorField("deformationGradient");
    if (!hadF) std::fill(F_->begin(), F_->end(), Tensor<Dim>::Identity());
    if (fresh)
        if (settings_.given("initialState")) {
            const Dictionary& init = settings_.dictionary("initialState");
            InitialState<Dim>::New(init)->apply(*particles_, *X_);
            Log::info("Initial state: " + init.get<std::string>("type"));
        }
    if (formulation_.evolvesH()) {
        const bool had = particles_->hasField("cofactor");
        H_ = &particles_->tensorField("cofactor");
        if (!had)
            for (std::size_t i = 0; i < n; ++i) {
                const Tensor<3> F3 = embed<Dim>((*F_)[i], 1.0);
                (*H_)[i] = inPlane<Dim>(0.5 * tensorCross(F3, F3));
            }
    }
    if (formulation_.evolvesJ()) {
        const bool had = particles_->hasField("jacobian");
        J_ = &particles_->scalarField("jacobian");
        if (!had)
            for (std::size_t i = 0; i < n; ++i) (*J_)[i] = (*F_)[i].determinant();
    }
    P_ = &particles_->tensorField("firstPiolaStress");
    pressure_ = &particles_->scalarField("pressure");
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

    // Spacing (h_min of the paper) and smoothing length.
    // Over every rank: the spacing sets h, which must be one for the whole body.
    const double largest = std::max(0.0, GlobalReduce::max(n, [&](std::size_t i) { return V_[i]; }));
    spacing_ = settings_.optionalScalar("spacing").value_or(std::pow(largest, 1.0 / Dim));
    if (!(spacing_ > 0))  // the default of a set with no volume (the schema checks a given one)
        throw properties_.error("", "the particle spacing " + formatKeywordNumber(spacing_) +
                                        " from the largest particle volume is not positive: give `spacing`");
    const double ratio = settings_.scalar("smoothingLengthRatio");
    h_ = ratio * spacing_;
    // For sampling and the interpolating function objects (sample, probes, swingingCubeError).
    auto& smoothingLength = particles_->scalarField("smoothingLength");
    std::fill(smoothingLength.begin(), smoothingLength.end(), h_);
    // The boundary conditions pick their particles from the initial state (skewSymmetricPlane
    // from the reference positions), so they are built after it.
    boundaries_ = readBoundaryConditions(*particles_, {.ghosts = false, .boundaryForces = true});
    const std::string& essential = settings_.word("essentialBoundaryConditions");
    const bool lagrangeMultiplier = essential == "lagrangeMultiplier" && !boundaries_.empty();
    if (lagrangeMultiplier && decomposition_)
        throw properties_.error(
            "essentialBoundaryConditions",
            "lagrangeMultiplier solves one system over the constrained particles of every "
            "rank and does not run on several ranks (issue 21); valid choices on several "
            "ranks: direct");
    if (decomposition_) {
        // Set-up's halo: X, m, rho0 of the other ranks' particles within two supports (the
        // header: why two), for the volumes, the images and the operators; cleared below.
        decomposition_->planHalo(*particles_, 2.0 * kernel_->supportRadius(h_) * (1.0 + 1e-9),
                                 "referencePosition");
        haloSize_ = decomposition_->appendHalo(*particles_, {"referencePosition", "mass", "density"});
        V_.resize(n + haloSize_);
        for (std::size_t i = n; i < n + haloSize_; ++i) V_[i] = m_[i] / rho0_[i];
        haloFields_ = {"velocity", "firstPiolaStress", "density"};
        if (J_) haloFields_.push_back("jacobian");
    }
    makeMirrorGhosts();
    typename ReferenceOperators<Dim>::Options options;
    options.laplacian = true;
    if (lagrangeMultiplier && !ghosts_.empty())
        throw properties_.error(
            "essentialBoundaryConditions",
            "lagrangeMultiplier needs `mirrorGhosts no;`: across a mirrored plane the constraint "
            "holds by symmetry, and the projection interpolates over the real particles only");
    options.correctedKernel = lagrangeMultiplier;
    // Without ghosts, the force (29c) on the plain corrected gradient leaves an error of order P/h
    // on the particles within 2h of a constrained plane, which neither the projection nor the
    // direct setting removes: the swinging cube converges at first order (p 0.83, P 0.82) with
    // either. On the corrected gradient of the corrected kernel (eq. 23, force 31), the kernel the
    // projection interpolates with, it converges at p 2.41, P 1.76 with either (measured,
    // tutorials/tlSph/swingingCube/README.md). So that is the default under lagrangeMultiplier.
    const GradientCorrection defaultGradient =
        lagrangeMultiplier ? GradientCorrection::correctedKernel : GradientCorrection::corrected;
    options.gradient =
        settings_.given("gradient") ? gradientCorrectionFromName(properties_, "gradient") : defaultGradient;
    if (!settings_.given("gradient"))
        Log::info("gradient " + gradientCorrectionName(options.gradient) + " (default" +
                  (lagrangeMultiplier ? " with essentialBoundaryConditions lagrangeMultiplier)" : ")"));
    Stopwatch watch;
    std::vector<Vector<Dim>> Xall(*X_);  // owned, then the halo
    Xall.insert(Xall.end(), ghosts_.position.begin(), ghosts_.position.end());
    if (decomposition_) {
        // Rows in the serial order: real particles by global id, then the images as made (after
        // every id: nextGlobalId() is the whole set's on every rank).
        const auto& ids = particles_->globalId();
        order_.assign(ids.begin(), ids.end());
        for (std::size_t g = 0; g < ghosts_.size(); ++g)
            order_.push_back(particles_->nextGlobalId() + std::int64_t(g));
        options.order = order_;
        options.interior = n;
    }
    operators_ = std::make_unique<ReferenceOperators<Dim>>(Xall, V_, h_, *kernel_, options);
    particles_->clearGhosts();  // the set-up's halo
    if (lagrangeMultiplier) {
        essentialTime_ = time().value();
        essential_ = std::make_unique<LagrangeMultiplierProjection<Dim>>(
            *operators_, V_, constraintsFrom(boundaries_, *particles_, essentialTime_), n);
        Log::info(
            "Essential boundary conditions by the Lagrange-multiplier projection (Lee et al. 2016 App. B): " +
            std::to_string(essential_->size()) + " constrained particles");
    }
    for (std::size_t k = 0; k < materials_->size(); ++k) {
        cpMax_ = std::max(cpMax_, law(k).pWaveSpeed());
        csMax_ = std::max(csMax_, std::sqrt(law(k).shearModulus() / law(k).referenceDensity()));
    }

    // P and the pressure of the initial state, for the first write and the function objects.
    if (formulation_.displacementBased()) computeDisplacementGradient();
    computeStress(false);
    stressCurrent_ = true;

    acceleration_.assign(n, Vector<Dim>::Zero());
    dFdt_.assign(n, Tensor<Dim>::Zero());
    if (H_) dHdt_.assign(n, Tensor<Dim>::Zero());
    if (J_) dJdt_.assign(n, 0.0);
    // The operators the dissipation model asked for (the bi-Laplacian is built on the Laplacian).
    const TlDissipation& model = *dissipationModel_;
    if (model.needsMomentumLaplacian() || model.needsMomentumBiLaplacian())
        lapP_.assign(n, Vector<Dim>::Zero());
    if (model.needsMomentumBiLaplacian()) lap2P_.assign(n, Vector<Dim>::Zero());
    if (J_ && (model.needsJacobianLaplacian() || model.needsJacobianBiLaplacian())) lapJ_.assign(n, 0.0);
    if (J_ && model.needsJacobianBiLaplacian()) lap2J_.assign(n, 0.0);

    const auto pairs = std::size_t(globalSum(double(operators_->neighbours().offsets()[n])));
    const auto particles = std::size_t(globalSum(double(n)));
    std::ostringstream s;
    s << "tlSph: formulation " << formulation_.name() << ", kernel " << kernel_->type() << ", spacing "
      << spacing_ << ", h " << h_ << ", " << pairs / std::max<std::size_t>(1, particles)
      << " neighbours per particle (reference configuration, " << watch.seconds() << " s), c_p,max " << cpMax_
      << " m/s, dissipation " << dissipationModel_->describe() << ", projections: momentum "
      << (projectMomentum_ ? "yes" : "no") << ", dissipation " << (projectDissipation_ ? "yes" : "no")
      << ", jacobian " << (projectJacobian_ ? "yes" : "no");
    Log::info(s.str());
    if (decomposition_) {
        const double halo = globalSum(double(haloSize_));
        std::ostringstream d;
        d << "Halo: " << halo << " particles (" << halo / double(std::max<std::size_t>(1, particles))
          << " of the owned) within two supports " << decomposition_->width() << " m in X, planned once; "
          << globalSum(double(ghosts_.size())) << " images on all ranks";
        Log::info(d.str());
        Log::info(decomposition_->report(*particles_, {}));
    }
    if (const std::string warning = model.stabilityWarning(courant(), csMax_ / cpMax_, J_ != nullptr);
        !warning.empty())
        Log::warning(warning);
}

template <int Dim>
Tensor<3> TlSphSolver<Dim>::cofactor3(std::size_t i) const {
    const Tensor<3> F3 = embed<Dim>((*F_)[i], 1.0);
    Tensor<3> H3 = 0.5 * tensorCross(F3, F3);
    if (H_) H3.template topLeftCorner<Dim, Dim>() = (*H_)[i];
    return H3;
}

template <int Dim>
void TlSphSolver<Dim>::computeStress(bool updateState) {
    auto timed = phase("computeStress");
    if (updateState && plastic_) plasticLoss_.assign(x_.size(), 0.0);
    parallelForWork(x_.size(), 32 * x_.size(), [&](std::size_t i) {
        const Tensor<3> F3 = embed<Dim>((*F_)[i], 1.0);
        const Tensor<3> H3 = cofactor3(i);
        const double J = J_ ? (*J_)[i] : F3.determinant();
        Tensor<3> P3;
        double pressure = 0;
        SymmTensor<3> cp;
        double epsP = 0;
        ConstitutiveLaw::Fields f;
        f.size = 1, f.F = &F3, f.H = &H3, f.J = &J, f.P = &P3, f.pressure = &pressure;
        const auto& law = this->law((*material_)[i]);
        if (law.usesPlasticState()) {
            const Tensor<Dim> c = (*plasticDeformation_)[i].full();
            cp = SymmTensor<3>::fromFull(embed<Dim>(c, plasticOutOfPlane_ ? (*plasticOutOfPlane_)[i] : 1.0));
            epsP = (*plasticStrain_)[i];
            f.plasticState = &cp, f.plasticStrain = &epsP;
            if (updateState) f.plasticDissipation = &plasticLoss_[i];
        }
        // {p,F,J} with a law whose isochoric part reads J (splitJacobian_): the law at J = det F,
        // then the volumetric part moved to the evolved J, P += (p(J) - p(det F)) H.
        const bool split = !splitJacobian_.empty() && splitJacobian_[(*material_)[i]];
        const SymmTensor<3> cpBefore = cp;
        const double epsPBefore = epsP, detF = F3.determinant();
        if (split) f.J = &detF;
        law.stress(f, updateState);
        if (split) {
            Tensor<3> unused;
            double pJ = 0, epsPJ = epsPBefore;
            SymmTensor<3> cpJ = cpBefore;
            ConstitutiveLaw::Fields g = f;
            g.J = &J, g.P = &unused, g.pressure = &pJ, g.plasticDissipation = nullptr;
            if (law.usesPlasticState()) g.plasticState = &cpJ, g.plasticStrain = &epsPJ;
            law.stress(g, false);
            P3 += (pJ - pressure) * H3;
            pressure = pJ;
        }
        if (updateState && law.usesPlasticState()) {
            plasticLoss_[i] *= rho0_[i] > 0 ? m_[i] / rho0_[i] : 0.0;  // per reference volume -> J
            const Tensor<3> c = cp.full();
            (*plasticDeformation_)[i] = SymmTensor<Dim>::fromFull(inPlane<Dim>(c));
            if (plasticOutOfPlane_) (*plasticOutOfPlane_)[i] = c(2, 2);
            (*plasticStrain_)[i] = epsP;
        }
        (*P_)[i] = inPlane<Dim>(P3);
        (*pressure_)[i] = pressure;
    });
    // The return's loss of every owned particle (ghosts are images): a conservation sum.
    if (updateState && plastic_)
        plasticDissipation_ += GlobalReduce::sum<double>(particles_->ownedCount(),
                                                         [&](std::size_t i) { return plasticLoss_[i]; });
}

template <int Dim>
void TlSphSolver<Dim>::makeMirrorGhosts() {
    if (!settings_.flag("mirrorGhosts")) return;
    const auto mirrors = boundaries_.referenceMirrors();
    if (mirrors.empty()) return;
    // Deep enough that a ghost within the support of a real particle has its whole support
    // (real and ghost) inside the extended body: its corrected gradient is then the mirror image
    // of its source's. The images are of the reference configuration, made once (planes in the
    // order written; images of images make the corners and edges).
    const double depth = 2.0 * kernel_->supportRadius(h_);
    const std::size_t n = X_->size();  // the real particles: owned, then the halo
    if (haloSize_ == 0) {
        ghosts_ = boundaries_.referenceImages(*X_, depth);
    } else {
        // The sources in global-id order, as a serial run's, so that the images come in its order.
        const auto& ids = particles_->globalId();
        std::vector<std::size_t> byId(n);
        std::iota(byId.begin(), byId.end(), std::size_t(0));
        std::sort(byId.begin(), byId.end(), [&](std::size_t a, std::size_t b) { return ids[a] < ids[b]; });
        std::vector<Vector<Dim>> X(n);
        for (std::size_t k = 0; k < n; ++k) X[k] = (*X_)[byId[k]];
        ghosts_ = boundaries_.referenceImages(X, depth);
        for (std::size_t& source : ghosts_.source) source = byId[source];
    }
    // A particle on a plane carries half (a quarter on an edge, ...) of its dual cell: the other
    // part is its own image's. In the extended body it is interior, so as a neighbour it counts
    // with its whole cell. (Its own equation is per unit volume and does not change.)
    for (std::size_t i = 0; i < n; ++i)
        for (const auto& mirror : mirrors)
            if (std::abs(mirror.plane->signedDistance((*X_)[i])) <= mirror.plane->tolerance()) V_[i] *= 2.0;
    for (std::size_t g = 0; g < ghosts_.size(); ++g) V_.push_back(V_[ghosts_.source[g]]);
    // Reactions of the planes reach the body through the ghosts: the internal forces no longer
    // sum to zero over the real particles, and projecting them would remove the reactions.
    // (Some rank has images: all agree.)
    if (globalSum(double(ghosts_.size())) > 0 && (projectMomentum_ || projectDissipation_)) {
        projectMomentum_ = projectDissipation_ = false;
        Log::info("Momentum projections off: the symmetry planes' mirror ghosts carry their reactions");
    }
    Log::info("Mirror ghosts: " + std::to_string(ghosts_.size()) + " reference images across " +
              std::to_string(mirrors.size()) + " symmetry/skew-symmetric planes (depth " +
              std::to_string(depth) + ")" + (Communicator::distributed() ? " on rank 0" : ""));
}

template <int Dim>
void TlSphSolver<Dim>::placeGhosts() {
    // Under MPI the halo first (what the pair loops read at a neighbour), the images after it.
    if (decomposition_) decomposition_->appendHalo(*particles_, haloFields_);
    if (ghosts_.empty()) return;
    // On the particle set's ghost range for the pair loops of one stage: every field copied from
    // its source (rho0, the material), then what the image changes. The pair loops read v, P, J
    // and rho0; X, F, H and the pressure are mapped too so that the range is a true image; the
    // plastic state and x keep their source's values (nothing reads them at a ghost; nor the
    // halo's F, H, pressure, which it does not carry).
    const std::size_t n = particles_->addGhosts(ghosts_.source, ghosts_.map);
    parallelFor(ghosts_.size(), [&](std::size_t g) {
        const std::size_t i = n + g, src = ghosts_.source[g];
        (*X_)[i] = ghosts_.position[g];
        v_[i] = ghosts_.reflectVector(g, v_[src]);
        (*P_)[i] = ghosts_.reflectTensor(g, (*P_)[src]);
        (*pressure_)[i] = ghosts_.reflectScalar(g, (*pressure_)[src]);
        (*F_)[i] = ghosts_.reflectDeformation(g, (*F_)[src]);
        if (H_) (*H_)[i] = ghosts_.reflectDeformation(g, (*H_)[src]);
        if (J_) (*J_)[i] = ghosts_.reflectJacobian(g, (*J_)[src]);
    });
}

template <int Dim>
template <class T, class Map>
void TlSphSolver<Dim>::imagesOf(std::vector<T>& field, std::size_t n, Map&& map) const {
    const std::size_t real = n + haloSize_;
    field.resize(real + ghosts_.size());
    if (decomposition_) decomposition_->refresh(field.data(), sizeof(T), n);
    parallelFor(ghosts_.size(), [&](std::size_t g) { field[real + g] = map(g, field[ghosts_.source[g]]); });
}

template <int Dim>
void TlSphSolver<Dim>::computeDisplacementGradient() {
    const auto& rows = operators_->neighbours();
    const auto& g = operators_->gradient();
    const auto& offsets = rows.offsets();
    const std::size_t n = x_.size();
    std::vector<Vector<Dim>> u(n);
    for (std::size_t i = 0; i < n; ++i) u[i] = x_[i] - (*X_)[i];
    imagesOf(u, n, [&](std::size_t g, const Vector<Dim>& a) { return ghosts_.reflectVector(g, a); });
    auto& F = *F_;
    parallelForWork(n, offsets[n], [&](std::size_t a) {
        Tensor<Dim> grad = Tensor<Dim>::Zero();
        for (std::size_t k = offsets[a]; k < offsets[a + 1]; ++k)
            grad += V_[rows.indices()[k]] * (u[rows.indices()[k]] - u[a]) * g[k].transpose();
        F[a] = Tensor<Dim>::Identity() + grad;
    });
}

template <int Dim>
void TlSphSolver<Dim>::computeRates(const std::vector<Vector<Dim>>& xTilde, double t) {
    // P of the state the step starts from was computed at the end of the last step (or at
    // set-up): the first stage reuses it.
    if (!stressCurrent_) {
        if (formulation_.displacementBased()) computeDisplacementGradient();
        computeStress(false);
    }
    stressCurrent_ = false;
    auto rateTime = phase("computeRates");
    const std::size_t n = x_.size();  // the owned particles (ghosts are placed below)
    const auto& rows = operators_->neighbours();
    const auto& offsets = rows.offsets();
    const auto& g = operators_->gradient();
    const auto& gAtNeighbour = operators_->gradientAtNeighbour();
    const auto& lap = operators_->laplacian();
    // Real particles first, then their mirror images on the ghost range (none without symmetry
    // planes), for the pair loop only.
    placeGhosts();
    const Vector<Dim>* v = v_.data();
    const Tensor<Dim>* P = P_->data();
    const double* J = J_ ? J_->data() : nullptr;
    const double* rho0 = rho0_.data();
    const bool lapMomentum = !lapP_.empty(), lapJacobian = !lapJ_.empty();
    // The particles whose motion is prescribed in every direction are outside the operators of
    // D(J) (updateKinematic: why).
    if (lapJacobian) updateKinematic(t);
    const char* kinematic = kinematic_.empty() ? nullptr : kinematic_.data();
    const bool lapJacobianHere = lapJacobian && !freeOperators_;
    const bool evolveF = formulation_.evolvesF();
    std::vector<Vector<Dim>> force(n);
    stageWork_.resize(n);
    parallelForWork(n, offsets[n], [&](std::size_t a) {
        Tensor<Dim> G = Tensor<Dim>::Zero();
        Vector<Dim> T = Vector<Dim>::Zero();
        Vector<Dim> Lp = Vector<Dim>::Zero();
        double LJ = 0;
        const Vector<Dim> pa = rho0[a] * v[a];
        for (std::size_t k = offsets[a]; k < offsets[a + 1]; ++k) {
            const std::size_t b = rows.indices()[k];
            const double Vb = V_[b];
            G += Vb * (v[b] - v[a]) * g[k].transpose();
            T += Vb * (P[b] * gAtNeighbour[k] - P[a] * g[k]);
            if (lapMomentum) Lp += Vb * lap[k] * (rho0[b] * v[b] - pa);
            if (lapJacobianHere && !(kinematic && kinematic[b])) LJ += Vb * lap[k] * (J[b] - J[a]);
        }
        force[a] = -T;
        stageWork_[a] = m_[a] / rho0[a] * v[a].dot(force[a]);
        if (evolveF) dFdt_[a] = G;
        if (H_ || J_) {
            const Tensor<3> G3 = embed<Dim>(G, 0.0);
            if (H_) dHdt_[a] = inPlane<Dim>(tensorCross(embed<Dim>((*F_)[a], 1.0), G3));
            if (J_) dJdt_[a] = cofactor3(a).cwiseProduct(G3).sum();
        }
        if (lapMomentum) lapP_[a] = Lp;
        if (lapJacobianHere) lapJ_[a] = (kinematic && kinematic[a]) ? 0.0 : LJ;
    });
    particles_->clearGhosts();
    pairInteractions_ += double(offsets[n]);
    rateTime.stop();

    // Dissipation: the operators the model asked for, then D(p), D(J) from its evaluate().
    auto dissipationTime = phase("dissipation");
    std::vector<Vector<Dim>> dissipationP;
    std::vector<double> dissipationJ;
    if (freeOperators_) freeJacobianLaplacians();
    const bool lap2JHere = !lap2J_.empty() && !freeOperators_;
    if (!lap2P_.empty() || lap2JHere) {
        // The Laplacians at the ghosts: their sources' mapped (lapP_, lapJ_ hold n + ghosts).
        if (!lap2P_.empty())
            imagesOf(lapP_, n,
                     [&](std::size_t g, const Vector<Dim>& a) { return ghosts_.reflectVector(g, a); });
        if (lap2JHere)
            imagesOf(lapJ_, n, [&](std::size_t g, double a) { return ghosts_.reflectScalar(g, a); });
        const Vector<Dim>* Lp = lap2P_.empty() ? nullptr : lapP_.data();
        const double* LJ = lap2JHere ? lapJ_.data() : nullptr;
        const auto& mirror = operators_->mirror();
        const char* kinematic = kinematic_.empty() ? nullptr : kinematic_.data();
        parallelForWork(n, offsets[n], [&](std::size_t a) {
            Vector<Dim> L2p = Vector<Dim>::Zero();
            double L2J = 0;
            // Two loops, not one with both terms: the J term's test of each neighbour kept the
            // compiler from the momentum loop's tight form (the dissipation phase took 0.50 s
            // instead of 0.30 s on bench/tlSph/twistingColumn, which has no J term).
            if (Lp)
                for (std::size_t k = offsets[a]; k < offsets[a + 1]; ++k) {
                    const std::size_t b = rows.indices()[k];
                    L2p += V_[b] * lap[k] * (Lp[b] - Lp[a]);
                }
            if (LJ)
                for (std::size_t k = offsets[a]; k < offsets[a + 1]; ++k) {
                    const std::size_t b = rows.indices()[k];
                    // L*[L[J]]: the V-adjoint of L (its weight at b's row, lap[mirror[k]]) on L[J].
                    if (!(kinematic && kinematic[b]))
                        L2J += V_[b] * (lap[mirror[k]] * LJ[b] - lap[k] * LJ[a]);
                }
            if (!lap2P_.empty()) lap2P_[a] = L2p;
            if (lap2JHere) lap2J_[a] = L2J;
        });
    }
    {
        // The model sees its block as plain arrays (a vector is Dim contiguous doubles).
        static_assert(sizeof(Vector<Dim>) == Dim * sizeof(double), "Vector<Dim> must be Dim packed doubles");
        auto raw = [](const auto& v) {
            return v.empty() ? nullptr : reinterpret_cast<const double*>(v.data());
        };
        TlDissipation::Block block;
        block.size = n, block.dimension = Dim;
        block.waveSpeed = cpMax_, block.shearSpeed = csMax_, block.spacing = spacing_;
        block.rho0 = rho0_.data();
        block.lapP = raw(lapP_), block.lap2P = raw(lap2P_);
        block.lapJ = raw(lapJ_), block.lap2J = raw(lap2J_);
        if (dissipationModel_->actsOnMomentum()) {
            dissipationP.assign(n, Vector<Dim>::Zero());
            block.dissipationP = reinterpret_cast<double*>(dissipationP.data());
        }
        if (J_ && dissipationModel_->actsOnJacobian()) {
            dissipationJ.assign(n, 0.0);
            block.dissipationJ = dissipationJ.data();
        }
        if (n && (block.dissipationP || block.dissipationJ)) dissipationModel_->evaluate(block);
    }
    dissipationTime.stop();

    // Conservation projections (linear in the force: projecting the sum is the sum of the
    // projections, so one solve serves both when both are on).
    auto projectionTime = phase("projections");
    if (!dissipationP.empty()) {
        if (projectMomentum_ == projectDissipation_) {
            parallelFor(n, [&](std::size_t a) { force[a] += dissipationP[a]; });
            if (projectMomentum_) MomentumProjection<Dim>::momentum(force, V_, xTilde);
        } else {
            if (projectMomentum_) MomentumProjection<Dim>::momentum(force, V_, xTilde);
            if (projectDissipation_) MomentumProjection<Dim>::momentum(dissipationP, V_, xTilde);
            parallelFor(n, [&](std::size_t a) { force[a] += dissipationP[a]; });
        }
    } else if (projectMomentum_) {
        MomentumProjection<Dim>::momentum(force, V_, xTilde);
    }
    if (!dissipationJ.empty()) {
        if (!kinematic_.empty())
            parallelFor(n, [&](std::size_t a) {
                if (kinematic_[a]) dissipationJ[a] = 0;
            });
        if (projectJacobian_) MomentumProjection<Dim>::mean(dissipationJ, V_, kinematic_);
        const double* pressure = pressure_->data();
        const std::int64_t* material = material_->data();
        parallelFor(n, [&](std::size_t a) {
            dJdt_[a] += dissipationJ[a];
            // Sigma_J D(J) (readMaterials: jacobianWork_); -1 leaves it in the imbalance.
            if (jacobianWork_[std::size_t(material[a])] == 1)
                stageWork_[a] -= m_[a] / rho0_[a] * pressure[a] * dissipationJ[a];
        });
    }
    projectionTime.stop();

    // External forces, then the essential boundary conditions on the rate.
    if (!boundaries_.empty()) {
        boundaryForce_.assign(n, Vector<Dim>::Zero());
        boundaries_.addBoundaryForces(*particles_, boundaryForce_, t);
    }
    parallelFor(n, [&](std::size_t a) {
        Vector<Dim> bodyAcceleration = Vector<Dim>::Zero();
        if (bodyForce_) bodyForce_->acceleration(x_[a].data(), t, bodyAcceleration.data());
        Vector<Dim> f = force[a] + rho0_[a] * bodyAcceleration;
        if (!boundaryForce_.empty()) f += boundaryForce_[a] / V_[a];
        acceleration_[a] = f / rho0_[a];
    });
    if (!boundaries_.empty()) boundaries_.constrainAcceleration(*particles_, acceleration_, t);
    if (essential_) {
        // The set of constraints changes when a condition is released: build the projection again.
        bool changed = false;
        for (std::size_t k = 0; k < boundaries_.size(); ++k)
            changed = changed || (boundaries_[k].active(essentialTime_) != boundaries_[k].active(t));
        if (changed) {
            essentialTime_ = t;
            essential_ = std::make_unique<LagrangeMultiplierProjection<Dim>>(
                *operators_, V_, constraintsFrom(boundaries_, *particles_, t), n);
        }
        std::vector<Vector<Dim>> rate(n);
        parallelFor(n, [&](std::size_t a) { rate[a] = rho0_[a] * acceleration_[a]; });
        essential_->project(rate, prescribedRates(boundaries_, essential_->constraints(), rho0_, t));
        parallelFor(n, [&](std::size_t a) { acceleration_[a] = rate[a] / rho0_[a]; });
    }
    // The power of what is not the internal force (body forces, tractions, the reactions of the
    // essential conditions) at this stage's velocity: the energy-growth check's input and the
    // budget's external work. With it, in the same pass, the budget's dissipation power: what the
    // projected force -T + D(p) and D(J) put into K + U beyond -T's own, with a minus sign.
    const auto powers = GlobalReduce::sum<SumArray<2>>(n, [&](std::size_t a) {
        SumArray<2> s;
        s.s[0] = m_[a] * (acceleration_[a] - force[a] / rho0_[a]).dot(v_[a]);
        s.s[1] = stageWork_[a] - m_[a] / rho0_[a] * v_[a].dot(force[a]);
        return s;
    });
    stagePower_ = powers.s[0];
    stageDissipation_ = powers.s[1];
}

template <int Dim>
void TlSphSolver<Dim>::updateKinematic(double t) {
    // A clamped particle (a fixed condition: the rigid clamp, not the body) keeps J = det F: D(J)
    // neither acts on it nor reads it. (Not a prescribedVelocity face: it moves with the body and
    // its strain is the body's; the nearly incompressible punch's pressure oscillation is 0.218
    // with its punched face in D(J), 0.256 without, 0.222 before the fix.) Measured on the oscillating plate ({p,F,J},
    // nu = 0.45, jacobian (0 0.125), dx = 4 mm): with D(J) on the clamped particles their J
    // drifted from det F = 1 with nothing to restore it (J <= 0 at t = 0.103 s before the fix);
    // with D(J) only off there but the clamp still read by L[J] (Dirichlet data), the energy grew
    // 11% in 0.27 s; with the clamp outside L and L* altogether it falls 3.7% (the {p,F} plate
    // 0.9%). The operators on the free body make L exact on linear J at the clamp's face again.
    if (boundaries_.empty()) return;
    bool changed = !kinematicBuilt_;
    for (std::size_t k = 0; k < boundaries_.size(); ++k)
        changed = changed || (boundaries_[k].active(kinematicTime_) != boundaries_[k].active(t));
    if (!changed) return;
    kinematicBuilt_ = true;
    kinematicTime_ = t;
    // Called with the ghosts placed: the owned count is the set's, not the size of x.
    const std::size_t n = particles_->ownedCount(), real = n + haloSize_, all = real + ghosts_.size();
    kinematic_.assign(all, 0);
    double any = 0;
    for (std::size_t k = 0; k < boundaries_.size(); ++k)
        if (boundaries_[k].active(t) && dynamic_cast<const Fixed<Dim>*>(&boundaries_[k]))
            for (const std::size_t i : boundaries_[k].selection().indices()) kinematic_[i] = 1, any = 1;
    if (decomposition_) decomposition_->refresh(kinematic_.data(), 1, n);
    for (std::size_t g = 0; g < ghosts_.size(); ++g) kinematic_[real + g] = kinematic_[ghosts_.source[g]];
    freeOperators_.reset();
    free_.clear();
    if (globalSum(any) == 0) {  // on no rank: every rank alike
        kinematic_.clear();
        return;
    }
    const std::vector<Vector<Dim>>& Xall = operators_->referencePositions();
    std::vector<Vector<Dim>> X;
    std::vector<double> V;
    typename ReferenceOperators<Dim>::Options options;
    options.laplacian = true;
    for (std::size_t i = 0; i < all; ++i)
        if (!kinematic_[i]) {
            free_.push_back(i);
            X.push_back(Xall[i]);
            V.push_back(V_[i]);
            if (!order_.empty()) options.order.push_back(order_[i]);
        }
    if (decomposition_)
        options.interior = std::size_t(std::lower_bound(free_.begin(), free_.end(), n) - free_.begin());
    std::string failure;
    try {
        freeOperators_ = std::make_unique<ReferenceOperators<Dim>>(X, V, h_, *kernel_, options);
    } catch (const Error& e) {
        failure = e.what();
    }
    // A free particle with too few free neighbours: D(J) keeps the body's operators, the
    // kinematic particles left out of its sums (not exact on linear J at the clamp's face). On
    // every rank when on one.
    if (globalSum(failure.empty() ? 0.0 : 1.0) > 0) {
        Log::warning(
            "D(J) on the operators of the whole body: those of the free particles could not be built (" +
            GlobalReduce::firstMessage(failure.empty() ? noMessageKey : Communicator::rank(), failure) + ")");
        freeOperators_.reset();
    }
}

template <int Dim>
void TlSphSolver<Dim>::freeJacobianLaplacians() {
    // L[J] and L*[L[J]] on the free body (free_ indexes n + ghosts; ghosts carry their sources'
    // images), written to lapJ_, lap2J_ of the real free particles (0 at the kinematic ones).
    const std::size_t n = x_.size(), m = free_.size();
    const auto& ops = *freeOperators_;
    std::vector<double> J(*J_);  // owned, then the halo and the images
    imagesOf(J, n, [&](std::size_t g, double a) { return ghosts_.reflectJacobian(g, a); });
    std::vector<double> Jfree(m);
    parallelFor(m, [&](std::size_t s) { Jfree[s] = J[free_[s]]; });
    const std::vector<double> L = ops.laplacianOf(Jfree);
    std::fill(lapJ_.begin(), lapJ_.begin() + n, 0.0);
    if (!lap2J_.empty()) std::fill(lap2J_.begin(), lap2J_.end(), 0.0);
    const auto& rows = ops.neighbours();
    const auto& offsets = rows.offsets();
    const auto& lap = ops.laplacian();
    const auto& mirror = ops.mirror();
    const auto& V = ops.volume();
    parallelFor(m, [&](std::size_t s) {
        const std::size_t i = free_[s];
        if (i >= n) return;
        lapJ_[i] = L[s];
        if (lap2J_.empty()) return;
        double L2 = 0;
        for (std::size_t k = offsets[s]; k < offsets[s + 1]; ++k) {
            const std::size_t b = rows.indices()[k];
            L2 += V[b] * (lap[mirror[k]] * L[b] - lap[k] * L[s]);
        }
        lap2J_[i] = L2;
    });
}

template <int Dim>
TimeStepVote TlSphSolver<Dim>::stableTimeStep() {
    if (!currentWaveSpeed_) return {courant() * spacing_ / cpMax_, "CFL (maxCo h / c_p)"};
    // In the reference configuration a deformed body carries waves faster than c_p: the
    // volumetric stiffness enters the acoustic tensor as kappa (H N)(H N)^T / rho0 and the shear
    // part as mu (F^T F)-scaled terms, so the reference wave speed grows like the largest
    // singular value of H (lateral stretch of a compressed direction) or of F. The step follows
    // c_p max_a max(sigma_max(F_a), sigma_max(H_a)), never below the small-strain c_p.
    // A time-step vote: every rank must step with the same dt, so the stretch is global. The
    // particle it names (for the health check's diagnosis of a collapsed step) is the one of
    // largest stretch, of lowest global id among equals: one more global reduction.
    const std::size_t n = x_.size();
    stretch_.resize(n);
    parallelFor(n, [&](std::size_t i) {
        const Tensor<3> F3 = embed<Dim>((*F_)[i], 1.0);
        const Tensor<3> H3 = cofactor3(i);
        Eigen::SelfAdjointEigenSolver<Tensor<3>> f, h;
        f.computeDirect(F3.transpose() * F3, Eigen::EigenvaluesOnly);
        h.computeDirect(H3.transpose() * H3, Eigen::EigenvaluesOnly);
        stretch_[i] = std::sqrt(std::max(f.eigenvalues().maxCoeff(), h.eigenvalues().maxCoeff()));
    });
    const double stretch = GlobalReduce::max(n, [&](std::size_t i) { return stretch_[i]; });
    const double factor = std::max(1.0, stretch);
    std::int64_t particle = -1;
    if (factor > 1) {  // at factor 1 the undeformed c_p limits, no particle
        const auto& ids = particles_->globalId();
        const double id = GlobalReduce::min(n, [&](std::size_t i) {
            return stretch_[i] == stretch ? double(ids[i]) : std::numeric_limits<double>::infinity();
        });
        if (std::isfinite(id)) particle = std::int64_t(id);
    }
    if (!deformedCourant_)
        return {courant() * spacing_ / (cpMax_ * factor),
                factor > 1.0001 ? "CFL (maxCo h / c_p, deformed: c_p x " + std::to_string(factor) + ")"
                                : std::string("CFL (maxCo h / c_p)"),
                particle};
    // deformedCourant: the undeformed c_p at maxCo (the paper's alpha_CFL), the deformed wave speed
    // c_p x stretch at its own Courant number. Measured on the Taylor bar (its README): the stretch
    // peaks on the axis at the impact face (the stagnation core's axial compression, 10.75), and
    // with the reference c_p that core inverts once c_p x stretch x dt / h reaches 2.0-2.4 (maxCo
    // 0.2 and 0.3): at most 1 keeps a margin of 2, where the old step kept the deformed Courant
    // number at maxCo, 7 times below it, at 3.3 times the steps.
    const double deformed = *deformedCourant_ * spacing_ / (cpMax_ * factor);
    const double undeformed = courant() * spacing_ / cpMax_;
    if (undeformed <= deformed) return {undeformed, "CFL (maxCo h / c_p)"};
    return {deformed, "CFL (deformedCourant h / (c_p x " + std::to_string(factor) + "))", particle};
}

template <int Dim>
void TlSphSolver<Dim>::step(double dt) {
    const std::size_t n = x_.size();
    const double t = time().value();
    // The end of the step as seen by the boundary conditions: its left limit, so that a condition
    // released at t + dt (a releaseTime the time control lands on) still acts over the whole
    // step, as it does for the exact solution, instead of half of it in the trapezoidal stage 2.
    const double tEnd = std::nextafter(t + dt, t);
    x0_ = x_, v0_ = v_;
    if (formulation_.evolvesF()) F0_ = *F_;
    if (H_) H0_ = *H_;
    if (J_) J0_ = *J_;
    const bool evolveF = formulation_.evolvesF();
    if (!energyStart_) {
        energyStart_ = totalEnergy();
        energyInput_ = *energyStart_;
        startSpeed_ = GlobalReduce::max(n, [&](std::size_t i) { return v_[i].norm(); });
    }

    // Stage 1: U* = U^n + dt U'(U^n), moments about x~ = x^n.
    computeRates(x0_, t);
    const double power1 = stagePower_, dissipation1 = stageDissipation_;
    auto integrateTime = phase("integrate");
    parallelFor(n, [&](std::size_t i) {
        x_[i] = x0_[i] + dt * v0_[i];
        v_[i] = v0_[i] + dt * acceleration_[i];
        if (evolveF) (*F_)[i] += dt * dFdt_[i];
        if (H_) (*H_)[i] += dt * dHdt_[i];
        if (J_) (*J_)[i] += dt * dJdt_[i];
    });
    if (!boundaries_.empty()) {
        boundaries_.constrainVelocity(*particles_, v_, tEnd);
        boundaries_.constrainPosition(*particles_, tEnd);
    }
    // x~ = x^n + dt/2 (v^n + v*) = x^{n+1}.
    std::vector<Vector<Dim>> xTilde(n);
    parallelFor(n, [&](std::size_t i) { xTilde[i] = x0_[i] + 0.5 * dt * (v0_[i] + v_[i]); });
    integrateTime.stop();
    checkState("stage 1");

    // Stage 2 and the average: U^{n+1} = (U^n + U* + dt U'(U*)) / 2.
    computeRates(xTilde, tEnd);
    externalWork_ += 0.5 * dt * (power1 + stagePower_);
    schemeDissipation_ += 0.5 * dt * (dissipation1 + stageDissipation_);
    energyInput_ = std::max(energyInput_, *energyStart_ + externalWork_);
    integrateTime.resume();
    parallelFor(n, [&](std::size_t i) {
        x_[i] = 0.5 * (x0_[i] + x_[i] + dt * v_[i]);
        v_[i] = 0.5 * (v0_[i] + v_[i] + dt * acceleration_[i]);
        if (evolveF) (*F_)[i] = 0.5 * (F0_[i] + (*F_)[i] + dt * dFdt_[i]);
        if (H_) (*H_)[i] = 0.5 * (H0_[i] + (*H_)[i] + dt * dHdt_[i]);
        if (J_) (*J_)[i] = 0.5 * (J0_[i] + (*J_)[i] + dt * dJdt_[i]);
    });
    if (!boundaries_.empty()) {
        boundaries_.constrainVelocity(*particles_, v_, tEnd);
        boundaries_.constrainPosition(*particles_, tEnd);
    }
    integrateTime.stop();
    // P^{n+1} for the output and the plastic state that goes with it.
    if (formulation_.displacementBased()) computeDisplacementGradient();
    computeStress(true);
    stressCurrent_ = true;
    checkState("step");
    if (++stepsSinceEnergyCheck_ >= 10) {
        stepsSinceEnergyCheck_ = 0;
        checkEnergyGrowth();
    }
}

template <int Dim>
double TlSphSolver<Dim>::totalEnergy() const {
    const double kinetic = GlobalReduce::sum<double>(
        x_.size(), [&](std::size_t i) { return 0.5 * m_[i] * v_[i].squaredNorm(); });
    return kinetic + internalEnergy().value_or(0.0);
}

template <int Dim>
void TlSphSolver<Dim>::checkEnergyGrowth() const {
    // Global sums: every rank reaches the same verdict and, if it trips, calls checkState with it.
    const std::size_t n = x_.size();
    const double kinetic =
        GlobalReduce::sum<double>(n, [&](std::size_t i) { return 0.5 * m_[i] * v_[i].squaredNorm(); });
    const double internal = internalEnergy().value_or(0.0);
    const double energy = kinetic + internal;
    const bool grown = energyInput_ > 0 && energy > energyGrowthLimit_ * energyInput_;
    if (std::isfinite(energy) && !grown) return;
    const double fastest = GlobalReduce::max(n, [&](std::size_t i) { return v_[i].norm(); });
    auto bad = [&](std::size_t i) { return v_[i].norm() == fastest || !v_[i].allFinite(); };
    Solver::checkState("energyGrowth", n, bad, [&](std::size_t i, double) {
        std::ostringstream s;
        s.precision(4);
        s << "the total energy (kinetic + internal) grew to " << energy << " J";
        if (energyInput_ > 0) s << ", " << energy / energyInput_ << " times";
        s << " the energy put in " << energyInput_ << " J (the initial " << *energyStart_
          << " J plus the work of the boundary conditions and body forces, " << externalWork_
          << " J), above energyGrowthLimit " << energyGrowthLimit_
          << " (constant/tlSphProperties): the scheme is unstable.\n"
          << "    Now: kinetic " << kinetic << " J, internal " << internal << " J.\n"
          << "    Fastest particle: global id " << particles_->globalId()[i] << " (reference position "
          << (*X_)[i].transpose() << ", material " << materials_->names()[(*material_)[i]]
          << "), field velocity |v| = " << v_[i].norm() << " m/s (the fastest at the start " << startSpeed_
          << " m/s), J = " << (J_ ? (*J_)[i] : (*F_)[i].determinant()) << ", |F| = " << (*F_)[i].norm()
          << ".\n"
          << "    Remedies (this run: formulation " << formulation_.name() << ", maxCo " << courant()
          << ", dissipation " << dissipationModel_->describe()
          << "): reduce the Courant number (maxCo in system/controlDict; the TVD RK2 with JST needs "
             "eps4 > maxCo^3/8, and the oscillating plate with eps4 1/8 is stable at maxCo 0.5, not "
             "0.6); check the dissipation (constant/tlSphProperties: the momentum eps4, and with "
             "momentumSpeed shear a jacobian eps4 for the pressure waves); if the energy comes from "
             "a source the check does not count, raise energyGrowthLimit.";
        return s.str();
    });
    // No particle to name (a speed that is not a number nowhere in v): the verdict all the same.
    throw RunError("phase energyGrowth, t = " + std::to_string(time().value()) + ": the total energy is " +
                   std::to_string(energy) + " against the energy put in " + std::to_string(energyInput_) +
                   " (energyGrowthLimit " + formatKeywordNumber(energyGrowthLimit_) +
                   "): the scheme is unstable; reduce maxCo or check the dissipation");
}

template <int Dim>
void TlSphSolver<Dim>::checkState(const char* phaseName) const {
    auto jacobian = [&](std::size_t i) { return J_ ? (*J_)[i] : (*F_)[i].determinant(); };
    auto bad = [&](std::size_t i) {
        return !x_[i].allFinite() || !v_[i].allFinite() || !(*F_)[i].allFinite() || !(jacobian(i) > 0) ||
               !(*P_)[i].allFinite();
    };
    Solver::checkState(phaseName, x_.size(), bad, [&](std::size_t i, double count) {
        std::ostringstream s;
        s.precision(6);
        s << "particle " << particles_->globalId()[i] << " (reference position " << (*X_)[i].transpose()
          << ", material " << materials_->names()[(*material_)[i]] << ") has J = " << jacobian(i)
          << ", |v| = " << v_[i].norm() << ", |F| = " << (*F_)[i].norm() << "; " << count
          << " particles affected.\n    ";
        if (!(jacobian(i) > 0) && std::isfinite(jacobian(i))) {
            // The remedies this run has not taken yet (issue 16: the advice named pFJ to a pFJ run).
            s << "The deformation has inverted the particle (J <= 0): hourglass modes or a too coarse "
                 "discretisation of a large local deformation.";
            if (J_) {
                const double detF = embed<Dim>((*F_)[i], 1.0).determinant();
                s << " Its evolved J " << jacobian(i) << " against det F " << detF
                  << (std::abs(jacobian(i) - detF) > 0.1 * std::abs(detF)
                          ? ": J has left its F (the jacobian coefficients of the dissipation drive it)."
                          : ".");
            }
            std::vector<std::string> remedies;
            if (dissipationModel_->actsOnMomentum())
                remedies.push_back("raise the momentum eps4 of the dissipation (constant/tlSphProperties)");
            else
                remedies.push_back("stabilise the momentum (dissipation { type jst; momentum (0 0.125); })");
            if (!J_)
                remedies.push_back("near incompressibility use formulation pFJ with jacobian (0 0.125)");
            else if (!dissipationModel_->actsOnJacobian())
                remedies.push_back("smooth J: jacobian (0 0.125) in the dissipation");
            remedies.push_back("refine the lattice");
            if (courant() > 0.1) remedies.push_back("reduce maxCo (system/controlDict)");
            s << " Remedies (this run: formulation " << formulation_.name() << ", maxCo " << courant()
              << "): ";
            for (std::size_t k = 0; k < remedies.size(); ++k) s << (k ? "; " : "") << remedies[k];
            s << ".";
        } else
            s << "The state is no longer finite: the step is unstable (maxCo " << courant()
              << "; JST eps4 must exceed maxCo^3/8), or a boundary condition drives the body "
                 "faster than the material can carry.";
        return s.str();
    });
}

template <int Dim>
std::optional<double> TlSphSolver<Dim>::internalEnergy() const {
    const std::size_t n = x_.size();
    std::vector<double> w(n, 0.0);
    parallelFor(n, [&](std::size_t i) {
        const Tensor<3> F3 = embed<Dim>((*F_)[i], 1.0);
        const Tensor<3> H3 = cofactor3(i);
        const double J = J_ ? (*J_)[i] : F3.determinant();
        Tensor<3> P3;
        SymmTensor<3> cp;
        double epsP = 0;
        ConstitutiveLaw::Fields f;
        f.size = 1, f.F = &F3, f.H = &H3, f.J = &J, f.P = &P3, f.energyDensity = &w[i];
        const auto& law = this->law((*material_)[i]);
        if (law.usesPlasticState()) {
            cp = SymmTensor<3>::fromFull(embed<Dim>((*plasticDeformation_)[i].full(),
                                                    plasticOutOfPlane_ ? (*plasticOutOfPlane_)[i] : 1.0));
            epsP = (*plasticStrain_)[i];
            f.plasticState = &cp, f.plasticStrain = &epsP;
        }
        if (!splitJacobian_.empty() && splitJacobian_[(*material_)[i]]) {
            // W(F, det F) + U(J) - U(det F), U(J) - U(det F) = (p(J) + p(det F))/2 (J - det F)
            // (exact for the laws' U = kappa/2 (J - 1)^2).
            const double detF = F3.determinant();
            const SymmTensor<3> cpBefore = cp;
            double pF = 0, pJ = 0, wJ = 0;
            f.J = &detF, f.pressure = &pF;
            law.stress(f, false);
            cp = cpBefore;
            f.J = &J, f.pressure = &pJ, f.energyDensity = &wJ;
            law.stress(f, false);
            w[i] += 0.5 * (pJ + pF) * (J - detF);
            return;
        }
        law.stress(f, false);
    });
    // A conservation sum over the whole body (the energy balance of conservedQuantities).
    return GlobalReduce::sum<double>(n, [&](std::size_t i) { return m_[i] / rho0_[i] * w[i]; });
}

template <int Dim>
double TlSphSolver<Dim>::pressureOscillation() const {
    const std::size_t n = x_.size();
    std::vector<double> p(*pressure_);
    imagesOf(p, n, [&](std::size_t g, double a) { return ghosts_.reflectScalar(g, a); });
    const auto lap = operators_->laplacianOf(p);
    // Figures of the whole body for the summary: global sums and maxima (here and below).
    const double num = GlobalReduce::sum<double>(
        n, [&](std::size_t i) { return V_[i] * std::abs(lap[i]) * spacing_ * spacing_; });
    const double den =
        GlobalReduce::sum<double>(n, [&](std::size_t i) { return V_[i] * std::abs((*pressure_)[i]); });
    return den > 0 ? num / den : 0.0;
}

template <int Dim>
double TlSphSolver<Dim>::compatibilityError() const {
    std::vector<Vector<Dim>> u(x_.size());
    for (std::size_t i = 0; i < u.size(); ++i) u[i] = x_[i] - (*X_)[i];
    const std::size_t n = u.size();
    imagesOf(u, n, [&](std::size_t g, const Vector<Dim>& a) { return ghosts_.reflectVector(g, a); });
    const auto grad = operators_->gradientOf(u);
    return GlobalReduce::max(n, [&](std::size_t i) {
        return ((*F_)[i] - Tensor<Dim>::Identity() - grad[i]).norm() / std::max(1.0, (*F_)[i].norm());
    });
}

template <int Dim>
std::vector<HealthIndicator> TlSphSolver<Dim>::healthIndicators() const {
    // Each: the worst value over the owned particles, how many are past the threshold, and the
    // worst one's global id (the lowest among equals): global reductions, the same on every rank.
    const std::size_t n = x_.size();
    const auto& ids = particles_->globalId();
    auto indicator = [&](std::string name, const std::vector<double>& value, bool largest, double threshold,
                         std::string definition) {
        HealthIndicator h;
        h.name = std::move(name);
        h.definition = std::move(definition);
        auto past = [&](std::size_t i) { return largest ? value[i] > threshold : value[i] < threshold; };
        h.value = largest ? GlobalReduce::max(n, [&](std::size_t i) { return value[i]; })
                          : GlobalReduce::min(n, [&](std::size_t i) { return value[i]; });
        h.count =
            std::size_t(GlobalReduce::sum<double>(n, [&](std::size_t i) { return past(i) ? 1.0 : 0.0; }));
        const double id = GlobalReduce::min(n, [&](std::size_t i) {
            return value[i] == h.value ? double(ids[i]) : std::numeric_limits<double>::infinity();
        });
        h.worst = std::isfinite(id) ? std::int64_t(id) : -1;
        return h;
    };
    const auto& rows = operators_->neighbours();
    const std::vector<Vector<Dim>>& X = operators_->referencePositions();  // real, then ghosts
    std::vector<double> value(n);
    std::vector<HealthIndicator> indicators;

    // The pair's deviation from its particle's deformation (TlSphHealth.hpp). Threshold 0.2: a
    // smooth deformation gives |grad F| |X_ab| / 2, so 0.2 is F changing by 20% over the support
    // radius, or a zero-energy mode of a tenth of the spacing: either the lattice no longer resolves
    // the motion. Measured (tests/cases/health/tlSph.sh): the oscillating plate at 4 mm peaks at
    // 0.003; the spinning cube on its 6^3 lattice (stretched 23% by the spin) at 0.18 with JST
    // (0.11 on 11^3), and without JST, its hourglass modes free, at 0.27-0.43.
    // x of the owned particles and the halo (the images' is not kept).
    std::vector<Vector<Dim>> x(x_);
    if (decomposition_) {
        x.resize(n + haloSize_);
        decomposition_->refresh(x.data(), sizeof(Vector<Dim>), n);
    }
    parallelForWork(n, rows.offsets()[n], [&](std::size_t a) {
        value[a] = hourglassIndicator<Dim>(a, rows, X.data(), x.data(), (*F_)[a], n + haloSize_);
    });
    indicators.push_back(indicator(
        "hourglass", value, true, 0.2,
        "max over the reference neighbours b of |F_a X_ab - x_ab| / |X_ab|, the pair's deviation from its "
        "particle's own deformation (Ganzenmueller 2015, CMAME 286), 0 for an affine motion; above 0.2: "
        "F varies by 20% over the support, or a zero-energy mode of a tenth of the spacing"));

    // Of the reference configuration, which never changes: computed once.
    if (!neighbourDeficiency_) {
        // The corrected Laplacian's Dim + 1 unknowns (App. A) need as many neighbours; the tutorial
        // plate's corners (h = 1.1 dx) have 5 in 2D, the cube's (h = 1.3 dx) 19 in 3D.
        const int fewest = Dim + 1;
        std::vector<double> conditioning(n);
        parallelForWork(n, rows.offsets()[n], [&](std::size_t a) {
            conditioning[a] = rows.rowSize(a) < std::size_t(fewest)
                                  ? 0.0
                                  : correctionConditioning<Dim>(a, rows, X.data(), V_.data(), *kernel_, h_);
        });
        neighbourDeficiency_ = indicator(
            "neighbourDeficiency", conditioning, false, 0.01,
            "smallest reciprocal condition number sigma_min/sigma_max of the gradient correction matrix "
            "B_a = sum_b V_b grad W_b(X_a) (x) (X_b - X_a) in the reference configuration (0 below " +
                std::to_string(fewest) +
                " neighbours); 1 inside a lattice, about 0.3 at a cube's corner; below 0.01 the corrected "
                "gradient amplifies one direction a hundredfold (a sliver, a layer too thin for h)");
    }
    indicators.push_back(*neighbourDeficiency_);

    // Total-Lagrangian SPH has no tensile instability (its kernel lives in the reference
    // configuration: Belytschko, Guo, Liu & Xiao 2000, "A unified stability analysis of meshless
    // particle methods", IJNME 48:1359-1400; Rabczuk, Belytschko & Xiao 2004, "Stable particle
    // methods based on Lagrangian kernels", CMAME 193:1035-1063): its failure is the
    // inverted particle, J <= 0, which checkState stops at. This is its early warning: the threshold
    // 0.5, half the volume lost, is far from the few per cent of volumetric strain of the solids it
    // models (measured smallest J: the spinning cube 0.98, the oscillating plate 0.999).
    parallelFor(n,
                [&](std::size_t i) { value[i] = J_ ? (*J_)[i] : embed<Dim>((*F_)[i], 1.0).determinant(); });
    indicators.push_back(indicator(
        "compression", value, false, 0.5,
        "smallest J (the evolved J, else det F); below 0.5 the particle has lost half its volume, on the "
        "way to an inverted particle (J <= 0 stops the run), where the solids modelled carry volumetric "
        "strains of a few per cent (the spinning cube's smallest J 0.98). Total-Lagrangian SPH has no "
        "tensile instability (kernels in the reference configuration: Belytschko et al. 2000; Rabczuk "
        "et al. 2004)"));
    return indicators;
}

template <int Dim>
std::vector<std::string> TlSphSolver<Dim>::summary(double loopSeconds) const {
    std::vector<std::string> lines;
    char line[200];
    // Of the whole body (every rank's owned rows; rank 0 prints).
    const double interactions = globalSum(pairInteractions_);
    const double owned = globalSum(double(x_.size()));
    const double pairs = globalSum(double(operators_->neighbours().offsets()[x_.size()]));
    std::snprintf(line, sizeof line,
                  "pair interactions/s  %.4g (%.1f neighbours per particle, 2 stages a step)",
                  loopSeconds > 0 ? interactions / loopSeconds : 0.0, owned > 0 ? pairs / owned : 0.0);
    lines.push_back(line);
    std::snprintf(line, sizeof line, "pressure oscillation  %.6g (sum V |L[p]| h^2 / sum V |p|)",
                  pressureOscillation());
    lines.push_back(line);
    if (formulation_.evolvesF()) {
        std::snprintf(line, sizeof line,
                      "compatibility        %.3e (max |F - I - grad~(x - X)| / max(1, |F|))",
                      compatibilityError());
        lines.push_back(line);
    }
    if (decomposition_) {
        // The communication of a stage (bench/mpi's weak-scaling model): the halo is refreshed
        // once per stage with haloFields_ (a message each, globalId first), plus L[p], L[J] where
        // the dissipation reads them; the set-up's halo is counted in.
        const double ranks = globalSum(1.0);
        const double halo = globalSum(double(haloSize_));
        const double bytes = globalSum(double(decomposition_->bytesSent()));
        const double messages = globalSum(double(decomposition_->messagesSent()));
        // Stages run: every stage adds the owned rows' pairs to pairInteractions_.
        const double stages = pairs > 0 ? std::round(interactions / pairs) : 0.0;
        std::snprintf(
            line, sizeof line,
            "decomposition        %.0f ranks (%s), cut once in X; halo %.0f particles (%.3g of the owned), "
            "two supports deep",
            ranks, decomposition_->partitioner().method().c_str(), halo, owned > 0 ? halo / owned : 0.0);
        lines.push_back(line);
        std::snprintf(
            line, sizeof line,
            "halo traffic         %.4g bytes per particle and %.3g messages per rank per stage (%.0f stages)",
            owned > 0 && stages > 0 ? bytes / owned / stages : 0.0,
            stages > 0 ? messages / ranks / stages : 0.0, stages);
        lines.push_back(line);
    }
    return lines;
}

template class TlSphSolver<1>;
template class TlSphSolver<2>;
template class TlSphSolver<3>;

MFDYN_REGISTER_SOLVER(TlSphSolver, "tlSph",
                      "Total-Lagrangian mixed {p,F,H,J} JST-SPH for large-strain solid dynamics");

}  // namespace mfdyn
