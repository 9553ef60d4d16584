// freeSurfaceFront: the surge front and the column height of a collapsing fluid column, the two
// quantities Martin & Moyce (1952, Phil. Trans. R. Soc. A 244:312, Figs. 3 and 5) measured:
//
//     front { type freeSurfaceFront; region water; wallBand 0.0057; }
//
// With s = x . d (d = `direction`, default +x, the way the surge runs) and h = x . u (u = `up`,
// default +y; in 3D +z), each write gives
//   wall    min s over the fluid (the column stays against the back wall);
//   front   the largest s of the fluid, made robust to a few stray particles (a droplet thrown
//           ahead, a particle left behind a splash) as the mass quantile: the smallest s_f with at
//           most `strayFraction` (default 1e-3) of the fluid's mass beyond it, m(s > s_f) <= f M.
//           With f = 0 it is the plain maximum; with N equal particles f M skips up to f N of them;
//   height  the same quantile of h over the particles within `wallBand` of the wall
//           (s - wall <= wallBand; about a cell), the column height at the wall.
// frontPosition.csv: time, wall, front, height (the front and height as coordinates; the surge
// length is front - wall). The quantile is a bisection on the global sums of mass beyond a trial
// value (60 halvings: to round-off of the body's extent), so it is the same on any number of
// ranks and threads.
#include "functionObjects/FreeSurfaceFront.hpp"

#include "core/Error.hpp"
#include "core/Parallel.hpp"
#include "functionObjects/RegionLookup.hpp"
#include "particles/ParticleSetBase.hpp"

#include <cmath>
#include <cstdio>
#include <limits>

namespace mfdyn {

KeywordSchema FreeSurfaceFront::keywords() {
    return KeywordSchema("functionObject", "freeSurfaceFront")
        .identifier("region", "the fluid (particleGen region) whose front is measured (default: all)")
        .optional()
        .vector("direction", "-", "the way the surge runs (default +x)")
        .optional()
        .example("(1 0)")
        .vector("up", "-", "against gravity: the column height's axis (default +y in 2D, +z in 3D)")
        .optional()
        .example("(0 1)")
        .scalar("wallBand", "m", "width of the band at the back wall where the column height is taken")
        .greaterThan(0)
        .scalar("strayFraction", "-",
                "mass fraction allowed beyond the front and the height (stray particles)")
        .optional()
        .example("1e-3")
        .append(functionObjectKeywords());
}

FreeSurfaceFront::FreeSurfaceFront(const Dictionary& dict, const std::string& name, const RunContext& context)
    : FreeSurfaceFront(keywords().read(dict), name, context) {}

namespace {
void unitVector(const KeywordValues& values, const char* key, int dim, double* out) {
    const Dictionary& dict = values.dict();
    const auto& v = values.vector(key);
    if (int(v.size()) < dim) throw dict.error(key, "expected " + std::to_string(dim) + " components");
    double norm = 0;
    for (int k = 0; k < dim; ++k) norm += v[k] * v[k];
    if (!(norm > 0) || !std::isfinite(norm)) throw dict.error(key, "must be a non-zero finite vector");
    for (int k = 0; k < 3; ++k) out[k] = k < dim ? v[k] / std::sqrt(norm) : 0.0;
}
}  // namespace

FreeSurfaceFront::FreeSurfaceFront(const KeywordValues& values, const std::string& name,
                                   const RunContext& context)
    : FunctionObject(values, name, context, ParticleScope::owned), band_(values.scalar("wallBand")) {
    const Dictionary& dict = values.dict();
    const int dim = context.dimension();
    if (dim < 2) throw dict.error("type", "freeSurfaceFront needs a 2D or 3D run (a front and a height)");
    requireField(dict, "type", "mass");
    if (values.given("region")) {
        requireField(dict, "region", "region");
        regionName_ = values.word("region");
        region_ = regionIndex(dict, "region", regionName_, context);
    }
    up_[1] = dim == 3 ? 0 : 1;
    up_[2] = dim == 3 ? 1 : 0;
    if (values.given("direction")) unitVector(values, "direction", dim, along_);
    if (values.given("up")) unitVector(values, "up", dim, up_);
    if (auto f = values.optionalScalar("strayFraction")) {
        if (!(*f >= 0 && *f < 0.5)) throw dict.error("strayFraction", "must lie in [0, 0.5)");
        stray_ = *f;
    }
    csv_ =
        std::make_unique<CsvFile>(outputFile("frontPosition.csv"),
                                  std::vector<std::string>{"time", "wall", "front", "height"}, startTime());
}

void FreeSurfaceFront::write() {
    const FieldStore& fields = context().fields();
    const int dim = fields.dimension();
    const std::size_t n = context().ownedParticles();
    const FieldBase& x = fields.field("position");
    const FieldBase& m = fields.field("mass");
    const FieldBase* region = region_ >= 0 ? &fields.field("region") : nullptr;
    const auto member = [&](std::size_t i) {
        return !region || std::int64_t(region->component(i, 0)) == region_;
    };
    const auto project = [&](std::size_t i, const double* e) {
        double s = 0;
        for (int d = 0; d < dim; ++d) s += x.component(i, d) * e[d];
        return s;
    };
    const double inf = std::numeric_limits<double>::infinity();
    wall_ = GlobalReduce::min(n, [&](std::size_t i) { return member(i) ? project(i, along_) : inf; });
    if (wall_ == inf)
        throw RunError("freeSurfaceFront '" + name() + "': no particle" +
                       (regionName_.empty() ? std::string() : " in region '" + regionName_ + "'"));
    // The mass quantile of q over the particles `in`: the smallest value with at most stray_ M of
    // their mass above it, by bisection between their extremes.
    const auto quantile = [&](auto&& in, const double* e) {
        const auto q = [&](std::size_t i) { return project(i, e); };
        const double hi0 = GlobalReduce::max(n, [&](std::size_t i) { return in(i) ? q(i) : -inf; });
        const double lo0 = GlobalReduce::min(n, [&](std::size_t i) { return in(i) ? q(i) : inf; });
        const double total =
            GlobalReduce::sum<double>(n, [&](std::size_t i) { return in(i) ? m.component(i, 0) : 0.0; });
        double lo = lo0, hi = hi0;
        if (stray_ == 0 || !(hi > lo)) return hi;
        for (int k = 0; k < 60 && hi > lo; ++k) {
            const double mid = 0.5 * (lo + hi);
            const double beyond = GlobalReduce::sum<double>(
                n, [&](std::size_t i) { return in(i) && q(i) > mid ? m.component(i, 0) : 0.0; });
            (beyond <= stray_ * total ? hi : lo) = mid;
        }
        return hi;
    };
    front_ = quantile(member, along_);
    const double wall = wall_, band = band_;
    height_ = quantile([&](std::size_t i) { return member(i) && project(i, along_) - wall <= band; }, up_);
    time_ = context().time().value();
    ++writes_;
    csv_->row({time_, wall_, front_, height_});
}

std::vector<std::string> FreeSurfaceFront::summary() const {
    if (writes_ == 0) return {};
    char s[240];
    std::snprintf(
        s, sizeof s,
        "freeSurfaceFront '%s': at t = %.6g the front %.6g (%.6g from the wall at %.6g), the column "
        "height at the wall %.6g (stray mass fraction %.3g)",
        name().c_str(), time_, front_, front_ - wall_, wall_, height_, stray_);
    return {s};
}

MFDYN_REGISTER(
    FunctionObject, FreeSurfaceFront, "freeSurfaceFront",
    "surge front and column height of a collapsing fluid column (dam break), robust to stray particles");

}  // namespace mfdyn
