// bodyCentroid: where each body is, for the material point method's fluid cases (doc/methods/mpm.md
// sections 4.5-4.7: a drop's penetration into a pool, the mean heights of two gravity currents, a
// float's draft). For each body b (a particleGen region), with u the unit `up` vector:
//
//   M_b = sum_{a in b} m_a,            c_b = sum m_a x_a / M_b     (mass-weighted centroid),
//   height_b  = c_b . u                (the mean height: its fluid's mass-weighted mean of x . u),
//   lowest_b  = min_a x_a . u,         highest_b = max_a x_a . u   (plain extremes, no quantile:
//                                       one particle sets them; the centroid is the robust measure),
//
// and with `level` L (a plane x . u = L: a pool's surface at rest, a still-water line):
//   depth_b = L - lowest_b             (how far the body reaches below it: a drop's penetration,
//                                       a float's draft),
//   centroidDepth_b = L - height_b.
//
//     drop { type bodyCentroid; regions (drop); up (0 1); level 0.02; }   // regions: default all
//
// `up` defaults to +y in 2D, +z in 3D, +x in 1D (normalised; a zero vector is refused).
// bodyCentroid.csv: time, then per body <b>_mass, <b>_centroid_x ..., <b>_height, <b>_lowest,
// <b>_highest (and <b>_depth, <b>_centroidDepth with a level). A body with no particle left
// (removed outside the grid) has mass 0 and NaN for the rest. The summary gives each body's final
// values, its mass beside the mass at the first write to all 17 digits (particle masses are
// constant in MPM, so the two agree exactly unless particles are removed), and with a level the
// largest depth over the writes and when it happened. Sums are GlobalReduce sums in fixed blocks
// and the extremes global min/max: the figures do not depend on the thread count, and an MPI
// build measures every rank's particles.
#include "functionObjects/BodyCentroid.hpp"

#include "core/Error.hpp"
#include "core/Parallel.hpp"
#include "functionObjects/RegionLookup.hpp"
#include "particles/ParticleSetBase.hpp"

#include <cmath>
#include <cstdio>
#include <limits>

