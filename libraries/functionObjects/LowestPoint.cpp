// lowestPoint: the displacement of a body's lowest particle, the tip of the material point
// method's hanging spring (doc/methods/mpm.md section 4.1: the downward displacement of the lowest
// material point, y0 = 0.81; thesis 3.005e-3, linear 2.943e-3, exact StVK 2.861e-3).
//
//     tip { type lowestPoint; region bar; direction (0 -1); reference 2.943e-3; }
//
// `direction` d (default -y in 2D, -z in 3D, -x in 1D; normalised) says which way is down: at the
// first write the particle of the region (default: every particle) farthest along d is chosen
// (ties: the lowest global id) and followed by its global id; each write gives its displacement
// along d, u = (x - x0) . d, positive when it moves down, x0 its position at that first write (a
// restarted run measures from its restart). lowestPoint.csv: time, displacement,
// meanDisplacement (the mean over this object's writes so far, the notebook's time mean), and the
// particle's position. With `reference`, the latest displacement and its error go into the
// summary beside the run time (referenceValues). The summary also gives the largest displacement
// and when it happened (the undamped spring's first peak, 2 u_s at 2L/c).
// The choice and the look-up are global reductions (min of the ids, sums), so an MPI build finds
// the particle on whichever rank holds it.
#include "functionObjects/LowestPoint.hpp"

#include "core/Error.hpp"
#include "core/Parallel.hpp"
#include "functionObjects/RegionLookup.hpp"
#include "particles/ParticleSetBase.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

namespace mfdyn {

KeywordSchema LowestPoint::keywords() {
    return KeywordSchema("functionObject", "lowestPoint")
        .identifier("region",
                    "the body (particleGen region) whose lowest particle is followed (default: all)")
        .optional()
        .vector("direction", "-", "which way is down (default -y in 2D, -z in 3D, -x in 1D)")
        .optional()
        .example("(0 -1)")
        .scalar("reference", "m", "the expected displacement, for the summary's error line")
        .optional()
        .append(functionObjectKeywords());
}

LowestPoint::LowestPoint(const Dictionary& dict, const std::string& name, const RunContext& context)
    : LowestPoint(keywords().read(dict), name, context) {}

LowestPoint::LowestPoint(const KeywordValues& values, const std::string& name, const RunContext& context)
    : FunctionObject(values, name, context, ParticleScope::owned),
      reference_(values.optionalScalar("reference")) {
    const Dictionary& dict = values.dict();
    const int dim = context.dimension();
    requireField(dict, "type", "globalId");
    if (values.given("region")) {
        requireField(dict, "region", "region");
        regionName_ = values.word("region");
        region_ = regionIndex(dict, "region", regionName_, context);
    }
    down_[dim - 1] = -1;
    if (values.given("direction")) {
        const auto& d = values.vector("direction");
        if (int(d.size()) < dim)
            throw dict.error("direction", "expected " + std::to_string(dim) + " components");
        double norm = 0;
        for (int k = 0; k < dim; ++k) norm += d[k] * d[k];
        if (!(norm > 0) || !std::isfinite(norm))
            throw dict.error("direction", "the direction must be a non-zero finite vector");
        for (int k = 0; k < dim; ++k) down_[k] = d[k] / std::sqrt(norm);
    }
    std::vector<std::string> columns{"time", "displacement", "meanDisplacement"};
    const char* axes[] = {"x", "y", "z"};
    for (int d = 0; d < dim; ++d) columns.push_back(std::string("position_") + axes[d]);
    csv_ = std::make_unique<CsvFile>(outputFile("lowestPoint.csv"), columns, startTime());
}

void LowestPoint::write() {
    const FieldStore& fields = context().fields();
    const int dim = fields.dimension();
    const std::size_t n = context().ownedParticles();
    const FieldBase& x = fields.field("position");
    const FieldBase& gid = fields.field("globalId");
    const FieldBase* region = region_ >= 0 ? &fields.field("region") : nullptr;
    const auto depth = [&](std::size_t i) {
        double s = 0;
        for (int d = 0; d < dim; ++d) s += x.component(i, d) * down_[d];
        return s;
    };
    const auto member = [&](std::size_t i) {
        return !region || std::int64_t(region->component(i, 0)) == region_;
    };
    const double noDepth = -std::numeric_limits<double>::infinity();
    if (id_ < 0) {
        // The deepest particle, then the lowest id among those as deep.
        double deepest = noDepth;
        for (std::size_t i = 0; i < n; ++i)
            if (member(i)) deepest = std::max(deepest, depth(i));
        deepest = globalMax(deepest);
        if (deepest == noDepth)
            throw RunError("lowestPoint '" + name() + "': no particle" +
                           (regionName_.empty() ? std::string() : " in region '" + regionName_ + "'"));
        double lowest = std::numeric_limits<double>::infinity();
        for (std::size_t i = 0; i < n; ++i)
            if (member(i) && depth(i) == deepest) lowest = std::min(lowest, gid.component(i, 0));
        id_ = std::int64_t(globalMin(lowest));
    }
    // The tracked particle's position (on one rank; the others add zeros), and whether it exists.
    const SumArray<4> found = GlobalReduce::sum<SumArray<4>>(n, [&](std::size_t i) {
        SumArray<4> s;
        if (std::int64_t(gid.component(i, 0)) != id_) return s;
        for (int d = 0; d < dim; ++d) s.s[d] = x.component(i, d);
        s.s[3] = 1;
        return s;
    });
    if (found.s[3] != 1)
        throw RunError("lowestPoint '" + name() + "': the particle followed (global id " +
                       std::to_string(id_) + ") is no longer in the run (removed)");
    if (writes_ == 0)
        for (int d = 0; d < dim; ++d) start_[d] = found.s[d];
    displacement_ = 0;
    for (int d = 0; d < dim; ++d) displacement_ += (found.s[d] - start_[d]) * down_[d];
    ++writes_;
    sum_ += displacement_;
    if (writes_ == 1 || displacement_ > peak_) peak_ = displacement_, peakTime_ = context().time().value();
    std::vector<double> row{context().time().value(), displacement_, sum_ / double(writes_)};
    for (int d = 0; d < dim; ++d) row.push_back(found.s[d]);
    csv_->row(row);
}

std::vector<ReferenceValue> LowestPoint::referenceValues() const {
    if (!reference_ || writes_ == 0) return {};
    return {{"displacement", displacement_, *reference_}};
}

std::vector<std::string> LowestPoint::summary() const {
    if (writes_ == 0) return {};
    char s[240];
    std::snprintf(s, sizeof s,
                  "lowestPoint '%s': particle %lld, displacement %.6g (mean over %zu writes %.6g), largest "
                  "%.6g at t = %.6g",
                  name().c_str(), static_cast<long long>(id_), displacement_, writes_, sum_ / double(writes_),
                  peak_, peakTime_);
    return {s};
}

MFDYN_REGISTER(FunctionObject, LowestPoint, "lowestPoint",
               "displacement of a body's lowest particle along a direction, with an optional reference");

}  // namespace mfdyn
