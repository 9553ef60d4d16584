#include "functionObjects/FunctionObject.hpp"

#include "core/Communicator.hpp"
#include "functionObjects/GatheredParticles.hpp"
#include "functionObjects/Health.hpp"

#include <cmath>
#include <cstdio>
#include <optional>
#include <set>
#include <tuple>

#include <sys/resource.h>

namespace mfdyn {

KeywordSchema functionObjectKeywords() {
    return KeywordSchema("functionObject", "common")
        .word("writeControl", {"timeStep", "runTime", "adjustableRunTime", "writeTime"},
              "when to write: every writeInterval steps, every writeInterval of time, or with the solver")
        .orDefault("timeStep")
        .scalar("writeInterval", "steps or s",
                "steps (timeStep: a whole number, default 1) or time (runTime, adjustableRunTime: required)")
        .greaterThan(0)
        .optional();
}

std::string relativeErrorText(double value, double exact) {
    char s[80];
    if (exact == 0)
        std::snprintf(s, sizeof s, "n/a (exact value 0; off by %.3g)", value);
    else
        std::snprintf(s, sizeof s, "%+.2f%%", 100 * (value - exact) / std::abs(exact));
    return s;
}

double processCpuSeconds() {
    struct rusage usage {};
    if (getrusage(RUSAGE_SELF, &usage) != 0) return std::numeric_limits<double>::quiet_NaN();
    return double(usage.ru_utime.tv_sec) + 1e-6 * double(usage.ru_utime.tv_usec) +
           double(usage.ru_stime.tv_sec) + 1e-6 * double(usage.ru_stime.tv_usec);
}

FunctionObject::FunctionObject(const Dictionary& dict, const std::string& name, const RunContext& context,
                               ParticleScope scope)
    : FunctionObject(functionObjectKeywords().read(dict), name, context, scope) {}

FunctionObject::FunctionObject(const KeywordValues& values, const std::string& name,
                               const RunContext& context, ParticleScope scope)
    : name_(name), context_(context), scope_(scope), startTime_(context.time().value()) {
    if (const auto* own = dynamic_cast<const FunctionObjectContext*>(&context)) own->show(scope);
    const std::string& control = values.word("writeControl");
    const std::optional<double> interval = values.optionalScalar("writeInterval");
    if (control == "timeStep") {
        control_ = Control::timeStep;
        interval_ = interval.value_or(1.0);
        if (interval_ < 1 || interval_ != std::floor(interval_))
            throw values.error("writeInterval",
                               "with writeControl timeStep, writeInterval is a whole number of steps >= 1");
    } else if (control == "writeTime") {
        control_ = Control::writeTime;
        interval_ = 1;
    } else {  // runTime, adjustableRunTime
        control_ = Control::runTime;
        if (!interval)
            throw InputError(values.dict().where(), values.dict().scope(),
                             "missing keyword 'writeInterval' (the time between writes, in s), required "
                             "with writeControl " +
                                 control);
        interval_ = *interval;
    }
    values.dict().findEntry("type");  // read by the selector
}

FunctionObject::~FunctionObject() = default;

bool FunctionObject::due(bool solverWrites) {
    const Time& time = context_.time();
    std::int64_t index = 0;
    switch (control_) {
        case Control::timeStep:
            index = time.timeIndex() / std::int64_t(interval_);
            break;
        case Control::runTime:
            index = std::int64_t(std::floor(time.value() / interval_ * (1 + 1e-9) + 1e-9));
            break;
        case Control::writeTime:
            if (!solverWrites && lastIndex_ >= 0) return false;
            index = time.timeIndex();
            break;
    }
    if (index == lastIndex_) return false;
    lastIndex_ = index;
    return true;
}

void FunctionObject::execute(bool solverWrites) {
    check();
    if (due(solverWrites)) writeStamped();
}

void FunctionObject::writeStamped() {
    write();
    // After the write: the CPU time the error it measured had cost, the write's own included.
    lastWrite_ = {context_.time().timeIndex(), context_.time().value(), processCpuSeconds()};
}

const FieldBase& FunctionObject::requireField(const Dictionary& dict, const std::string& key,
                                              const std::string& name) const {
    if (const FieldBase* f = context_.fields().findField(name)) return *f;
    const auto names = context_.fields().fieldNames();
    std::string message = "no field '" + name + "' in this run; fields:";
    for (const auto& n : names) message += " " + n;
    if (auto guess = closestMatch(name, names); !guess.empty()) message += " (did you mean '" + guess + "'?)";
    throw dict.error(key, message);
}

std::filesystem::path FunctionObject::outputFile(const std::string& fileName) const {
    return context_.runCase().postProcessing() / name_ / context_.startTimeName() / fileName;
}

ErrorNormWriter::ErrorNormWriter(const std::filesystem::path& file, std::string source, double startTime)
    : csv_(file, {"time", "field", "L1", "L2", "Linf"}, startTime), source_(std::move(source)) {}

void ErrorNormWriter::add(double time, const std::string& field, double L1, double L2, double Linf) {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    add(time, field, L1, L2, Linf, nan, nan, nan);
}

void ErrorNormWriter::add(double time, const std::string& field, double L1, double L2, double Linf,
                          double exactL1, double exactL2, double exactLinf) {
    csv_.row(time, field, {L1, L2, Linf});
    const ErrorNorm latest{source_, field, time, L1, L2, Linf, exactL1, exactL2, exactLinf};
    for (auto& norm : latest_) {
        if (norm.field == field) {
            norm = latest;
            return;
        }
    }
    latest_.push_back(latest);
}

FunctionObjectList::FunctionObjectList(const Dictionary& controlDict, const RunContext& context) {
    // Several ranks: each object gets a context of its own, which shows the particles of the
    // scope it states (FunctionObject.hpp); one process: the run's own, no copy.
    if (Communicator::distributed()) gathered_ = std::make_unique<GatheredParticles>(context);
    const auto contextFor = [&]() -> const RunContext& {
        if (!gathered_) return context;
        contexts_.push_back(std::make_unique<FunctionObjectContext>(context, *gathered_));
        return *contexts_.back();
    };
    constructObjects(controlDict, contextFor);
    if (!gathered_) return;
    // What the objects of scope all read, together: only that is gathered from now on.
    std::optional<std::set<std::string>> read = std::set<std::string>{};
    for (const auto& object : objects_) {
        if (!object->readsAllParticles()) continue;
        const auto fields = object->fieldsRead();
        if (!fields)
            read.reset();
        else if (read)
            read->insert(fields->begin(), fields->end());
    }
    gathered_->select(read);
}

FunctionObjectList::~FunctionObjectList() = default;

void FunctionObjectList::constructObjects(const Dictionary& controlDict,
                                          const std::function<const RunContext&()>& contextFor) {
    const Dictionary* functions = controlDict.findDict("functions");
    bool healthListed = false;
    if (functions)
        for (const auto& entry : functions->entries())
            if (entry->isDict())
                if (auto type = functions->subDict(entry->key).getOptional<std::string>("type"))
                    healthListed = healthListed || *type == "health";
    // First: a state it stops on is never seen (and written into a CSV) by the objects after it.
    if (controlDict.findDict("health")) {
        if (healthListed)
            throw controlDict.error("health",
                                    "the health check is set twice: here and as a function object "
                                    "of type health in `functions`; keep one");
        objects_.push_back(std::make_unique<Health>(controlDict.subDict("health"), "health", contextFor()));
    } else if (!healthListed && controlDict.getOrDefault<bool>("health", true)) {
        const Dictionary defaults;  // every keyword at its default (read in the constructor, not kept)
        objects_.push_back(std::make_unique<Health>(defaults, "health", contextFor()));
    }
    if (!functions) return;
    for (const auto& entry : functions->entries()) {
        if (!entry->isDict())
            throw functions->error(
                entry->key, "expected a dictionary { type ...; } for function object '" + entry->key + "'");
        objects_.push_back(FunctionObject::New(functions->subDict(entry->key), entry->key, contextFor()));
    }
}

void FunctionObjectList::execute(bool solverWrites) {
    // The copy is gathered once per call, before the first write of an object of scope all, and
    // not at all at a call without one. Collective: whether an object is due depends on the time
    // alone, and the checks that throw (health) throw on every rank together.
    bool gathered = false;
    for (auto& object : objects_) {
        object->check();
        if (!object->due(solverWrites)) continue;
        if (gathered_ && object->readsAllParticles() && !gathered) {
            gathered_->refresh();
            gathered = true;
        }
        object->writeStamped();
    }
}

void FunctionObjectList::checkVote(const TimeStepVote& vote) {
    for (auto& object : objects_) object->checkVote(vote);
}

std::string FunctionObjectList::stopRequest() const {
    for (const auto& object : objects_)
        if (object->stopRequested())
            return "function object '" + object->name() + "' (" + object->stopReason() + ")";
    return {};
}

std::vector<ErrorNorm> FunctionObjectList::errorNorms() const {
    std::vector<ErrorNorm> all;
    for (const auto& object : objects_)
        for (auto& norm : object->errorNorms()) all.push_back(norm);
    return all;
}

std::vector<FunctionObjectList::ErrorRecord> FunctionObjectList::errorRecords() const {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    std::vector<ErrorRecord> all;
    for (const auto& object : objects_) {
        const FunctionObject::WriteStamp& stamp = object->lastWrite();
        for (const auto& n : object->errorNorms()) {
            // The norm's own time; the stamp is of the same write unless the object kept an older norm.
            FunctionObject::WriteStamp at = stamp;
            if (!(n.time == stamp.time)) at = {-1, n.time, nan};
            const std::string base = n.source + "/" + n.field + "/";
            for (const auto& [norm, value, exact] :
                 {std::tuple{"L1", n.L1, n.exactL1}, {"L2", n.L2, n.exactL2}, {"Linf", n.Linf, n.exactLinf}})
                all.push_back({base + norm, value, exact, exact > 0 ? value / exact : nan, true, at});
        }
        for (const auto& r : object->referenceValues())
            all.push_back({object->name() + "/" + r.name, r.value, r.exact,
                           r.exact != 0 ? (r.value - r.exact) / std::abs(r.exact) : nan, false, stamp});
    }
    return all;
}

std::vector<std::string> FunctionObjectList::summary() const {
    std::vector<std::string> all;
    for (const auto& object : objects_)
        for (auto& line : object->summary()) all.push_back(object->name() + ": " + line);
    return all;
}

}  // namespace mfdyn
