// isothermalShockBarError: a 1D run of the isothermal shock-bar (Zisis 2017 §5.1, Fig. 5.1;
// doc/methods/sph-impact.md 8.2) against its exact solution (libraries/verification/IsothermalShockBar: two
// successive Riemann problems, exact until t = 0.5393). Writes, at each of its write times t:
//
//   errorNorms.csv  L1, L2, Linf of density, velocity, pressure over [from, to], weights m/ρ
//                   (as riemannError);
//   plateaus.csv    per uniform state of the exact profile, the medians of ρ, v, P over the
//                   particles in its middle (20% of its width left out at each end, where SPH
//                   smears the waves) beside the exact values (in the summary's error lines as
//                   <plateau>Density, <plateau>Velocity, <plateau>Pressure). Before the impact's shock reaches
//                   the interface at b (t1 = 0.15616) there is one plateau, `impact`; after it three:
//                   `impact` (ρ*, v*, P* of the first impact, left of the reflected fan),
//                   `reflected` (material 1 behind the reflected fan) and `transmitted` (material 2
//                   behind the transmitted shock);
//   fronts.csv      each shock's position, where the SPH pressure crosses the mean of the exact
//                   pressures either side (nearest crossing within frontWindow of the exact front),
//                   beside the exact position and the local smoothing length h;
//   contact.csv     the largest |P − P*|/P* within 3h of the material interface (after t1);
//   profile_<time>.csv  x, ρ, v, P and their exact values, for plots.
//
//     bar
//     {
//         type isothermalShockBarError;  interval (0.3 1.4);  fields (density velocity pressure);
//         frontWindow 0.03;   // default
//     }
//
// The set-up is the one of the note (IsothermalShockBar::zisis2017()), measured from the run's
// start time.
#include "functionObjects/IsothermalShockBarError.hpp"

#include "verification/ErrorNorms.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace mfdyn {

namespace {

double median(std::vector<double> v) {
    if (v.empty()) return NAN;
    std::nth_element(v.begin(), v.begin() + long(v.size() / 2), v.end());
    return v[v.size() / 2];
}

}  // namespace

KeywordSchema IsothermalShockBarError::keywords() {
    return KeywordSchema("functionObject", "isothermalShockBarError")
        .scalar("frontWindow", "m", "half-width of the window around each exact front searched for the front")
        .greaterThan(0)
        .orDefault(0.03)
        .words("fields", "the fields compared: density, velocity, pressure")
        .orDefaultNames({"density", "velocity", "pressure"})
        .vector("interval", "m", "(from to): the part of the bar the norms are taken over")
        .ofLength(2)
        .orDefault(std::vector<double>{0.0, 1.4})
        .append(functionObjectKeywords());
}

IsothermalShockBarError::IsothermalShockBarError(const Dictionary& dict, const std::string& name,
                                                 const RunContext& context)
    : IsothermalShockBarError(keywords().read(dict), name, context) {}

IsothermalShockBarError::IsothermalShockBarError(const KeywordValues& values, const std::string& name,
                                                 const RunContext& context)
    : FunctionObject(values, name, context),
      exact_(std::make_unique<IsothermalShockBar>(IsothermalShockBar::zisis2017())),
      t0_(context.time().value()),
      frontWindow_(values.scalar("frontWindow")),
      fields_(values.words("fields")),
      norms_(outputFile("errorNorms.csv"), name, startTime()) {
    const Dictionary& dict = values.dict();
    if (context.dimension() != 1)
        throw dict.error("type", "isothermalShockBarError compares 1D runs; this case is " +
                                     std::to_string(context.dimension()) + "D");
    const auto& interval = values.vector("interval");
    if (!(interval[1] > interval[0])) throw values.error("interval", "expected (from to) with from < to");
    from_ = interval[0], to_ = interval[1];
    for (const auto& f : fields_) {
        if (f != "density" && f != "velocity" && f != "pressure")
            throw values.error("fields",
                               "'" + f + "' has no exact counterpart; valid: density velocity pressure");
        if (!context.fields().findField(f)) throw values.error("fields", "this run has no field '" + f + "'");
    }
    if (!context.fields().findField("smoothingLength"))
        throw dict.error("type", "isothermalShockBarError needs the field smoothingLength (an SPH run)");
    plateaus_ = std::make_unique<CsvFile>(
        outputFile("plateaus.csv"),
        std::vector<std::string>{"time", "plateau", "density", "densityExact", "velocity", "velocityExact",
                                 "pressure", "pressureExact", "particles"},
        startTime());
    fronts_ = std::make_unique<CsvFile>(
        outputFile("fronts.csv"), std::vector<std::string>{"time", "front", "x", "xExact", "h"}, startTime());
    contact_ = std::make_unique<CsvFile>(outputFile("contact.csv"),
                                         std::vector<std::string>{"time", "pressureDeviation", "particles"},
                                         startTime());
}

