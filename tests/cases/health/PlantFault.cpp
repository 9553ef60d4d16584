// plantFault: a test-only function object (libplantFault.so, loaded with libs) that plants one
// fault into a running solver's state, so that the health check can be shown to fire on every
// solver from a case directory (tests/cases/health):
//
//     functions {
//         plant  { type plantFault; time 0.01; particle 3; field velocity; component 0; value nan; }
//         health { type health; }   // after it: the check sees the fault in the same step
//     }
//
// At the first step whose time reaches `time`, component `component` of field `field` of the
// particle with global id `particle` becomes `value` (a number, nan or inf): a NaN, a speed that
// collapses the time step, a position outside the domain. It writes through the run context's
// read-only view, which only a test may do.
#include "core/Error.hpp"
#include "core/Log.hpp"
#include "functionObjects/FunctionObject.hpp"

#include <cmath>
#include <limits>

namespace mfdyn {

class PlantFault final : public FunctionObject {
public:
    static KeywordSchema keywords() {
        return KeywordSchema("functionObject", "plantFault")
            .scalar("time", "s", "when to plant the fault")
            .integer("particle", "-", "the global id of the particle to change")
            .atLeast(0)
            .identifier("field", "the field to change")
            .integer("component", "-", "its component")
            .orDefault(0)
            .atLeast(0)
            .identifier("value", "the value: a number, nan or inf")
            .append(functionObjectKeywords());
    }
    PlantFault(const Dictionary& dict, const std::string& name, const RunContext& context)
        : PlantFault(keywords().read(dict), name, context) {}

    void check() override {
        if (planted_ || context().time().value() < time_) return;
        planted_ = true;
        const FieldStore& fields = context().fields();
        FieldBase* field = fields.findField(field_);
        if (!field) throw RunError("plantFault: no field " + field_);
        const FieldBase& ids = fields.field("globalId");
        for (std::size_t i = 0; i < fields.size(); ++i)
            if (std::int64_t(ids.component(i, 0)) == particle_) {
                static_cast<double*>(
                    field->data())[i * std::size_t(field->components()) + std::size_t(component_)] = value_;
                Log::info("plantFault: " + field_ + " component " + std::to_string(component_) +
                          " of particle " + std::to_string(particle_) + " set to " + valueText_ +
                          " at t = " + context().time().timeName());
            }
    }
    void write() override {}

private:
    PlantFault(const KeywordValues& v, const std::string& name, const RunContext& context)
        : FunctionObject(v, name, context, ParticleScope::owned),
          time_(v.scalar("time")),
          particle_(v.integer("particle")),
          field_(v.word("field")),
          component_(int(v.integer("component"))),
          valueText_(v.word("value")) {
        if (valueText_ == "nan")
            value_ = std::numeric_limits<double>::quiet_NaN();
        else if (valueText_ == "inf")
            value_ = std::numeric_limits<double>::infinity();
        else
            value_ = std::stod(valueText_);
    }
    double time_;
    std::int64_t particle_;
    std::string field_;
    int component_;
    std::string valueText_;
    double value_ = 0;
    bool planted_ = false;
};

MFDYN_REGISTER(FunctionObject, PlantFault, "plantFault", "test only: plants a fault into the state");

}  // namespace mfdyn
