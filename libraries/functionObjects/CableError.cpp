// cableError: the cable of Lee, Gil, Greto, Karim & Bonet 2016 section 8.1 (doc/methods/tl-jst-sph.md 8.1),
// a bar along x fixed at X = 0 and free at X = L, v0 on X <= a at t = 0, against the d'Alembert
// solution of verification/CableWave with c = sqrt(E/rho0) (nu = 0: the 1D bar speed is the
// dilatational one). One particle, the nearest to `tip` in the reference configuration, chosen
// at the start (and followed by globalId), is compared at each of its write times t (with
// writeControl timeStep and writeInterval 1, every step):
//
//   cable.csv       time,tipVelocity,exactTipVelocity,tipDisplacement,exactTipDisplacement
//                   (axial components: v_x, and u_x = x - X), the exact values at the tip's own X;
//   errorNorms.csv  tipVelocity, tipDisplacement: the norms of the history so far,
//                   L1 = mean |e|, L2 = sqrt(mean e^2) (rms), Linf = max |e|, with the same
//                   norms of the exact history as the scale of the summary's relative error;
//   summary         peakTipDisplacement: the largest |u_x| so far against the exact largest.
//
// Expected shape (L = 10, c = 5000, v0 = 5, a = 2.5): tip velocity +5 m/s on (1.5, 2.0) ms and
// -5 m/s on (2.0, 2.5) ms, tip displacement a triangle peaking at +2.5 mm at 2 ms and -2.5 mm at
// 6 ms. Time is the run's time (the exact solution starts at t = 0).
//
//     tip
//     {
//         type cableError;
//         rho0 8000;  youngsModulus 200e9;  length 10;  loadedLength 2.5;  velocity 5;
//         tip (10 0.2 0.2);
//         writeControl timeStep;  writeInterval 1;
//     }
// Keywords: doc/models/functionObject/cableError.md (the schema below).
#include "functionObjects/CableError.hpp"

#include <cmath>
#include <cstdio>
#include <limits>

namespace mfdyn {

namespace {

CableWave cableFrom(const KeywordValues& values) {
    const double rho0 = values.scalar("rho0"), E = values.scalar("youngsModulus");
    const double L = values.scalar("length"), a = values.scalar("loadedLength");
    if (!(a <= L)) throw values.error("loadedLength", "expected 0 <= loadedLength <= length");
    return CableWave(L, std::sqrt(E / rho0), values.scalar("velocity"), a);
}

}  // namespace

void CableError::History::add(double e) {
    sumAbs += std::abs(e), sumSquares += e * e;
    max = std::max(max, std::abs(e));
}

KeywordSchema CableError::keywords() {
    return KeywordSchema("functionObject", "cableError")
        .scalar("rho0", "kg/m^3", "reference density of the cable")
        .greaterThan(0)
        .scalar("youngsModulus", "Pa", "Young's modulus E of the cable (wave speed sqrt(E/rho0))")
        .greaterThan(0)
        .scalar("length", "m", "cable length L")
        .greaterThan(0)
        .scalar("loadedLength", "m", "length of the end section given the initial velocity")
        .atLeast(0)
        .scalar("velocity", "m/s", "initial velocity of the loaded section")
        .vector("tip", "m",
                "the point whose nearest particle is the tip; components beyond the case's dimension are "
                "ignored (default (length 0 0))")
        .optional()
        .identifier("positionField", "vector field of the particles' coordinates used to find the tip")
        .orDefault("referencePosition")
        .append(functionObjectKeywords());
}

CableError::CableError(const Dictionary& dict, const std::string& name, const RunContext& context)
    : CableError(keywords().read(dict), name, context) {}

CableError::CableError(const KeywordValues& values, const std::string& name, const RunContext& context)
    : FunctionObject(values, name, context),
      exact_(cableFrom(values)),
      positionField_(values.word("positionField")),
      norms_(outputFile("errorNorms.csv"), name, startTime()) {
    const Dictionary& dict = values.dict();
    const FieldStore& fields = context.fields();
    const int dim = context.dimension();
    const FieldBase& X = requireField(dict, "positionField", positionField_);
    requireField(dict, "type", "position");
    requireField(dict, "type", "velocity");
    requireField(dict, "type", "globalId");
    std::vector<double> tip =
        values.given("tip") ? values.vector("tip") : std::vector<double>{exact_.length(), 0.0, 0.0};
    if (tip.size() < std::size_t(dim))
        throw values.error("tip", "expected a point with at least " + std::to_string(dim) + " components");
    if (fields.size() == 0) throw dict.error("type", "cableError: there are no particles");
    double best = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < fields.size(); ++i) {
        double d2 = 0;
        for (int c = 0; c < dim; ++c) d2 += std::pow(X.component(i, c) - tip[std::size_t(c)], 2);
        if (d2 < best) best = d2, tip_ = i;
    }
    tipId_ = std::int64_t(fields.field("globalId").component(tip_, 0));
    tipX_ = X.component(tip_, 0);
    csv_ = std::make_unique<CsvFile>(outputFile("cable.csv"),
                                     std::vector<std::string>{"time", "tipVelocity", "exactTipVelocity",
                                                              "tipDisplacement", "exactTipDisplacement"},
                                     startTime());
}

