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
// bodyExtents.csv: time, l_x, l_y(, l_z). With `reference` (one value per column), the latest
// extents and their errors go into the summary beside the run time (referenceValues l_x, l_y ...).
// Extremes are global reductions (max, min), so an MPI build measures the whole body.
#include "functionObjects/BodyExtents.hpp"

#include "core/Error.hpp"
#include "core/Parallel.hpp"
#include "functionObjects/RegionLookup.hpp"
#include "particles/ParticleSetBase.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace mfdyn {

namespace {
const char* axes[] = {"x", "y", "z"};
}

KeywordSchema BodyExtents::keywords() {
    return KeywordSchema("functionObject", "bodyExtents")
        .identifier("region", "the body (particleGen region) to measure (default: all particles)")
        .optional()
        .word("mode", {"bounds", "lines"},
              "bounding extents, or (2D) the top row's length l_x and the centre column's l_y")
        .orDefault("bounds")
        .vector("reference", "m", "expected extents, one per direction (l_x l_y ...), for the summary")
        .optional()
        .example("(0.0321 0.1208)")
        .append(functionObjectKeywords());
}

BodyExtents::BodyExtents(const Dictionary& dict, const std::string& name, const RunContext& context)
    : BodyExtents(keywords().read(dict), name, context) {}

BodyExtents::BodyExtents(const KeywordValues& values, const std::string& name, const RunContext& context)
    : FunctionObject(values, name, context), lines_(values.word("mode") == "lines") {
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
    std::vector<std::string> columns{"time"};
    for (int d = 0; d < dim; ++d) columns.push_back(std::string("l_") + axes[d]);
    csv_ = std::make_unique<CsvFile>(outputFile("bodyExtents.csv"), columns, startTime());
}

void BodyExtents::chooseLines() {
    const FieldStore& fields = context().fields();
    const std::size_t n = fields.size();
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
    // (An MPI build would gather the ids of every rank here.)
    std::sort(row_.begin(), row_.end());
    std::sort(column_.begin(), column_.end());
}

void BodyExtents::write() {
    const FieldStore& fields = context().fields();
    const int dim = fields.dimension();
    const std::size_t n = fields.size();
    const FieldBase& x = fields.field("position");
    const FieldBase* region = region_ >= 0 ? &fields.field("region") : nullptr;
    const auto member = [&](std::size_t i) {
        return !region || std::int64_t(region->component(i, 0)) == region_;
    };
    if (lines_ && !written_) chooseLines();
    written_ = true;
    const double inf = std::numeric_limits<double>::infinity();
    extents_.assign(dim, 0.0);
    std::vector<double> row{context().time().value()};
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
    csv_->row(row);
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
