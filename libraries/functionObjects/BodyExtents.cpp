// bodyExtents: the extents of a body, the width and height of the material point method's
// hanging block (doc/methods/mpm.md section 4.2, Tables 6-9: l_y about 0.120, l_x about 0.032).
//
//     block { type bodyExtents; region block; mode lines; reference (0.0321 0.1208); }
//
//   mode bounds (default): l_d = max_a x_a,d - min_a x_a,d over the region's particles (default:
//                every particle), each direction of the run;
//   mode lines (2D): the thesis's measures: l_x the distance between the first and last particle
//                of the top row, l_y that of the centre column, rows and column as they are at the
//                first write: the top row the particles at the largest y (within 1e-9 of the
//                body's height), the centre column those at the x nearest the middle of the
//                body's x range (of two columns equally near, the one of smaller x). A block that
//                hangs from its top contracts most there, so its top row is narrower than the
//                body's widest extent: the two modes differ (l_x 0.032 against about 0.06).
//                With k x k points the initial l_x = l_y = 0.06 (1 - 1/k).
//   mode radius (2D, 3D): a body about an axis (a sphere squeezed or sheared about x3):
//                r = max_a |(x_a - c) - ((x_a - c).e) e|, the largest distance from the axis e
//                through the centre c, the height max_a (x_a - c).e - min_a (x_a - c).e (3D),
//                and r_ring, the mean of those distances over the particles at 0.8 r or more
//                (the outer ring: less at the mercy of one particle than the largest);
//                `axis` (3D; default (0 0 1), normalised) and `centre` (default the body's
//                centroid at each write, mass-weighted where the run has `mass`, else the mean
//                position). In 2D the axis is the out-of-plane one: r = max_a |x_a - c|.
//
//     sphere { type bodyExtents; mode radius; axis (0 0 1); directions ((1 1 0) (1 -1 0)); }
//
//   directions (optional, modes bounds and radius): l_dk = max_a x_a.d_k - min_a x_a.d_k for each
//                given direction d_k (normalised when read): the elongation of a sheared sphere
//                along the bisector x1 = x2, ((1 1 0) (1 -1 0) (0 0 1)), and normal to it.
// bodyExtents.csv: time, l_x, l_y(, l_z) (mode radius: time, r(, height), r_ring), then l_d1,
// l_d2 ... for the directions. With `reference` (one value per l_x l_y ..., modes bounds and
// lines), the latest extents and their errors go into the summary beside the run time
// (referenceValues l_x, l_y ...).
// Extremes and sums are global reductions, and the ids of mode lines' row and column are those of
// every rank, so an MPI build measures the whole body.
#include "functionObjects/BodyExtents.hpp"

#include "core/Communicator.hpp"
#include "core/Dictionary.hpp"
#include "core/Error.hpp"
#include "core/Parallel.hpp"
#include "functionObjects/RegionLookup.hpp"
#include "particles/ParticleSetBase.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <limits>