namespace mfdyn {

namespace {
const char* axes[] = {"x", "y", "z"};
}

KeywordSchema BodyCentroid::keywords() {
    return KeywordSchema("functionObject", "bodyCentroid")
        .words("regions",
               "the bodies (particleGen regions) to measure, in this order (default: every region)")
        .optional()
        .vector("up", "-", "against gravity: the axis of heights (default +y in 2D, +z in 3D, +x in 1D)")
        .optional()
        .example("(0 1)")
        .scalar("level", "m",
                "a reference height along up (a pool's surface at rest): depths below it are written")
        .optional()
        .example("0.02")
        .append(functionObjectKeywords());
}

BodyCentroid::BodyCentroid(const Dictionary& dict, const std::string& name, const RunContext& context)
    : BodyCentroid(keywords().read(dict), name, context) {}

BodyCentroid::BodyCentroid(const KeywordValues& values, const std::string& name, const RunContext& context)
    : FunctionObject(values, name, context, ParticleScope::owned), level_(values.optionalScalar("level")) {
    const Dictionary& dict = values.dict();
    const int dim = context.dimension();
    requireField(dict, "type", "mass");
    requireField(dict, "type", "region");
    const std::vector<std::string> names = runRegionNames(context);
    if (values.given("regions")) {
        for (const auto& r : values.words("regions"))
            bodies_.push_back({regionIndex(dict, "regions", r, context), r});
    } else {
        for (std::size_t r = 0; r < names.size(); ++r) bodies_.push_back({std::int64_t(r), names[r]});
        if (bodies_.empty()) throw dict.error("type", "bodyCentroid: this run's particles name no region");
    }
    up_[dim - 1] = 1;
    if (values.given("up")) {
        const auto& u = values.vector("up");
        if (int(u.size()) < dim)
            throw dict.error(
                "up", "expected " + std::to_string(dim) + " components, found " + std::to_string(u.size()));
        double norm = 0;
        for (int k = 0; k < dim; ++k) norm += u[k] * u[k];
        if (!(norm > 0) || !std::isfinite(norm))
            throw dict.error("up", "the up direction must be a non-zero finite vector");
        for (int k = 0; k < 3; ++k) up_[k] = k < dim ? u[k] / std::sqrt(norm) : 0.0;
    }
    std::vector<std::string> columns{"time"};
    for (const Body& b : bodies_) {
        columns.push_back(b.name + "_mass");
        for (int d = 0; d < dim; ++d) columns.push_back(b.name + "_centroid_" + axes[d]);
        for (const char* c : {"_height", "_lowest", "_highest"}) columns.push_back(b.name + c);
        if (level_) columns.push_back(b.name + "_depth"), columns.push_back(b.name + "_centroidDepth");
    }
    csv_ = std::make_unique<CsvFile>(outputFile("bodyCentroid.csv"), columns, startTime());
}

void BodyCentroid::write() {
    const FieldStore& fields = context().fields();
    const int dim = fields.dimension();
    const std::size_t n = context().ownedParticles();
    const FieldBase& x = fields.field("position");
    const FieldBase& m = fields.field("mass");
    const FieldBase& region = fields.field("region");
    const auto along = [&](std::size_t i) {
        double s = 0;
        for (int d = 0; d < dim; ++d) s += x.component(i, d) * up_[d];
        return s;
    };
    const double inf = std::numeric_limits<double>::infinity(),
                 nan = std::numeric_limits<double>::quiet_NaN();
    time_ = context().time().value();
    std::vector<double> row{time_};
    for (Body& b : bodies_) {
        const auto in = [&](std::size_t i) { return std::int64_t(region.component(i, 0)) == b.region; };
        // [M, M c (dim)]
        const SumArray<4> s = GlobalReduce::sum<SumArray<4>>(n, [&](std::size_t i) {
            SumArray<4> t;
            if (!in(i)) return t;
            const double mi = m.component(i, 0);
            t.s[0] = mi;
            for (int d = 0; d < dim; ++d) t.s[1 + d] = mi * x.component(i, d);
            return t;
        });
        b.mass = s.s[0];
        const bool empty = !(b.mass > 0);
        b.height = 0;
        for (int d = 0; d < dim; ++d) {
            b.centroid[d] = empty ? nan : s.s[1 + d] / b.mass;
            b.height += b.centroid[d] * up_[d];
        }
        b.lowest = GlobalReduce::min(n, [&](std::size_t i) { return in(i) ? along(i) : inf; });
        b.highest = GlobalReduce::max(n, [&](std::size_t i) { return in(i) ? along(i) : -inf; });
        if (empty) b.height = b.lowest = b.highest = nan;
        if (writes_ == 0) b.initialMass = b.mass;
        row.push_back(b.mass);
        for (int d = 0; d < dim; ++d) row.push_back(b.centroid[d]);
        row.push_back(b.height), row.push_back(b.lowest), row.push_back(b.highest);
        if (level_) {
            const double depth = *level_ - b.lowest;
            if (writes_ == 0 || depth > b.deepest) b.deepest = depth, b.deepestTime = time_;
            row.push_back(depth), row.push_back(*level_ - b.height);
        }
    }
    ++writes_;
    csv_->row(row);
}

std::vector<std::string> BodyCentroid::summary() const {
    if (writes_ == 0) return {};
    std::vector<std::string> lines;
    const int dim = context().dimension();
    char s[400];
    for (const Body& b : bodies_) {
        std::string centroid;
        for (int d = 0; d < dim; ++d) {
            std::snprintf(s, sizeof s, "%s%.6g", d ? " " : "", b.centroid[d]);
            centroid += s;
        }
        std::snprintf(s, sizeof s,
                      "bodyCentroid '%s' body %s: at t = %.6g mass %.17g (first write %.17g, change %.3e), "
                      "centroid (%s), height %.6g, lowest %.6g, highest %.6g",
                      name().c_str(), b.name.c_str(), time_, b.mass, b.initialMass, b.mass - b.initialMass,
                      centroid.c_str(), b.height, b.lowest, b.highest);
        lines.push_back(s);
        if (level_) {
            std::snprintf(s, sizeof s,
                          "bodyCentroid '%s' body %s: below the level %.6g: depth %.6g (centroid %.6g), "
                          "largest depth %.6g at t = %.6g",
                          name().c_str(), b.name.c_str(), *level_, *level_ - b.lowest, *level_ - b.height,
                          b.deepest, b.deepestTime);
            lines.push_back(s);
        }
    }
    return lines;
}

MFDYN_REGISTER(FunctionObject, BodyCentroid, "bodyCentroid",
               "mass, centroid and lowest/highest point of each body along up, with depths below a level");

}  // namespace mfdyn
