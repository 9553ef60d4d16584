// debrisCloud: the measures a shadowgraph of a hypervelocity impact gives (Piekutowski 1996;
// Hiermaier 1997; Zisis 2017 §6.2), from the particles. With s = x·d the distance along the impact
// direction d and ℓ the lateral distance from the impact axis (through the origin):
//
//   debris       particles with s > rear (behind the target's rear face)
//   length L     max s over the debris − rear            (from the rear face to the cloud's tip)
//   width W      max ℓ − min ℓ over the debris in 2D, 2·max |ℓ| in 3D (largest lateral extent)
//   hole D       in 2D: the gap between the innermost target particles left and right of the axis
//                still within the target's original thickness; in 3D: twice the smallest |ℓ| there
//
// Isolated outliers would set extents no shadowgraph shows, so each extreme is taken at the
// `trim` quantile of the particles (default 0.005: half a percent dropped at each end).
//
//     debris { type debrisCloud; direction (0 -1); rear 0.004; front 0; targetRegions (plate); }
//
// rear and front are the target's faces as distances along `direction` (here y = -4 mm and 0).
// Writes debrisCloud.csv (time, length, width, lengthOverWidth, holeDiameter, debrisParticles)
// and, for pictures, cloud_<time>.csv (particle positions and region) at each write.
#include "functionObjects/DebrisCloud.hpp"

#include "particles/ParticleSetBase.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace mfdyn {

namespace {

double quantile(std::vector<double> v, double q) {
    if (v.empty()) return NAN;
    const std::size_t k = std::min(v.size() - 1, std::size_t(q * double(v.size() - 1) + 0.5));
    std::nth_element(v.begin(), v.begin() + long(k), v.end());
    return v[k];
}

}  // namespace

KeywordSchema DebrisCloud::keywords() {
    return KeywordSchema("functionObject", "debrisCloud")
        .vector("direction", "-", "the projectile's direction of flight (normalised when read)")
        .example("(1 0 0)")
        .scalar("front", "m", "position of the target's front face along direction")
        .scalar("rear", "m", "position of the target's rear face along direction (debris: beyond it)")
        .scalar("trim", "-", "fraction of the debris particles left out at each end of the extents")
        .atLeast(0)
        .lessThan(0.5)
        .orDefault(0.005)
        .words("targetRegions", "the regions of the target plate (for the hole)")
        .append(functionObjectKeywords());
}

DebrisCloud::DebrisCloud(const Dictionary& dict, const std::string& name, const RunContext& context)
    : DebrisCloud(keywords().read(dict), name, context) {}

DebrisCloud::DebrisCloud(const KeywordValues& values, const std::string& name, const RunContext& context)
    : FunctionObject(values, name, context),
      direction_(values.vector("direction")),
      rear_(values.scalar("rear")),
      front_(values.scalar("front")),
      trim_(values.scalar("trim")) {
    const Dictionary& dict = values.dict();
    const int dim = context.dimension();
    if (dim < 2) throw dict.error("type", "debrisCloud measures 2D and 3D runs");
    if (int(direction_.size()) < dim)
        throw dict.error("direction", "expected " + std::to_string(dim) + " components");
    direction_.resize(dim);
    double norm = 0;
    for (double c : direction_) norm += c * c;
    if (!(norm > 0)) throw dict.error("direction", "direction must not be zero");
    for (double& c : direction_) c /= std::sqrt(norm);
    if (!(rear_ > front_)) throw dict.error("rear", "rear must lie beyond front along the direction");

    const auto& regionNames = dynamic_cast<const ParticleSetBase&>(context.fields()).regionNames;
    for (const auto& region : values.words("targetRegions")) {
        auto it = std::find(regionNames.begin(), regionNames.end(), region);
        if (it == regionNames.end()) {
            std::string valid;
            for (const auto& r : regionNames) valid += " " + r;
            throw dict.error("targetRegions", "no region '" + region + "'; regions:" + valid);
        }
        targetRegions_.push_back(it - regionNames.begin());
    }
    csv_ = std::make_unique<CsvFile>(outputFile("debrisCloud.csv"),
                                     std::vector<std::string>{"time", "length", "width", "lengthOverWidth",
                                                              "holeDiameter", "debrisParticles"},
                                     startTime());
}