namespace mfdyn {

namespace {
const char* axes[] = {"x", "y", "z"};

// `v` (dim components, not zero) divided by its length, zero-padded to 3.
std::array<double, 3> unitVector(const Dictionary& dict, const std::string& key, const std::vector<double>& v,
                                 int dim, const std::string& what = "") {
    if (int(v.size()) != dim)
        throw dict.error(
            key, what + "expected " + std::to_string(dim) + " components, found " + std::to_string(v.size()));
    double norm = 0;
    for (double c : v) norm += c * c;
    norm = std::sqrt(norm);
    if (!(norm > 0) || !std::isfinite(norm)) throw dict.error(key, what + "a direction must be non-zero");
    std::array<double, 3> u{0, 0, 0};
    for (std::size_t d = 0; d < v.size(); ++d) u[d] = v[d] / norm;
    return u;
}

// `directions ((1 1 0) (1 -1 0));`: each of dim numbers, normalised.
std::vector<std::array<double, 3>> readDirections(const Dictionary& dict, int dim) {
    const Entry& entry = dict.entry("directions");
    const auto bad = [&](const std::string& what) {
        return dict.error("directions", "expected a list of directions ((1 1 0) ...): " + what);
    };
    if (entry.tokens.size() != 1 || entry.tokens[0].kind != Token::Kind::list) throw bad("not a list");
    std::vector<std::array<double, 3>> out;
    for (const Token& t : entry.tokens[0].list) {
        if (t.kind != Token::Kind::list)
            throw bad("'" + t.str() + "' is not a direction (a list of numbers)");
        std::vector<double> v;
        for (const Token& c : t.list) {
            if (!c.isNumber()) throw bad("'" + t.str() + "' holds a non-number");
            v.push_back(c.number());
        }
        std::string which = "'";  // (built in steps: GCC 12 warns of a bogus overlap in "'" + str)
        which += t.str();
        which += "': ";
        out.push_back(unitVector(dict, "directions", v, dim, which));
    }
    if (out.empty()) throw bad("the list is empty");
    return out;
}

// The ids of every rank together, sorted (collective).
std::vector<std::int64_t> allRanksIds(const std::vector<std::int64_t>& mine) {
    std::vector<std::int64_t> all = mine;
    if (Communicator::distributed()) {
        std::vector<char> bytes(mine.size() * sizeof(std::int64_t));
        if (!bytes.empty()) std::memcpy(bytes.data(), mine.data(), bytes.size());
        all.clear();
        for (const auto& part : Communicator::allGatherVariable(bytes)) {
            const std::size_t first = all.size();
            all.resize(first + part.size() / sizeof(std::int64_t));
            if (!part.empty()) std::memcpy(all.data() + first, part.data(), part.size());
        }
    }
    std::sort(all.begin(), all.end());
    return all;
}
}  // namespace

KeywordSchema BodyExtents::keywords() {
    return KeywordSchema("functionObject", "bodyExtents")
        .identifier("region", "the body (particleGen region) to measure (default: all particles)")
        .optional()
        .word("mode", {"bounds", "lines", "radius"},
              "bounding extents, or (2D) the top row's length l_x and the centre column's l_y, or the "
              "radius about an axis and the height along it")
        .orDefault("bounds")
        .vector("reference", "m", "expected extents, one per direction (l_x l_y ...), for the summary")
        .optional()
        .example("(0.0321 0.1208)")
        .table("directions", "-",
               "extra directions ((1 1 0) (1 -1 0) ...), normalised: l_dk = max x.d_k - min x.d_k "
               "(modes bounds, radius)")
        .optional()
        .example("((1 1 0) (1 -1 0))")
        .vector("axis", "-", "mode radius (3D): the axis, normalised (default (0 0 1))")
        .optional()
        .example("(0 0 1)")
        .vector("centre", "m", "mode radius: the centre (default: the body's centroid at each write)")
        .optional()
        .example("(0 0 0)")
        .append(functionObjectKeywords());
}

BodyExtents::BodyExtents(const Dictionary& dict, const std::string& name, const RunContext& context)
    : BodyExtents(keywords().read(dict), name, context) {}

BodyExtents::BodyExtents(const KeywordValues& values, const std::string& name, const RunContext& context)
    : FunctionObject(values, name, context, ParticleScope::owned),
      lines_(values.word("mode") == "lines"),
      radius_(values.word("mode") == "radius") {
    const Dictionary& dict = values.dict();
    const int dim = context.dimension();
    if (lines_) {
        if (dim != 2)
            throw dict.error("mode",
                             "mode lines (the top row and centre column of a 2D block) needs a 2D run, "
                             "and this one is " +
                                 std::to_string(dim) + "D: use mode bounds");
        requireField(dict, "mode", "globalId");
    }
    if (values.given("region")) {
        requireField(dict, "region", "region");
        regionName_ = values.word("region");
        region_ = regionIndex(dict, "region", regionName_, context);
    }
    if (values.given("reference")) {
        reference_ = values.vector("reference");
        if (int(reference_.size()) != dim)
            throw dict.error("reference", "expected " + std::to_string(dim) + " extents (l_x l_y" +
                                              (dim == 3 ? " l_z" : "") + "), found " +
                                              std::to_string(reference_.size()));
    }
    if (radius_ && dim < 2)
        throw dict.error("mode", "mode radius (about an axis) needs a 2D or 3D run, and this one is 1D");
    if (radius_ && values.given("reference"))
        throw dict.error(
            "reference",
            "reference compares the extents l_x l_y ... of modes bounds and lines, not mode radius");
    for (const char* key : {"axis", "centre"})
        if (values.given(key) && !radius_)
            throw dict.error(key, std::string(key) + " is mode radius's: give mode radius or no " + key);
    if (values.given("axis")) {
        if (dim != 3)
            throw dict.error("axis",
                             "in a " + std::to_string(dim) +
                                 "D run mode radius measures about the out-of-plane axis: give no axis");
        axis_ = unitVector(dict, "axis", values.vector("axis"), dim);
    }
    if (values.given("centre")) {
        const std::vector<double>& c = values.vector("centre");
        if (int(c.size()) != dim)
            throw dict.error("centre", "expected " + std::to_string(dim) + " components, found " +
                                           std::to_string(c.size()));
        fixedCentre_ = true;
        for (int d = 0; d < dim; ++d) centre_[std::size_t(d)] = c[std::size_t(d)];
    }
    if (values.given("directions")) {
        if (lines_)
            throw dict.error("directions",
                             "directions are whole-body extents: modes bounds and radius, not lines");
        directions_ = readDirections(dict, dim);
    }
    std::vector<std::string> columns{"time"};
    if (radius_) {
        columns.push_back("r");
        if (dim == 3) columns.push_back("height");
        columns.push_back("r_ring");
    } else {
        for (int d = 0; d < dim; ++d) columns.push_back(std::string("l_") + axes[d]);
    }
    for (std::size_t k = 0; k < directions_.size(); ++k) columns.push_back("l_d" + std::to_string(k + 1));
    csv_ = std::make_unique<CsvFile>(outputFile("bodyExtents.csv"), columns, startTime());
}

void BodyExtents::chooseLines() {
    const FieldStore& fields = context().fields();
    const std::size_t n = context().ownedParticles();
    const FieldBase& x = fields.field("position");
    const FieldBase& gid = fields.field("globalId");
    const FieldBase* region = region_ >= 0 ? &fields.field("region") : nullptr;
    const auto member = [&](std::size_t i) {
        return !region || std::int64_t(region->component(i, 0)) == region_;
    };
    const double inf = std::numeric_limits<double>::infinity();
    double lo[2] = {inf, inf}, hi[2] = {-inf, -inf};
    for (std::size_t i = 0; i < n; ++i)
        if (member(i))
            for (int d = 0; d < 2; ++d)
                lo[d] = std::min(lo[d], x.component(i, d)), hi[d] = std::max(hi[d], x.component(i, d));
    for (int d = 0; d < 2; ++d) lo[d] = globalMin(lo[d]), hi[d] = -globalMin(-hi[d]);
    if (!(hi[0] >= lo[0]))
        throw RunError("bodyExtents '" + name() + "': no particle" +
                       (regionName_.empty() ? std::string() : " in region '" + regionName_ + "'"));
    // The centre column: the x nearest the middle (ties: the smaller x).
    const double middle = 0.5 * (lo[0] + hi[0]);
    double best = inf;
    for (std::size_t i = 0; i < n; ++i)
        if (member(i)) best = std::min(best, std::abs(x.component(i, 0) - middle));
    best = globalMin(best);
    // Of the columns at that distance, the smaller x (the other is its mirror image).
    double chosen = inf;
    for (std::size_t i = 0; i < n; ++i)
        if (member(i) && std::abs(x.component(i, 0) - middle) == best)
            chosen = std::min(chosen, x.component(i, 0));
    chosen = globalMin(chosen);
    // Rows and columns of a lattice share their coordinate up to round-off of the generator.
    const double tolerance[2] = {1e-9 * std::max(hi[0] - lo[0], 1e-300),
                                 1e-9 * std::max(hi[1] - lo[1], 1e-300)};
    row_.clear(), column_.clear();
    for (std::size_t i = 0; i < n; ++i) {
        if (!member(i)) continue;
        const auto id = std::int64_t(gid.component(i, 0));
        if (hi[1] - x.component(i, 1) <= tolerance[1]) row_.push_back(id);
        if (std::abs(x.component(i, 0) - chosen) <= tolerance[0]) column_.push_back(id);
    }
    // Every rank's, on every rank: a particle of the row may move to another rank later.
    row_ = allRanksIds(row_);
    column_ = allRanksIds(column_);
}

void BodyExtents::write() {
    const FieldStore& fields = context().fields();
    const int dim = fields.dimension();
    const std::size_t n = context().ownedParticles();
    const FieldBase& x = fields.field("position");
    const FieldBase* region = region_ >= 0 ? &fields.field("region") : nullptr;
    const auto member = [&](std::size_t i) {
        return !region || std::int64_t(region->component(i, 0)) == region_;
    };
    if (lines_ && !written_) chooseLines();
    written_ = true;
    const double inf = std::numeric_limits<double>::infinity();
    std::vector<double> row{context().time().value()};
    if (radius_) {
        writeRadius(row);
        writeDirections(row);
        csv_->row(row);
        return;
    }
    extents_.assign(dim, 0.0);
    for (int d = 0; d < dim; ++d) {
        const std::vector<std::int64_t>* line = lines_ ? (d == 0 ? &row_ : &column_) : nullptr;
        const FieldBase* gid = lines_ ? &fields.field("globalId") : nullptr;
        double lo = inf, hi = -inf;
        for (std::size_t i = 0; i < n; ++i) {
            if (!member(i)) continue;
            if (line && !std::binary_search(line->begin(), line->end(), std::int64_t(gid->component(i, 0))))
                continue;
            lo = std::min(lo, x.component(i, d));
            hi = std::max(hi, x.component(i, d));
        }
        lo = globalMin(lo), hi = -globalMin(-hi);
        if (!(hi >= lo))
            throw RunError("bodyExtents '" + name() + "': no particle" +
                           (regionName_.empty() ? std::string() : " in region '" + regionName_ + "'") +
                           (lines_ ? std::string(" on the ") + (d == 0 ? "top row" : "centre column") +
                                         " chosen at the first write (removed since)"
                                   : std::string()));
        extents_[d] = hi - lo;
        row.push_back(extents_[d]);
    }
    writeDirections(row);
    csv_->row(row);
}

bool BodyExtents::member(const FieldBase* region, std::size_t i) const {
    return !region || std::int64_t(region->component(i, 0)) == region_;
}

std::string BodyExtents::noParticle() const {
    return "bodyExtents '" + name() + "': no particle" +
           (regionName_.empty() ? std::string() : " in region '" + regionName_ + "'");
}

void BodyExtents::writeDirections(std::vector<double>& row) const {
    if (directions_.empty()) return;
    const FieldStore& fields = context().fields();
    const int dim = fields.dimension();
    const std::size_t n = context().ownedParticles();
    const FieldBase& x = fields.field("position");
    const FieldBase* region = region_ >= 0 ? &fields.field("region") : nullptr;
    const double inf = std::numeric_limits<double>::infinity();
    for (const auto& dir : directions_) {
        double lo = inf, hi = -inf;
        for (std::size_t i = 0; i < n; ++i) {
            if (!member(region, i)) continue;
            double s = 0;
            for (int d = 0; d < dim; ++d) s += x.component(i, d) * dir[std::size_t(d)];
            lo = std::min(lo, s), hi = std::max(hi, s);
        }
        lo = globalMin(lo), hi = -globalMin(-hi);
        if (!(hi >= lo)) throw RunError(noParticle());
        row.push_back(hi - lo);
    }
}

void BodyExtents::writeRadius(std::vector<double>& row) const {
    const FieldStore& fields = context().fields();
    const int dim = fields.dimension();
    const std::size_t n = context().ownedParticles();
    const FieldBase& x = fields.field("position");
    const FieldBase* region = region_ >= 0 ? &fields.field("region") : nullptr;
    // The centre: given, or the centroid (mass-weighted where there are masses, like bodyCentroid).
    std::array<double, 3> c = centre_;
    if (!fixedCentre_) {
        const FieldBase* mass = fields.findField("mass");
        if (mass && mass->kind() != FieldKind::scalar) mass = nullptr;
        double w = 0, m = 0, sx[3] = {0, 0, 0}, sm[3] = {0, 0, 0};
        for (std::size_t i = 0; i < n; ++i) {
            if (!member(region, i)) continue;
            const double mi = mass ? mass->component(i, 0) : 0.0;
            w += 1, m += mi;
            for (int d = 0; d < dim; ++d) sx[d] += x.component(i, d), sm[d] += mi * x.component(i, d);
        }
        w = globalSum(w), m = globalSum(m);
        if (!(w > 0)) throw RunError(noParticle());
        for (int d = 0; d < dim; ++d) {
            sx[d] = globalSum(sx[d]), sm[d] = globalSum(sm[d]);
            c[std::size_t(d)] = m > 0 ? sm[d] / m : sx[d] / w;  // no (or zero) masses: the mean position
        }
    }
    // The distance from the axis and the height along it of particle i.
    const auto measure = [&](std::size_t i, double& rho, double& h) {
        double v[3] = {0, 0, 0};
        for (int d = 0; d < dim; ++d) v[d] = x.component(i, d) - c[std::size_t(d)];
        h = dim == 3 ? v[0] * axis_[0] + v[1] * axis_[1] + v[2] * axis_[2] : 0.0;
        double r2 = 0;
        for (int d = 0; d < 3; ++d) {
            const double q = v[d] - (dim == 3 ? h * axis_[std::size_t(d)] : 0.0);
            r2 += q * q;
        }
        rho = std::sqrt(r2);
    };
    const double inf = std::numeric_limits<double>::infinity();
    double r = -inf, lo = inf, hi = -inf;
    for (std::size_t i = 0; i < n; ++i) {
        if (!member(region, i)) continue;
        double rho, h;
        measure(i, rho, h);
        r = std::max(r, rho), lo = std::min(lo, h), hi = std::max(hi, h);
    }
    r = -globalMin(-r), lo = globalMin(lo), hi = -globalMin(-hi);
    if (!(hi >= lo)) throw RunError(noParticle());
    // The outer ring: the particles at 0.8 r or more from the axis (never empty: the farthest is).
    double ringSum = 0, ringCount = 0;
    for (std::size_t i = 0; i < n; ++i) {
        if (!member(region, i)) continue;
        double rho, h;
        measure(i, rho, h);
        if (rho >= 0.8 * r) ringSum += rho, ringCount += 1;
    }
    ringSum = globalSum(ringSum), ringCount = globalSum(ringCount);
    row.push_back(r);
    if (dim == 3) row.push_back(hi - lo);
    row.push_back(ringSum / ringCount);
}

std::vector<ReferenceValue> BodyExtents::referenceValues() const {
    if (reference_.empty() || !written_) return {};
    std::vector<ReferenceValue> out;
    for (std::size_t d = 0; d < extents_.size(); ++d)
        out.push_back({std::string("l_") + axes[d], extents_[d], reference_[d]});
    return out;
}

MFDYN_REGISTER(
    FunctionObject, BodyExtents, "bodyExtents",
    "extents of a body: bounding, or (2D) its top row and centre column, with optional references");

}  // namespace mfdyn
