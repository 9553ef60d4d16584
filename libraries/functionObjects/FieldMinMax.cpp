// fieldMinMax: the smallest and largest value of chosen fields each write, with the global id of
// the particle where each occurs.
//
//     minMax { type fieldMinMax; fields (velocity density); mode magnitude; }  // magnitude | component
//
// In `magnitude` mode a vector or tensor is reduced to its Euclidean (Frobenius) norm; in
// `component` mode each stored component gets its own columns (name_x_min, ...).
//
// Derived field: `vonMisesStress`, when the run has no field of that name, is the standard von
// Mises stress sqrt(3/2 s:s) of `cauchyStress` with its out-of-plane `cauchyStressZZ` below 3D
// (the material point method's fields; VonMisesStress.hpp), computed at each write:
//     vonMises { type fieldMinMax; fields (vonMisesStress); }
//
// Derived fields: `maxPrincipalStress` and `minPrincipalStress`, when the run has no field of that
// name, are the largest and smallest eigenvalue of the Cauchy stress sigma = S - p I of
// `deviatoricStress` and `pressure` (the finite pointset method's fields; below 3D the deviator is
// in-plane and sigma_zz = -p: PrincipalStress.hpp), computed at each write:
//     principal { type fieldMinMax; fields (maxPrincipalStress minPrincipalStress); }
#include "functionObjects/FieldMinMax.hpp"

#include "functionObjects/PrincipalStress.hpp"
#include "functionObjects/VonMisesStress.hpp"

#include "core/Parallel.hpp"

#include <cmath>
#include <limits>
#include <optional>

namespace mfdyn {

KeywordSchema FieldMinMax::keywords() {
    return KeywordSchema("functionObject", "fieldMinMax")
        .words("fields",
               "the fields to watch (vonMisesStress: derived from cauchyStress; maxPrincipalStress, "
               "minPrincipalStress: from deviatoricStress and pressure; see the source)")
        .word("mode", {"magnitude", "component"}, "min and max of the magnitude, or of each component")
        .orDefault("magnitude")
        .append(functionObjectKeywords());
}

FieldMinMax::FieldMinMax(const Dictionary& dict, const std::string& name, const RunContext& context)
    : FieldMinMax(keywords().read(dict), name, context) {}

FieldMinMax::FieldMinMax(const KeywordValues& values, const std::string& name, const RunContext& context)
    : FunctionObject(values, name, context, ParticleScope::owned) {
    const Dictionary& dict = values.dict();
    fields_ = values.words("fields");
    components_ = values.word("mode") == "component";
    std::vector<std::string> columns{"time"};
    for (const auto& field : fields_) {
        if (derived(field)) {
            try {
                if (PrincipalStressField::isName(field))
                    PrincipalStressField check(context.fields(), "", field);
                else
                    VonMisesField check(context.fields(), "");
            } catch (const InputError& e) {
                throw dict.error("fields", e.what());
            }
            for (const char* what : {"_min", "_minId", "_max", "_maxId"}) columns.push_back(field + what);
            continue;
        }
        const FieldBase* f = &requireField(dict, "fields", field);
        std::vector<std::string> parts{field};
        if (components_ && f->components() > 1) {
            parts.clear();
            for (const auto& c : componentNames(f->kind(), f->dimension())) parts.push_back(field + "_" + c);
        }
        for (const auto& p : parts)
            for (const char* what : {"_min", "_minId", "_max", "_maxId"}) columns.push_back(p + what);
    }
    csv_ = std::make_unique<CsvFile>(outputFile("fieldMinMax.csv"), columns, startTime());
}

bool FieldMinMax::derived(const std::string& field) const {
    return (field == VonMisesField::name || PrincipalStressField::isName(field)) &&
           !context().fields().findField(field);
}

void FieldMinMax::write() {
    const FieldStore& store = context().fields();
    const FieldBase& ids = store.field("globalId");
    const std::size_t n = context().ownedParticles();
    const bool any = globalSum(double(n)) > 0;
    std::vector<double> row{context().time().value()};
    for (const auto& name : fields_) {
        const bool isDerived = derived(name);
        std::optional<VonMisesField> vonMises;
        std::optional<PrincipalStressField> principal;
        const bool largest = name == PrincipalStressField::maxName;
        const FieldBase* f = nullptr;
        if (!isDerived)
            f = &store.field(name);
        else if (PrincipalStressField::isName(name))
            principal.emplace(store, "fieldMinMax '" + this->name() + "'", name);
        else
            vonMises.emplace(store, "fieldMinMax '" + this->name() + "'");
        const int nc = isDerived ? 1 : f->components();
        const int parts = components_ ? nc : 1;
        for (int p = 0; p < parts; ++p) {
            auto value = [&](std::size_t i) {
                if (vonMises) return (*vonMises)(i);
                if (principal) {
                    const PrincipalStresses s = (*principal)(i);
                    return largest ? s.max : s.min;
                }
                if (components_ || nc == 1) return f->component(i, components_ ? p : 0);
                double s = 0;
                for (int c = 0; c < nc; ++c) s += f->component(i, c) * f->component(i, c);
                return std::sqrt(s);
            };
            // Over every rank: the extreme, then the lowest global id that holds it (the serial
            // run's first index with it when its particles are in id order, as particleGen writes
            // them), so any number of ranks and threads gives the same row. NaN values are passed
            // over (the min and max reductions ignore them).
            std::vector<double> values(n);
            for (std::size_t i = 0; i < n; ++i) values[i] = value(i);
            const double lo = GlobalReduce::min(n, [&](std::size_t i) { return values[i]; });
            const double hi = GlobalReduce::max(n, [&](std::size_t i) { return values[i]; });
            const auto lowestIdAt = [&](double extreme) {
                const double id = GlobalReduce::min(n, [&](std::size_t i) {
                    return values[i] == extreme ? ids.component(i, 0)
                                                : std::numeric_limits<double>::infinity();
                });
                return std::isfinite(id) ? id : -1.0;
            };
            const double idLo = lowestIdAt(lo), idHi = lowestIdAt(hi);
            row.insert(row.end(), {any ? lo : NAN, any ? idLo : -1, any ? hi : NAN, any ? idHi : -1});
        }
    }
    csv_->row(row);
}

MFDYN_REGISTER(FunctionObject, FieldMinMax, "fieldMinMax",
               "minimum and maximum of fields (magnitude or per component)");

}  // namespace mfdyn
