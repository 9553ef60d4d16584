// probes: particle fields interpolated to fixed points, one row per write.
//
//     probes
//     {
//         type          probes;
//         fields        (velocity density);
//         points        ((0.1 0 0) (0.5 0.2 0));
//         interpolation shepard;              // shepard | mls (Interpolation.hpp)
//         kernel        { type wendlandC2; }  // default wendlandC2
//         h             0.02;                 // else the particles' smoothingLength field
//     }
//
// writes postProcessing/<name>/<startTime>/probes.csv with columns time, then for probe k and
// each field component p<k>_<field>[_<component>] (p0_velocity_x, p0_velocity_y, p0_density,
// p1_velocity_x, ...). The interpolation is the one of the sample utility (equations in
// Interpolation.cpp), re-binned at each write because the particles move. A probe with no
// particle within reach reads NaN, with one warning.
#include "functionObjects/Probes.hpp"

#include "core/Log.hpp"
#include "functionObjects/SamplingSet.hpp"

namespace mfdyn {

KeywordSchema Probes::keywords() {
    return KeywordSchema("functionObject", "probes")
        .words("fields", "the fields to interpolate")
        .table("points", "m", "the probe locations, ((x y z) ...)")
        .example("((0 0 0) (0.1 0 0))")
        .append(Interpolation::keywords())
        .append(functionObjectKeywords());
}

Probes::Probes(const Dictionary& dict, const std::string& name, const RunContext& context)
    : Probes(keywords().read(dict), name, context) {}

Probes::Probes(const KeywordValues& values, const std::string& name, const RunContext& context)
    : FunctionObject(values, name, context),
      fields_(values.words("fields")),
      points_(SamplingSet::readPoints(values.dict(), "points")),
      interpolation_(values, context.fields()) {
    const Dictionary& dict = values.dict();
    std::vector<std::string> columns{"time"};
    std::vector<std::string> parts;
    for (const auto& field : fields_) {
        const FieldBase* f = &requireField(dict, "fields", field);
        for (const auto& c : componentNames(f->kind(), f->dimension()))
            parts.push_back(c.empty() || f->components() == 1 ? field : field + "_" + c);
    }
    for (std::size_t k = 0; k < points_.size(); ++k)
        for (const auto& p : parts) columns.push_back("p" + std::to_string(k) + "_" + p);
    csv_ = std::make_unique<CsvFile>(outputFile("probes.csv"), columns, startTime());
}

std::optional<std::vector<std::string>> Probes::fieldsRead() const {
    std::vector<std::string> read = interpolation_.fieldsRead();
    read.insert(read.end(), fields_.begin(), fields_.end());
    return read;
}

void Probes::write() {
    interpolation_.update();
    const auto stencils = interpolation_.stencils(points_);
    std::vector<std::vector<std::vector<double>>> values;
    for (const auto& field : fields_)
        values.push_back(Interpolation::apply(stencils, context().fields().field(field)));
    std::vector<double> row{context().time().value()};
    for (std::size_t k = 0; k < points_.size(); ++k) {
        if (stencils[k].status == Interpolation::Status::noNeighbours && !warned_) {
            Log::warning("probes '" + name() + "': probe " + std::to_string(k) +
                         " has no particle within reach; it reads NaN");
            warned_ = true;
        }
        for (const auto& v : values) row.insert(row.end(), v[k].begin(), v[k].end());
    }
    csv_->row(row);
}

MFDYN_REGISTER(FunctionObject, Probes, "probes",
               "particle fields interpolated (shepard or mls) to fixed points");

}  // namespace mfdyn
