// hydrostaticPressure: a fluid at rest against the hydrostatic pressure p(h) = rho g (H - h), H the
// free surface's height (doc/methods/mpm.md 5, X1: a weakly compressible column at rest with grid
// damping, within 2% away from the free surface):
//
//     p { type hydrostaticPressure; region water; rho 1000; g 9.81; bins 20; surfaceBand 0.1;
//         surfaceOffset 0.0125; point (0.5 0); halfWidth 0.25; }
//
// Heights are h = x . u (u = `up`, default +y in 2D, +z in 3D). The particles used are those of
// `region` (default all) and, with `point` and `halfWidth`, within halfWidth of the vertical line
// through point (|(x - point) - ((x - point) . u) u| <= halfWidth), away from side walls. H is
// `freeSurface` when given, else the highest such particle's h plus `surfaceOffset` (default 0):
// the surface lies half a particle spacing above the top row of points, so the offset is that
// half spacing. The band [h_min, H - surfaceBand] from the lowest particle up is cut into `bins`
// equal bins; per non-empty bin b the mean pressure p_b of its particles (the solver's `pressure`
// field, positive in compression) is compared with the exact value at their mean height,
// e_b = p_b - rho g (H - h_b). Near the surface p -> 0 and a relative error means little (and the
// surface particles carry the discretisation's half-cell pressure offset), hence the band.
// errorNorms.csv gets field pressure with L1 = mean |e_b|, L2 = sqrt(mean e_b^2), Linf = max |e_b|,
// beside the same norms of the exact values; the summary and referenceValues give the bin with the
// largest relative error |e_b| / (rho g (H - h_b)) (name worstBin: its p_b against its exact one).
// profile.csv: time, height, pressure, exact, relativeError, particles per bin and write.
// Each bin's sums are global reductions, so every rank and thread count gives the same numbers.
#include "functionObjects/HydrostaticPressure.hpp"

#include "core/Error.hpp"
#include "core/Parallel.hpp"
#include "functionObjects/RegionLookup.hpp"
#include "particles/ParticleSetBase.hpp"

#include <cmath>
#include <cstdio>
#include <limits>

