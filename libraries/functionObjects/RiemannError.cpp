// riemannError: a 1D run against the exact solution of its Riemann problem (two uniform states
// meeting at x0 at the start time; libraries/verification/RiemannSolver). For each field f of
// density, velocity, pressure, specificInternalEnergy, over the particles in [from, to] with
// weights w = m/ρ (their lengths):
//
//   L1 = Σ w|f − f_exact| / Σ w,   L2 = (Σ w (f − f_exact)² / Σ w)^½,   Linf = max |f − f_exact|
//
// written to errorNorms.csv. starState.csv compares the star pressure and velocity with the exact
// ones: the median over the particles between the left wave's tail and the right wave's head,
// leaving out 10% of that plateau's width at each end and around the contact (where SPH smears).
//
//     riemann
//     {
//         type riemannError;  x0 0.5;  interval (0 1);  fields (density velocity pressure);
//         left  { density 1;     velocity 0; pressure 1;   equationOfState { type idealGas; gamma 1.4; } }
//         right { density 0.125; velocity 0; pressure 0.1; equationOfState { type idealGas; gamma 1.4; } }
//     }
//
// In 2D and 3D the tube lies along x: the x components of position and velocity are compared, every
// particle of the cross-section counting (the finite pointset method's 3D tube, doc/methods/fpm.md
// §4.1). Where the right wave is a shock, shock.csv has its position: the largest x of a particle
// with p above the mean of the star and right pressures, beside the exact one (the summary's
// reference value shockPosition).
//
// equationOfState types: idealGas (gamma), stiffenedGas (gamma, pRef), linearBarotropic (rho0, c0).
#include "functionObjects/RiemannError.hpp"

#include "verification/ErrorNorms.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

