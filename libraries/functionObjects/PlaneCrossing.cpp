// planeCrossing: the first time any particle of a body lies beyond a plane. The thesis ends its
// dam-with-barrier runs when the water first leaves the grid through the open top y = 8 and
// quotes that time as the result (doc/methods/mpm.md 4.4: t = 1.265 at mu = 0.01, 1.35 at
// mu = 50, none by t = 4 at mu = 220):
//
//     exit { type planeCrossing; region water; point (0 8); normal (0 1); stopAtCrossing yes; }
//
// With s_p = (x_p - point) . n (n = `normal`, normalised), each write finds the leading particle,
// the one with the largest s_p (ties: the lowest global id), and appends its s and position to
// leading.csv (time, distance, globalId, position). The crossing is the first write with
// max_p s_p > 0: its time t_c, the particle and its position go to crossing.csv and the summary,
// with the write before it (t_b, s_b < 0). The crossing happened in (t_b, t_c]; the summary also
// gives the linear estimate t* = t_b + (t_c - t_b) s_b / (s_b - s_c) (the leading particle moves
// smoothly over one write interval; with writeControl timeStep and writeInterval 1, the default,
// t_c - t_b is one step). `reference` (s) puts t_c beside the expected time in the run summary's
// error lines. With `stopAtCrossing yes` the run ends cleanly after the crossing step: the state
// is written and the exit status is 0 (SolverRun asks every function object after it runs them);
// the thesis instead aborts when a particle leaves the grid, one step later for a plane on the
// grid's edge. A particle already beyond the plane at the first write is a crossing at the start
// (said in the summary). The reductions are global (max, then min of the ids, then sums), so
// every rank and thread count finds the same particle.
#include "functionObjects/PlaneCrossing.hpp"

#include "core/Error.hpp"
#include "core/Parallel.hpp"
#include "functionObjects/RegionLookup.hpp"
#include "particles/ParticleSetBase.hpp"

#include <cmath>
#include <cstdio>
#include <limits>