std::optional<std::vector<std::string>> IsothermalShockBarError::fieldsRead() const {
    std::vector<std::string> read{"position", "mass", "density", "velocity", "pressure", "smoothingLength"};
    read.insert(read.end(), fields_.begin(), fields_.end());
    return read;
}

void IsothermalShockBarError::write() {
    const FieldStore& fields = context().fields();
    const std::size_t n = fields.size();
    const double time = context().time().value();
    const double t = time - t0_;
    if (n == 0 || t <= 0) return;
    if (t > exact_->validUntil()) {
        char line[200];
        std::snprintf(line, sizeof line,
                      "isothermal shock-bar: t = %.6g is past %.6g, where the exact solution ends", t,
                      exact_->validUntil());
        summary_ = {line};
        return;
    }

    // Particles in order of x.
    const FieldBase& position = fields.field("position");
    const FieldBase& mass = fields.field("mass");
    const FieldBase& rhoField = fields.field("density");
    const FieldBase& vField = fields.field("velocity");
    const FieldBase& pField = fields.field("pressure");
    const FieldBase& hField = fields.field("smoothingLength");
    std::vector<std::size_t> order(n);
    for (std::size_t i = 0; i < n; ++i) order[i] = i;
    std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
        return position.component(a, 0) < position.component(b, 0);
    });
    std::vector<double> x(n), w(n), rho(n), v(n), p(n), h(n);
    for (std::size_t k = 0; k < n; ++k) {
        const std::size_t i = order[k];
        x[k] = position.component(i, 0), rho[k] = rhoField.component(i, 0), v[k] = vField.component(i, 0);
        p[k] = pField.component(i, 0), h[k] = hField.component(i, 0), w[k] = mass.component(i, 0) / rho[k];
    }

    for (const auto& name : fields_) {
        const std::vector<double>& values = name == "density" ? rho : name == "velocity" ? v : p;
        auto exact = [&](double xi) {
            const FlowState s = exact_->state(xi, t);
            return name == "density" ? s.density : name == "velocity" ? s.velocity : s.pressure;
        };
        const ErrorNorms e = ErrorNorms::compute(x, values, w, exact, from_, to_);
        // The same norms of the exact profile (the error of a field of zeros): the relative error's scale.
        const ErrorNorms scale = ErrorNorms::compute(x, std::vector<double>(n, 0.0), w, exact, from_, to_);
        norms_.add(time, name, e.l1, e.l2, e.linf, scale.l1, scale.l2, scale.linf);
    }

    // The exact waves at t (bars 1|2 meet at a = 0.6, 2|3 at b = 0.8).
    const RiemannSolver& impact = exact_->impact();
    const RiemannSolver& transmission = exact_->transmission();
    const double a = 0.6, b = 0.8, t1 = exact_->transmissionTime(), T = t - t1;
    const double impactShock = a + impact.leftWave().headSpeed * t;
    struct Plateau {
        const char* name;
        double from, to, rho, v, p;
    };
    struct Front {
        const char* name;
        double x;
    };
    std::vector<Plateau> plateaus;
    std::vector<Front> fronts{{"impactShock", impactShock}};
    double contact = NAN;
    if (t <= t1) {
        const double right = a + impact.rightWave().headSpeed * t;
        plateaus.push_back({"impact", impactShock, right, impact.starDensityLeft(), impact.starVelocity(),
                            impact.starPressure()});
        fronts.push_back({"impactRightShock", right});
    } else {
        const double fanHead = b + transmission.leftWave().headSpeed * T;
        const double fanTail = b + transmission.leftWave().tailSpeed * T;
        contact = b + transmission.contactSpeed() * T;
        const double shock = b + transmission.rightWave().headSpeed * T;
        plateaus.push_back({"impact", impactShock, fanHead, impact.starDensityLeft(), impact.starVelocity(),
                            impact.starPressure()});
        plateaus.push_back({"reflected", fanTail, contact, transmission.starDensityLeft(),
                            transmission.starVelocity(), transmission.starPressure()});
        plateaus.push_back({"transmitted", contact, shock, transmission.starDensityRight(),
                            transmission.starVelocity(), transmission.starPressure()});
        fronts.push_back({"transmittedShock", shock});
    }

    char line[300];
    summary_.clear();
    references_.clear();
    // Relative errors where the exact value is not 0; against an exact 0 (a plateau at rest) the
    // absolute error is reported instead. An empty plateau is said so, not folded in as NaN.
    double worstPlateau = 0, worstAtRest = -1;
    std::string empty;
    std::size_t measured = 0;
    for (const Plateau& q : plateaus) {
        const double margin = 0.2 * (q.to - q.from);
        std::vector<double> rs, vs, ps;
        for (std::size_t k = 0; k < n; ++k)
            if (x[k] > q.from + margin && x[k] < q.to - margin)
                rs.push_back(rho[k]), vs.push_back(v[k]), ps.push_back(p[k]);
        const double count = double(rs.size());
        const double r = median(rs), u = median(vs), pr = median(ps);
        plateaus_->row(time, q.name, {r, q.rho, u, q.v, pr, q.p, count});
        if (rs.empty()) {
            empty += std::string(empty.empty() ? "" : ", ") + q.name;
            continue;
        }
        ++measured;
        const std::string plateau = q.name;
        references_.push_back({plateau + "Density", r, q.rho});
        references_.push_back({plateau + "Velocity", u, q.v});
        references_.push_back({plateau + "Pressure", pr, q.p});
        for (const auto& [value, exact] : {std::pair{r, q.rho}, std::pair{u, q.v}, std::pair{pr, q.p}}) {
            if (exact != 0)
                worstPlateau = std::max(worstPlateau, std::abs(value - exact) / std::abs(exact));
            else
                worstAtRest = std::max(worstAtRest, std::abs(value));
        }
    }
    if (measured > 0) {
        std::snprintf(line, sizeof line,
                      "isothermal shock-bar: %zu plateaus, largest relative error of rho, v, P %.3g%%",
                      measured, 100 * worstPlateau);
        summary_.push_back(line);
    }
    if (worstAtRest >= 0) {
        std::snprintf(line, sizeof line,
                      "isothermal shock-bar: relative error n/a where the exact value is 0; largest absolute "
                      "value there %.3g",
                      worstAtRest);
        summary_.push_back(line);
    }
    if (!empty.empty()) summary_.push_back("isothermal shock-bar: no particles in the plateau " + empty);

    for (const Front& f : fronts) {
        const double eps = 1e-9;
        const double level =
            0.5 * (exact_->state(f.x - eps, t).pressure + exact_->state(f.x + eps, t).pressure);
        double best = NAN, bestH = NAN;
        for (std::size_t k = 0; k + 1 < n; ++k) {
            if (x[k + 1] < f.x - frontWindow_ || x[k] > f.x + frontWindow_) continue;
            if ((p[k] - level) * (p[k + 1] - level) > 0 || p[k] == p[k + 1]) continue;
            const double xc = x[k] + (level - p[k]) / (p[k + 1] - p[k]) * (x[k + 1] - x[k]);
            if (std::isnan(best) || std::abs(xc - f.x) < std::abs(best - f.x))
                best = xc, bestH = 0.5 * (h[k] + h[k + 1]);
        }
        fronts_->row(time, f.name, {best, f.x, bestH});
        if (std::isnan(best))
            std::snprintf(
                line, sizeof line,
                "isothermal shock-bar: %s not found (no pressure crossing within frontWindow %.3g of "
                "the exact %.6g)",
                f.name, frontWindow_, f.x);
        else
            std::snprintf(line, sizeof line, "isothermal shock-bar: %s at %.6g (exact %.6g, %+.2f h)", f.name,
                          best, f.x, (best - f.x) / bestH);
        summary_.push_back(line);
    }

    if (!std::isnan(contact)) {
        const double pStar = transmission.starPressure();
        double worst = 0, count = 0;
        for (std::size_t k = 0; k < n; ++k)
            if (std::abs(x[k] - contact) < 3 * h[k])
                worst = std::max(worst, std::abs(p[k] - pStar) / pStar), ++count;
        contact_->row({time, worst, count});
        if (count == 0)
            std::snprintf(line, sizeof line, "isothermal shock-bar: no particles within 3h of the interface");
        else
            std::snprintf(
                line, sizeof line,
                "isothermal shock-bar: pressure within 3h of the interface off P* by %.3g%% at most",
                100 * worst);
        summary_.push_back(line);
    }

    CsvFile profile(
        outputFile("profile_" + context().time().timeName() + ".csv"),
        {"x", "density", "densityExact", "velocity", "velocityExact", "pressure", "pressureExact"});
    for (std::size_t k = 0; k < n; ++k) {
        if (x[k] < from_ || x[k] > to_) continue;
        const FlowState s = exact_->state(x[k], t);
        profile.row({x[k], rho[k], s.density, v[k], s.velocity, p[k], s.pressure});
    }
}

MFDYN_REGISTER(
    FunctionObject, IsothermalShockBarError, "isothermalShockBarError",
    "1D isothermal shock-bar (Zisis 2017 5.1) against its exact solution: norms, plateaus, shock fronts");

}  // namespace mfdyn