namespace mfdyn {

namespace {

// The equation of state of one side, read with the keywords of its type: the exact solver's three
// laws, a subset of the equationOfState family.
RiemannEquationOfState readEos(const Dictionary& dict) {
    const KeywordValues type = KeywordSchema("functionObject", "riemannError equationOfState")
                                   .word("type", {"idealGas", "stiffenedGas", "linearBarotropic"},
                                         "the laws the exact Riemann solver handles")
                                   .read(dict);
    const std::string& law = type.word("type");
    KeywordSchema schema("functionObject", "riemannError " + law);
    if (law == "linearBarotropic") {
        schema.scalar("rho0", "kg/m^3", "reference density").greaterThan(0);
        schema.scalar("c0", "m/s", "sound speed").greaterThan(0);
        const KeywordValues v = schema.read(dict);
        return RiemannEquationOfState::linearBarotropic(v.scalar("rho0"), v.scalar("c0"));
    }
    schema.scalar("gamma", "-", "ratio of specific heats").greaterThan(1);
    if (law == "stiffenedGas") schema.scalar("pRef", "Pa", "stiffening pressure").atLeast(0);
    const KeywordValues v = schema.read(dict);
    if (law == "idealGas") return RiemannEquationOfState::idealGas(v.scalar("gamma"));
    return RiemannEquationOfState::stiffenedGas(v.scalar("gamma"), v.scalar("pRef"));
}

// The exact solver's checks of a side's state (P above the law's floor, P = c0² (ρ − ρ0) for
// linearBarotropic), reported at the side's entry in the dictionary rather than without a place.
void checkState(const Dictionary& dict, const PrimitiveState& state, const RiemannEquationOfState& eos,
                const std::string& side) {
    try {
        eos.check(state, side);
    } catch (const InputError&) {
        throw;
    } catch (const Error& e) {
        throw dict.error(state.density > 0 ? "pressure" : "density", e.what());
    }
}

PrimitiveState readState(const Dictionary& dict) {
    const KeywordValues v = KeywordSchema("functionObject", "riemannError state")
                                .scalar("density", "kg/m^3", "initial density of the side")
                                .greaterThan(0)
                                .scalar("velocity", "m/s", "initial velocity of the side")
                                .scalar("pressure", "Pa", "initial pressure of the side")
                                .dictionary("equationOfState", "the side's equation of state")
                                .read(dict);
    return {v.scalar("density"), v.scalar("velocity"), v.scalar("pressure")};
}

double median(std::vector<double> v) {
    if (v.empty()) return NAN;
    std::nth_element(v.begin(), v.begin() + long(v.size() / 2), v.end());
    return v[v.size() / 2];
}

}  // namespace

KeywordSchema RiemannError::keywords() {
    return KeywordSchema("functionObject", "riemannError")
        .scalar("x0", "m", "initial position of the discontinuity")
        .dictionary("left",
                    "the state left of x0: density, velocity, pressure, equationOfState { type ...; }")
        .dictionary("right", "the state right of x0, as left")
        .vector("interval", "m", "(from to): the part of the tube the norms are taken over")
        .ofLength(2)
        .example("(0 1)")
        .words("fields", "the fields compared: density, velocity, pressure, specificInternalEnergy")
        .orDefaultNames({"density", "velocity", "pressure"})
        .append(functionObjectKeywords());
}

RiemannError::RiemannError(const Dictionary& dict, const std::string& name, const RunContext& context)
    : RiemannError(keywords().read(dict), name, context) {}

RiemannError::RiemannError(const KeywordValues& values, const std::string& name, const RunContext& context)
    : FunctionObject(values, name, context),
      t0_(context.time().value()),
      fields_(values.words("fields")),
      norms_(outputFile("errorNorms.csv"), name, startTime()) {
    const Dictionary& dict = values.dict();
    const Dictionary& left = values.dictionary("left");
    const Dictionary& right = values.dictionary("right");
    const PrimitiveState leftState = readState(left), rightState = readState(right);
    const RiemannEquationOfState leftEos = readEos(left.subDict("equationOfState"));
    const RiemannEquationOfState rightEos = readEos(right.subDict("equationOfState"));
    checkState(left, leftState, leftEos, "left");
    checkState(right, rightState, rightEos, "right");
    try {
        exact_ = std::make_unique<ShockTubeSolution>(values.scalar("x0"), leftState, leftEos, rightState,
                                                     rightEos);
    } catch (const InputError&) {
        throw;
    } catch (const Error& e) {  // vacuum, no bracket: a property of both states together
        throw values.error("right", std::string(e.what()) + " (the states 'left' and 'right' together)");
    }
    const auto& interval = values.vector("interval");
    if (!(interval[1] > interval[0])) throw values.error("interval", "expected (from to) with from < to");
    from_ = interval[0], to_ = interval[1];
    for (const auto& f : fields_) {
        if (f != "density" && f != "velocity" && f != "pressure" && f != "specificInternalEnergy")
            throw values.error("fields", "'" + f +
                                             "' has no exact counterpart; valid: density velocity pressure "
                                             "specificInternalEnergy");
        requireField(dict, "fields", f);
    }
    star_ = std::make_unique<CsvFile>(
        outputFile("starState.csv"),
        std::vector<std::string>{"time", "pStar", "pStarExact", "uStar", "uStarExact"}, startTime());
    if (exact_->solver().starPressure() > rightState.pressure)  // the right wave is a shock
        shock_ = std::make_unique<CsvFile>(
            outputFile("shock.csv"), std::vector<std::string>{"time", "shockPosition", "shockPositionExact"},
            startTime());
}

std::optional<std::vector<std::string>> RiemannError::fieldsRead() const {
    std::vector<std::string> read{"position", "mass", "density", "velocity", "pressure"};
    read.insert(read.end(), fields_.begin(), fields_.end());
    return read;
}

void RiemannError::write() {
    const FieldStore& fields = context().fields();
    const std::size_t n = fields.size();
    const double t = context().time().value() - t0_;
    if (n == 0 || t <= 0) return;
    std::vector<double> x(n), w(n);
    const FieldBase& position = fields.field("position");
    const FieldBase& mass = fields.field("mass");
    const FieldBase& rho = fields.field("density");
    for (std::size_t i = 0; i < n; ++i)
        x[i] = position.component(i, 0), w[i] = mass.component(i, 0) / rho.component(i, 0);

    for (const auto& name : fields_) {
        const FieldBase& f = fields.field(name);
        std::vector<double> values(n);
        for (std::size_t i = 0; i < n; ++i) values[i] = f.component(i, 0);
        auto exact = [&](double xi) {
            const FlowState s = exact_->state(xi, t);
            if (name == "density") return s.density;
            if (name == "velocity") return s.velocity;
            if (name == "pressure") return s.pressure;
            return s.internalEnergy;
        };
        const ErrorNorms e = ErrorNorms::compute(x, values, w, exact, from_, to_);
        // The same norms of the exact profile (the error of zeros): the summary's relative error.
        const ErrorNorms scale = ErrorNorms::compute(x, std::vector<double>(n, 0.0), w, exact, from_, to_);
        norms_.add(context().time().value(), name, e.l1, e.l2, e.linf, scale.l1, scale.l2, scale.linf);
    }

    // Star state: the plateau between the waves, away from its edges and the contact.
    const auto waves = exact_->wavePositions(t);
    const double width = waves.rightTail - waves.leftTail;
    const double margin = 0.1 * width;
    const FieldBase& p = fields.field("pressure");
    const FieldBase& v = fields.field("velocity");
    std::vector<double> ps, vs;
    for (std::size_t i = 0; i < n; ++i) {
        const double xi = x[i];
        if (xi < waves.leftTail + margin || xi > waves.rightTail - margin ||
            std::abs(xi - waves.contact) < margin)
            continue;
        ps.push_back(p.component(i, 0)), vs.push_back(v.component(i, 0));
    }
    const double pStar = median(ps), uStar = median(vs);
    const double pExact = exact_->solver().starPressure(), uExact = exact_->solver().starVelocity();
    star_->row({context().time().value(), pStar, pExact, uStar, uExact});
    references_.clear();
    if (!ps.empty()) references_ = {{"starPressure", pStar, pExact}, {"starVelocity", uStar, uExact}};
    if (shock_) {
        const double level = 0.5 * (pExact + exact_->solver().right().pressure);
        double front = -std::numeric_limits<double>::infinity();
        for (std::size_t i = 0; i < n; ++i)
            if (x[i] >= from_ && x[i] <= to_ && p.component(i, 0) > level) front = std::max(front, x[i]);
        shock_->row({context().time().value(), front, waves.rightHead});
        if (std::isfinite(front)) references_.push_back({"shockPosition", front, waves.rightHead});
    }

    // The profile beside the exact one, for plots: profile_<time>.csv, particles in order of x.
    std::vector<std::size_t> order(n);
    for (std::size_t i = 0; i < n; ++i) order[i] = i;
    std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return x[a] < x[b]; });
    CsvFile profile(
        outputFile("profile_" + context().time().timeName() + ".csv"),
        {"x", "density", "densityExact", "velocity", "velocityExact", "pressure", "pressureExact"});
    for (const std::size_t i : order) {
        if (x[i] < from_ || x[i] > to_) continue;
        const FlowState s = exact_->state(x[i], t);
        profile.row({x[i], rho.component(i, 0), s.density, v.component(i, 0), s.velocity, p.component(i, 0),
                     s.pressure});
    }
    char line[300];
    if (ps.empty())
        std::snprintf(line, sizeof line,
                      "star state at t = %.6g: no particles in the plateau between the waves (exact star "
                      "pressure %.6g, velocity %.6g)",
                      context().time().value(), pExact, uExact);
    else
        std::snprintf(line, sizeof line,
                      "star pressure %.6g (exact %.6g, %s), star velocity %.6g (exact %.6g, %s)", pStar,
                      pExact, relativeErrorText(pStar, pExact).c_str(), uStar, uExact,
                      relativeErrorText(uStar, uExact).c_str());
    summary_ = {line};
}

MFDYN_REGISTER(FunctionObject, RiemannError, "riemannError",
               "a tube along x against the exact Riemann solution: L1/L2/Linf of rho, v, P, e, the star "
               "state, the shock");

}  // namespace mfdyn