namespace mfdyn {

KeywordSchema PlaneCrossing::keywords() {
    return KeywordSchema("functionObject", "planeCrossing")
        .identifier("region", "the body (particleGen region) whose particles are watched (default: all)")
        .optional()
        .vector("point", "m", "a point of the plane")
        .example("(0 8)")
        .vector("normal", "-", "the plane's normal, pointing to the side a particle crosses to")
        .example("(0 1)")
        .flag("stopAtCrossing", "end the run cleanly (state written, exit status 0) at the crossing")
        .orDefault(false)
        .scalar("reference", "s", "the expected crossing time, for the summary's error line")
        .optional()
        .append(functionObjectKeywords());
}

PlaneCrossing::PlaneCrossing(const Dictionary& dict, const std::string& name, const RunContext& context)
    : PlaneCrossing(keywords().read(dict), name, context) {}

PlaneCrossing::PlaneCrossing(const KeywordValues& values, const std::string& name, const RunContext& context)
    : FunctionObject(values, name, context, ParticleScope::owned),
      stop_(values.flag("stopAtCrossing")),
      reference_(values.optionalScalar("reference")) {
    const Dictionary& dict = values.dict();
    const int dim = context.dimension();
    requireField(dict, "type", "globalId");
    if (values.given("region")) {
        requireField(dict, "region", "region");
        regionName_ = values.word("region");
        region_ = regionIndex(dict, "region", regionName_, context);
    }
    const auto& p = values.vector("point");
    const auto& n = values.vector("normal");
    if (int(p.size()) != dim)
        throw dict.error("point", "expected " + std::to_string(dim) + " components (a " +
                                      std::to_string(dim) + "D run), found " + std::to_string(p.size()));
    if (int(n.size()) != dim)
        throw dict.error("normal", "expected " + std::to_string(dim) + " components (a " +
                                       std::to_string(dim) + "D run), found " + std::to_string(n.size()));
    double norm = 0;
    for (int d = 0; d < dim; ++d) norm += n[d] * n[d];
    if (!(norm > 0) || !std::isfinite(norm))
        throw dict.error("normal", "the plane's normal must be a non-zero finite vector");
    for (int d = 0; d < dim; ++d) {
        if (!std::isfinite(p[d])) throw dict.error("point", "the point must be finite");
        point_[d] = p[d];
        normal_[d] = n[d] / std::sqrt(norm);
    }
    std::vector<std::string> columns{"time", "distance", "globalId"};
    const char* axes[] = {"x", "y", "z"};
    for (int d = 0; d < dim; ++d) columns.push_back(std::string("position_") + axes[d]);
    leading_ = std::make_unique<CsvFile>(outputFile("leading.csv"), columns, startTime());
}

void PlaneCrossing::write() {
    const FieldStore& fields = context().fields();
    const int dim = fields.dimension();
    const std::size_t n = context().ownedParticles();
    const FieldBase& x = fields.field("position");
    const FieldBase& gid = fields.field("globalId");
    const FieldBase* region = region_ >= 0 ? &fields.field("region") : nullptr;
    const auto member = [&](std::size_t i) {
        return !region || std::int64_t(region->component(i, 0)) == region_;
    };
    const auto distance = [&](std::size_t i) {
        double s = 0;
        for (int d = 0; d < dim; ++d) s += (x.component(i, d) - point_[d]) * normal_[d];
        return s;
    };
    const double inf = std::numeric_limits<double>::infinity();
    const double lead = GlobalReduce::max(n, [&](std::size_t i) { return member(i) ? distance(i) : -inf; });
    if (lead == -inf)
        throw RunError("planeCrossing '" + name() + "': no particle" +
                       (regionName_.empty() ? std::string() : " in region '" + regionName_ + "'"));
    const double id = GlobalReduce::min(
        n, [&](std::size_t i) { return member(i) && distance(i) == lead ? gid.component(i, 0) : inf; });
    const SumArray<4> at = GlobalReduce::sum<SumArray<4>>(n, [&](std::size_t i) {
        SumArray<4> s;
        if (!member(i) || gid.component(i, 0) != id || distance(i) != lead) return s;
        for (int d = 0; d < dim; ++d) s.s[d] = x.component(i, d);
        s.s[3] = 1;
        return s;
    });
    const double t = context().time().value();
    if (!crossed_ && lead > 0) {
        crossed_ = true;
        crossedAtStart_ = writes_ == 0;
        crossTime_ = t;
        crossDistance_ = lead;
        beforeTime_ = writes_ == 0 ? t : time_;
        beforeDistance_ = writes_ == 0 ? lead : distance_;
        crossId_ = std::int64_t(id);
        for (int d = 0; d < dim; ++d) crossPosition_[d] = at.s[d];
        std::vector<std::string> columns{"time", "previousTime", "estimatedTime", "distance", "globalId"};
        const char* axes[] = {"x", "y", "z"};
        for (int d = 0; d < dim; ++d) columns.push_back(std::string("position_") + axes[d]);
        CsvFile table(outputFile("crossing.csv"), columns, startTime());
        std::vector<double> row{crossTime_, beforeTime_, estimatedTime(), crossDistance_, double(crossId_)};
        for (int d = 0; d < dim; ++d) row.push_back(crossPosition_[d]);
        table.row(row);
    }
    distance_ = lead;
    time_ = t;
    ++writes_;
    std::vector<double> row{t, lead, id};
    for (int d = 0; d < dim; ++d) row.push_back(at.s[d]);
    leading_->row(row);
}

double PlaneCrossing::estimatedTime() const {
    // The leading particle's s linear in time between the two writes that bracket the crossing.
    if (crossedAtStart_ || !(beforeDistance_ < 0)) return crossTime_;
    return beforeTime_ + (crossTime_ - beforeTime_) * beforeDistance_ / (beforeDistance_ - crossDistance_);
}

std::vector<ReferenceValue> PlaneCrossing::referenceValues() const {
    if (!reference_ || !crossed_) return {};
    return {{"crossingTime", crossTime_, *reference_}};
}

std::string PlaneCrossing::stopReason() const {
    char s[200];
    std::snprintf(s, sizeof s,
                  "planeCrossing: particle %lld crossed the plane at t = %.6g (stopAtCrossing yes)",
                  static_cast<long long>(crossId_), crossTime_);
    return s;
}

std::vector<std::string> PlaneCrossing::summary() const {
    if (writes_ == 0) return {};
    char s[320];
    if (!crossed_) {
        std::snprintf(s, sizeof s,
                      "planeCrossing '%s': no particle crossed by t = %.6g (the leading one %.6g before the "
                      "plane)",
                      name().c_str(), time_, -distance_);
        return {s};
    }
    if (crossedAtStart_) {
        std::snprintf(
            s, sizeof s,
            "planeCrossing '%s': particle %lld already beyond the plane (by %.6g) at the first write, "
            "t = %.6g",
            name().c_str(), static_cast<long long>(crossId_), crossDistance_, crossTime_);
        return {s};
    }
    const int dim = context().dimension();
    std::string where = "(";
    for (int d = 0; d < dim; ++d) {
        char c[40];
        std::snprintf(c, sizeof c, "%s%.6g", d ? " " : "", crossPosition_[d]);
        where += c;
    }
    where += ")";
    std::snprintf(s, sizeof s,
                  "planeCrossing '%s': first crossing at t = %.6g (after t = %.6g; linear estimate %.6g) by "
                  "particle %lld at %s",
                  name().c_str(), crossTime_, beforeTime_, estimatedTime(), static_cast<long long>(crossId_),
                  where.c_str());
    return {s};
}

MFDYN_REGISTER(
    FunctionObject, PlaneCrossing, "planeCrossing",
    "first time a particle of a body crosses a plane (the dam exit time); optionally stops the run");

}  // namespace mfdyn