void DebrisCloud::write() {
    const FieldStore& fields = context().fields();
    const int dim = fields.dimension();
    const FieldBase& x = fields.field("position");
    const FieldBase& region = fields.field("region");
    // A lateral axis in 2D: d rotated by 90 degrees.
    const double lateral2D[2] = {-direction_[1], direction_[0]};

    std::vector<double> s, lateral, holeLeft, holeRight;
    for (std::size_t i = 0; i < fields.size(); ++i) {
        double along = 0, across2D = 0, r2 = 0;
        for (int d = 0; d < dim; ++d) along += x.component(i, d) * direction_[d];
        for (int d = 0; d < dim; ++d) {
            const double perpendicular = x.component(i, d) - along * direction_[d];
            r2 += perpendicular * perpendicular;
            if (dim == 2) across2D += x.component(i, d) * lateral2D[d];
        }
        const double across = dim == 2 ? across2D : std::sqrt(r2);
        const bool target = std::find(targetRegions_.begin(), targetRegions_.end(),
                                      std::int64_t(region.component(i, 0))) != targetRegions_.end();
        if (target && along >= front_ && along <= rear_)
            (across >= 0 ? holeRight : holeLeft).push_back(std::abs(across));
        s.push_back(along), lateral.push_back(across);
    }
    std::vector<double> debrisS, debrisLateral;
    for (std::size_t k = 0; k < s.size(); ++k)
        if (s[k] > rear_) debrisS.push_back(s[k]), debrisLateral.push_back(lateral[k]);

    const double length = debrisS.empty() ? 0.0 : quantile(debrisS, 1 - trim_) - rear_;
    double width = 0;
    if (!debrisS.empty()) {
        if (dim == 2) {
            width = quantile(debrisLateral, 1 - trim_) - quantile(debrisLateral, trim_);
        } else {
            for (double& l : debrisLateral) l = std::abs(l);
            width = 2 * quantile(debrisLateral, 1 - trim_);
        }
    }
    double hole;
    if (dim == 2) {
        hole = (holeRight.empty() || holeLeft.empty())
                   ? NAN
                   : quantile(holeRight, trim_) + quantile(holeLeft, trim_);
    } else {
        std::vector<double> all(holeLeft);
        all.insert(all.end(), holeRight.begin(), holeRight.end());
        hole = all.empty() ? NAN : 2 * quantile(all, trim_);
    }
    const double ratio = width > 0 ? length / width : NAN;

    // The cloud itself, for a picture of its shape: cloud_<time>.csv with position and region.
    std::vector<std::string> columns{"x", "y"};
    if (dim == 3) columns.push_back("z");
    columns.push_back("region");
    CsvFile cloud(outputFile("cloud_" + context().time().timeName() + ".csv"), columns);
    std::vector<double> row(dim + 1);
    for (std::size_t i = 0; i < fields.size(); ++i) {
        for (int d = 0; d < dim; ++d) row[d] = x.component(i, d);
        row[dim] = region.component(i, 0);
        cloud.row(row);
    }
    csv_->row({context().time().value(), length, width, ratio, hole, double(debrisS.size())});
    // What could not be measured is said so rather than printed as nan.
    char ratioText[48], holeText[80], line[300];
    if (std::isnan(ratio))
        std::snprintf(ratioText, sizeof ratioText, "n/a (no width)");
    else
        std::snprintf(ratioText, sizeof ratioText, "%.3f", ratio);
    if (std::isnan(hole))
        std::snprintf(holeText, sizeof holeText, "n/a (no target particles %s in the plate)",
                      dim == 2 ? "on one side of the axis" : "around the axis");
    else
        std::snprintf(holeText, sizeof holeText, "%.4g m", hole);
    std::snprintf(line, sizeof line,
                  "debris length %.4g m, width %.4g m, L/W %s, hole diameter %s (%zu particles)", length,
                  width, ratioText, holeText, debrisS.size());
    summary_ = {line};
}

MFDYN_REGISTER(FunctionObject, DebrisCloud, "debrisCloud",
               "debris-cloud length, width, L/W and target hole diameter behind an impacted plate");

}  // namespace mfdyn