namespace mfdyn {

KeywordSchema HydrostaticPressure::keywords() {
    return KeywordSchema("functionObject", "hydrostaticPressure")
        .identifier("region", "the fluid (particleGen region) whose pressure is sampled (default: all)")
        .optional()
        .scalar("rho", "kg/m^3", "the fluid's density in rho g (H - h)")
        .greaterThan(0)
        .scalar("g", "m/s^2", "the magnitude of gravity")
        .greaterThan(0)
        .vector("up", "-", "against gravity: the axis of the heights (default +y in 2D, +z in 3D)")
        .optional()
        .example("(0 1)")
        .vector("point", "m", "a point of the vertical sampling line (default: every particle)")
        .optional()
        .example("(0.5 0)")
        .scalar("halfWidth", "m", "particles within this distance of the line are sampled (with point)")
        .greaterThan(0)
        .optional()
        .scalar("freeSurface", "m", "the free surface's height H (default: measured, the highest particle)")
        .optional()
        .scalar("surfaceOffset", "m",
                "added to the highest particle's height for a measured H (half the particle spacing)")
        .atLeast(0)
        .orDefault(0.0)
        .scalar("surfaceBand", "m", "the band below the free surface left out of the comparison")
        .atLeast(0)
        .integer("bins", "-", "height bins between the lowest particle and H - surfaceBand")
        .atLeast(1)
        .append(functionObjectKeywords());
}

HydrostaticPressure::HydrostaticPressure(const Dictionary& dict, const std::string& name,
                                         const RunContext& context)
    : HydrostaticPressure(keywords().read(dict), name, context) {}

HydrostaticPressure::HydrostaticPressure(const KeywordValues& values, const std::string& name,
                                         const RunContext& context)
    : FunctionObject(values, name, context, ParticleScope::owned),
      rho_(values.scalar("rho")),
      g_(values.scalar("g")),
      freeSurface_(values.optionalScalar("freeSurface")),
      surfaceOffset_(values.scalar("surfaceOffset")),
      surfaceBand_(values.scalar("surfaceBand")),
      bins_(values.integer("bins")) {
    const Dictionary& dict = values.dict();
    const int dim = context.dimension();
    if (dim < 2) throw dict.error("type", "hydrostaticPressure needs a 2D or 3D run (a height and a line)");
    requireField(dict, "type", "pressure");
    if (values.given("region")) {
        requireField(dict, "region", "region");
        regionName_ = values.word("region");
        region_ = regionIndex(dict, "region", regionName_, context);
    }
    up_[dim - 1] = 1;
    if (values.given("up")) {
        const auto& u = values.vector("up");
        if (int(u.size()) != dim) throw dict.error("up", "expected " + std::to_string(dim) + " components");
        double norm = 0;
        for (int d = 0; d < dim; ++d) norm += u[d] * u[d];
        if (!(norm > 0) || !std::isfinite(norm)) throw dict.error("up", "must be a non-zero finite vector");
        for (int d = 0; d < dim; ++d) up_[d] = u[d] / std::sqrt(norm);
    }
    if (values.given("point") != values.given("halfWidth"))
        throw dict.error(values.given("point") ? "point" : "halfWidth",
                         "point and halfWidth go together (the sampling line and its width); give both or "
                         "neither (every particle)");
    if (values.given("point")) {
        const auto& p = values.vector("point");
        if (int(p.size()) != dim)
            throw dict.error("point", "expected " + std::to_string(dim) + " components");
        for (int d = 0; d < dim; ++d) point_[d] = p[d];
        halfWidth_ = values.scalar("halfWidth");
        line_ = true;
    }
    profile_ = std::make_unique<CsvFile>(
        outputFile("profile.csv"),
        std::vector<std::string>{"time", "height", "pressure", "exact", "relativeError", "particles"},
        startTime());
    norms_ = std::make_unique<ErrorNormWriter>(outputFile("errorNorms.csv"), name, startTime());
}

void HydrostaticPressure::write() {
    const FieldStore& fields = context().fields();
    const int dim = fields.dimension();
    const std::size_t n = context().ownedParticles();
    const FieldBase& x = fields.field("position");
    const FieldBase& p = fields.field("pressure");
    const FieldBase* region = region_ >= 0 ? &fields.field("region") : nullptr;
    const auto height = [&](std::size_t i) {
        double h = 0;
        for (int d = 0; d < dim; ++d) h += x.component(i, d) * up_[d];
        return h;
    };
    const auto member = [&](std::size_t i) {
        if (region && std::int64_t(region->component(i, 0)) != region_) return false;
        if (!line_) return true;
        double r[3] = {0, 0, 0}, along = 0;
        for (int d = 0; d < dim; ++d) along += (r[d] = x.component(i, d) - point_[d]) * up_[d];
        double off = 0;
        for (int d = 0; d < dim; ++d) off += (r[d] - along * up_[d]) * (r[d] - along * up_[d]);
        return off <= halfWidth_ * halfWidth_;
    };
    const double inf = std::numeric_limits<double>::infinity();
    const double top = GlobalReduce::max(n, [&](std::size_t i) { return member(i) ? height(i) : -inf; });
    const double bottom = GlobalReduce::min(n, [&](std::size_t i) { return member(i) ? height(i) : inf; });
    if (top == -inf)
        throw RunError("hydrostaticPressure '" + name() + "': no particle" +
                       (regionName_.empty() ? std::string() : " in region '" + regionName_ + "'") +
                       (line_ ? " within halfWidth of the sampling line" : ""));
    const double H = freeSurface_ ? *freeSurface_ : top + surfaceOffset_;
    const double hi = H - surfaceBand_;
    time_ = context().time().value();
    height_ = H;
    binsUsed_ = 0;
    worstRelative_ = -1;
    double L1 = 0, L2 = 0, Linf = 0, e1 = 0, e2 = 0, eInf = 0;
    if (hi > bottom) {
        const double width = (hi - bottom) / double(bins_);
        for (long b = 0; b < bins_; ++b) {
            const double lo = bottom + double(b) * width, up = b + 1 == bins_ ? hi : lo + width;
            const SumArray<3> s = GlobalReduce::sum<SumArray<3>>(n, [&](std::size_t i) {
                SumArray<3> t;
                if (!member(i)) return t;
                const double h = height(i);
                if (h < lo || h > up || (h == up && b + 1 < bins_)) return t;
                t.s[0] = 1;
                t.s[1] = p.component(i, 0);
                t.s[2] = h;
                return t;
            });
            if (s.s[0] == 0) continue;
            const double pb = s.s[1] / s.s[0], hb = s.s[2] / s.s[0];
            const double exact = rho_ * g_ * (H - hb);
            const double e = std::abs(pb - exact), relative = e / exact;
            ++binsUsed_;
            L1 += e, L2 += e * e, Linf = std::max(Linf, e);
            e1 += exact, e2 += exact * exact, eInf = std::max(eInf, exact);
            if (relative > worstRelative_)
                worstRelative_ = relative, worstHeight_ = hb, worstPressure_ = pb, worstExact_ = exact;
            profile_->row({time_, hb, pb, exact, (pb - exact) / exact, s.s[0]});
        }
    }
    ++writes_;
    if (binsUsed_ == 0) return;
    const double k = double(binsUsed_);
    norms_->add(time_, "pressure", L1 / k, std::sqrt(L2 / k), Linf, e1 / k, std::sqrt(e2 / k), eInf);
}

std::vector<ErrorNorm> HydrostaticPressure::errorNorms() const {
    return norms_->latest();
}

std::vector<ReferenceValue> HydrostaticPressure::referenceValues() const {
    if (binsUsed_ == 0) return {};
    return {{"worstBin", worstPressure_, worstExact_}};
}

std::vector<std::string> HydrostaticPressure::summary() const {
    if (writes_ == 0) return {};
    char s[320];
    if (binsUsed_ == 0) {
        std::snprintf(
            s, sizeof s,
            "hydrostaticPressure '%s': at t = %.6g no particle below H - surfaceBand = %.6g (H %.6g)",
            name().c_str(), time_, height_ - surfaceBand_, height_);
        return {s};
    }
    std::snprintf(s, sizeof s,
                  "hydrostaticPressure '%s': at t = %.6g, H = %.6g, the largest relative error %.3g%% at h = "
                  "%.6g (p %.6g against rho g (H - h) = %.6g) over %zu bins below H - %.6g",
                  name().c_str(), time_, height_, 100 * worstRelative_, worstHeight_, worstPressure_,
                  worstExact_, binsUsed_, surfaceBand_);
    return {s};
}

MFDYN_REGISTER(FunctionObject, HydrostaticPressure, "hydrostaticPressure",
               "pressure binned by height along a vertical line against rho g (H - h), with error norms");

}  // namespace mfdyn
