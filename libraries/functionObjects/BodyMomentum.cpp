// bodyMomentum: mass, linear momentum and angular momentum of each body (particleGen region), the
// per-disk momenta of the material point method's two disks (doc/methods/mpm.md section 4.3: each
// disk's x and y momenta equal, falling to 0 at the largest strain energy and reversing):
//
//   M_b = sum_{a in b} m_a,   P_b = sum m_a v_a,   L_b = sum m_a (x_a - c) x v_a
//
// (L: z only in 2D, 3 components in 3D, none in 1D), about `centre` c (default the origin).
//
//     disks { type bodyMomentum; regions (lower upper); centre (0.5 0.5); }   // regions: default all
//
// bodyMomentum.csv: time, then per region <region>_mass, <region>_momentum_x ..., and
// <region>_angularMomentum_z (2D) or _x _y _z (3D). The summary gives each body's change of
// momentum over the run. Sums go through GlobalReduce::sum, one per region (fixed blocks: the
// figures do not depend on the thread count; an MPI build sums over every rank).
#include "functionObjects/BodyMomentum.hpp"

#include "core/Parallel.hpp"
#include "functionObjects/RegionLookup.hpp"
#include "particles/ParticleSetBase.hpp"

#include <algorithm>
#include <cstdio>

namespace mfdyn {

KeywordSchema BodyMomentum::keywords() {
    return KeywordSchema("functionObject", "bodyMomentum")
        .words("regions",
               "the bodies (particleGen regions) to measure, in this order (default: every region)")
        .optional()
        .vector("centre", "m", "the point the angular momentum is taken about")
        .orDefault(std::vector<double>{0, 0, 0})
        .append(functionObjectKeywords());
}

BodyMomentum::BodyMomentum(const Dictionary& dict, const std::string& name, const RunContext& context)
    : BodyMomentum(keywords().read(dict), name, context) {}

BodyMomentum::BodyMomentum(const KeywordValues& values, const std::string& name, const RunContext& context)
    : FunctionObject(values, name, context, ParticleScope::owned) {
    const Dictionary& dict = values.dict();
    const int dim = context.dimension();
    regionNames_ = runRegionNames(context);
    requireField(dict, "type", "region");
    if (values.given("regions")) {
        for (const auto& r : values.words("regions"))
            regions_.push_back(regionIndex(dict, "regions", r, context));
    } else {
        for (std::size_t r = 0; r < regionNames_.size(); ++r) regions_.push_back(std::int64_t(r));
        if (regions_.empty()) throw dict.error("type", "bodyMomentum: this run's particles name no region");
    }
    const auto& c = values.vector("centre");
    if (int(c.size()) < dim) throw dict.error("centre", "expected " + std::to_string(dim) + " components");
    for (int d = 0; d < dim; ++d) centre_[d] = c[d];

    const char* axes[] = {"x", "y", "z"};
    const int nL = dim == 2 ? 1 : dim == 3 ? 3 : 0;
    perRegion_ = 1 + dim + nL;
    columns_ = {"time"};
    for (std::int64_t r : regions_) {
        const std::string& n = regionNames_[std::size_t(r)];
        columns_.push_back(n + "_mass");
        for (int d = 0; d < dim; ++d) columns_.push_back(n + "_momentum_" + axes[d]);
        if (nL == 1) columns_.push_back(n + "_angularMomentum_z");
        if (nL == 3)
            for (int d = 0; d < 3; ++d) columns_.push_back(n + "_angularMomentum_" + axes[d]);
    }
    csv_ = std::make_unique<CsvFile>(outputFile("bodyMomentum.csv"), columns_, startTime());
}

std::vector<double> BodyMomentum::measure() const {
    const FieldStore& fields = context().fields();
    const int dim = fields.dimension();
    const std::size_t n = context().ownedParticles();
    const FieldBase* massField = fields.findField("mass");
    const FieldBase& position = fields.field("position");
    const FieldBase* velocity = fields.findField("velocity");
    const FieldBase& region = fields.field("region");
    const int nL = perRegion_ - 1 - dim;
    std::vector<double> row{context().time().value()};
    for (std::int64_t r : regions_) {
        // [M, P (dim), L (0|1|3)]: at most 7 sums.
        const SumArray<7> total = GlobalReduce::sum<SumArray<7>>(n, [&](std::size_t i) {
            SumArray<7> s;
            if (std::int64_t(region.component(i, 0)) != r) return s;
            const double m = massField ? massField->component(i, 0) : 1.0;
            double x[3] = {0, 0, 0}, v[3] = {0, 0, 0};
            for (int d = 0; d < dim; ++d) {
                x[d] = position.component(i, d) - centre_[d];
                v[d] = velocity ? velocity->component(i, d) : 0.0;
            }
            s.s[0] = m;
            for (int d = 0; d < dim; ++d) s.s[1 + d] = m * v[d];
            const double lx = x[1] * v[2] - x[2] * v[1], ly = x[2] * v[0] - x[0] * v[2],
                         lz = x[0] * v[1] - x[1] * v[0];
            if (nL == 1) s.s[1 + dim] = m * lz;
            if (nL == 3) s.s[1 + dim] = m * lx, s.s[2 + dim] = m * ly, s.s[3 + dim] = m * lz;
            return s;
        });
        for (int k = 0; k < perRegion_; ++k) row.push_back(total.s[k]);
    }
    return row;
}

void BodyMomentum::write() {
    last_ = measure();
    if (first_.empty()) first_ = last_;
    csv_->row(last_);
}

std::vector<std::string> BodyMomentum::summary() const {
    if (first_.empty()) return {};
    std::vector<std::string> lines;
    char s[200];
    for (std::size_t k = 1; k < columns_.size(); ++k) {
        if (columns_[k].find("omentum_") == std::string::npos) continue;
        std::snprintf(s, sizeof s, "%s change %.3e (%.10g -> %.10g)", columns_[k].c_str(),
                      last_[k] - first_[k], first_[k], last_[k]);
        lines.push_back(s);
    }
    return lines;
}

MFDYN_REGISTER(FunctionObject, BodyMomentum, "bodyMomentum",
               "mass, linear and angular momentum of each body (particleGen region)");

}  // namespace mfdyn