std::size_t CableError::locateTip() const {
    const FieldBase& id = context().fields().field("globalId");
    if (tip_ < id.size() && std::int64_t(id.component(tip_, 0)) == tipId_) return tip_;
    for (std::size_t i = 0; i < id.size(); ++i)
        if (std::int64_t(id.component(i, 0)) == tipId_) return i;
    throw Error("cableError: the tip particle (globalId " + std::to_string(tipId_) + ") is gone");
}

void CableError::write() {
    tip_ = locateTip();
    const FieldStore& fields = context().fields();
    const double t = context().time().value();
    const double v = fields.field("velocity").component(tip_, 0);
    const double u =
        fields.field("position").component(tip_, 0) - fields.field(positionField_).component(tip_, 0);
    const double vExact = exact_.velocity(tipX_, t), uExact = exact_.displacement(tipX_, t);
    csv_->row({t, v, vExact, u, uExact});
    velocityError_.add(v - vExact);
    displacementError_.add(u - uExact);
    velocityExact_.add(vExact);
    displacementExact_.add(uExact);
    ++rows_;
    const double n = double(rows_);
    norms_.add(t, "tipVelocity", velocityError_.sumAbs / n, std::sqrt(velocityError_.sumSquares / n),
               velocityError_.max, velocityExact_.sumAbs / n, std::sqrt(velocityExact_.sumSquares / n),
               velocityExact_.max);
    norms_.add(t, "tipDisplacement", displacementError_.sumAbs / n,
               std::sqrt(displacementError_.sumSquares / n), displacementError_.max,
               displacementExact_.sumAbs / n, std::sqrt(displacementExact_.sumSquares / n),
               displacementExact_.max);
    if (std::abs(u) > std::abs(peak_)) peak_ = u, peakTime_ = t;
}

std::vector<std::string> CableError::summary() const {
    if (rows_ == 0) return {};
    char line[200];
    std::snprintf(line, sizeof line,
                  "cable tip (X = %.6g): largest |displacement| %.4g m at t = %.4g s (exact %.4g m)", tipX_,
                  peak_, peakTime_, exact_.displacement(tipX_, peakTime_));
    return {line};
}

std::vector<ReferenceValue> CableError::referenceValues() const {
    if (rows_ == 0) return {};
    // The README's figure: the peak the tip reached against the exact peak over the same times
    // (2.5 mm = v0 a/c once t >= 2 ms).
    return {{"peakTipDisplacement", std::abs(peak_), displacementExact_.max}};
}

MFDYN_REGISTER(
    FunctionObject, CableError, "cableError",
    "cable tip velocity and displacement against d'Alembert (Lee et al. 2016 8.1): cable.csv, history norms");

}  // namespace mfdyn
