#pragma once
// Run-time post-processing, selected in controlDict's `functions { name { type ...; } }`. Each
// function object has its own writeControl:
//
//     writeControl  timeStep;   // timeStep (every writeInterval steps, default 1) | runTime |
//                               // adjustableRunTime (each writeInterval of time) |
//                               // writeTime (with the solver's writes)
//     writeInterval 10;
//
// and writes CSV under postProcessing/<name>/<startTime>/. Those that compare with a reference
// write errorNorms.csv (time,field,L1,L2,Linf) and report their latest norms for the run summary,
// with the same norms of the exact field where they know them (the relative error), and the
// single values they compare with an exact one (referenceValues: a star pressure, a peak). The
// summary prints both in one fixed format, with the step, time and process CPU time of the write
// that measured them (SolverRun: "error <name>  <value> (exact <x>, relative <r>) at CPU ..."),
// which mfStudy reads.
//
// On several ranks (MPI) each rank holds only its own particles. An object says in its base
// constructor which particles its context shows it (ParticleScope): by default `all`, every
// rank's owned particles gathered in global-id order on every rank, so an object written for one
// process needs no MPI code and gives the serial answer; `owned`, this rank's own, for an object
// that makes every figure a global reduction (GlobalReduce, globalMax...) and so sees each
// particle once over the ranks. FunctionObjectList gathers the copy (GatheredParticles.hpp) at
// the calls where an object of scope `all` writes; on one process there is no copy and both
// scopes show the run's own particles.
#include "core/Registry.hpp"
#include "functionObjects/CsvFile.hpp"
#include "functionObjects/RunContext.hpp"

#include <cstdint>
#include <filesystem>
#include <functional>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace mfdyn {

class FunctionObjectContext;
class GatheredParticles;

// writeControl and writeInterval, appended to every function object's schema.
KeywordSchema functionObjectKeywords();

// For summaries: "+1.23%", the relative error of `value` against `exact`; against an exact zero a
// relative error means nothing (it printed +inf% or nan%): "n/a (exact value 0; off by 1.2e-05)".
std::string relativeErrorText(double value, double exact);

struct ErrorNorm {
    std::string source;  // function object name
    std::string field;
    double time, L1, L2, Linf;
    // The same norms of the exact field, NaN where the object does not give them: L1/exactL1 is
    // the relative error that mfStudy's targets (10%, 1%, 0.1%) are set on, whatever the units.
    double exactL1 = std::numeric_limits<double>::quiet_NaN();
    double exactL2 = std::numeric_limits<double>::quiet_NaN();
    double exactLinf = std::numeric_limits<double>::quiet_NaN();
};

// One value a function object compares with its exact one, as of its latest write. `name` is
// one word (no spaces: the summary's error lines are split on white space).
struct ReferenceValue {
    std::string name;
    double value, exact;
};

// User + system CPU time of this process so far, all threads (getrusage).
double processCpuSeconds();

// Which particles a function object's context shows on several ranks (above).
enum class ParticleScope {
    all,   // every rank's owned particles, the same copy on every rank
    owned  // this rank's owned particles: every figure is a global reduction
};

class FunctionObject {
public:
    static constexpr const char* familyName = "functionObject";
    using Selector = Registry<FunctionObject, const Dictionary&, const std::string&, const RunContext&>;
    static std::unique_ptr<FunctionObject> New(const Dictionary& dict, const std::string& name,
                                               const RunContext& context) {
        return Selector::New(dict, name, context);
    }

    // From the values of the type's schema, which appends functionObjectKeywords(). `scope` is
    // stated here, in the base constructor, because the derived constructor already reads the
    // particles (selections, a tip chosen by position) through the context it was handed: the
    // list's per-object context takes the scope before that (FunctionObjectContext).
    FunctionObject(const KeywordValues& values, const std::string& name, const RunContext& context,
                   ParticleScope scope = ParticleScope::all);
    // For a type without a schema of its own (a user's library): reads functionObjectKeywords().
    FunctionObject(const Dictionary& dict, const std::string& name, const RunContext& context,
                   ParticleScope scope = ParticleScope::all);
    virtual ~FunctionObject();

    const std::string& name() const { return name_; }
    // Whether this object reads every rank's particles (scope all): the list gathers them before
    // the calls at which it writes.
    bool readsAllParticles() const { return scope_ == ParticleScope::all; }
    // The particle fields an object of scope all reads, asked once after construction: only these
    // (and globalId, region) are gathered at its writes. nullopt: every field of the run.
    virtual std::optional<std::vector<std::string>> fieldsRead() const { return std::nullopt; }
    // Whether this step is one of this object's write times (`solverWrites`: the solver writes now).
    bool due(bool solverWrites);
    virtual void write() = 0;
    // Called after every step before due(): a check that must not wait for a write (health).
    virtual void check() {}
    // Called with the solver's stable-time-step vote before each step takes it: a check of the
    // vote itself (health: a collapsed step stops the run before the integrator uses it).
    virtual void checkVote(const TimeStepVote& /*vote*/) {}
    // check(), due(), then write() and the stamp of that write (step, time, process CPU time).
    // (FunctionObjectList runs the same steps for all its objects, gathering in between.)
    void execute(bool solverWrites);
    virtual std::vector<ErrorNorm> errorNorms() const { return {}; }
    // Values compared with an exact one, as of the latest write (empty: none).
    virtual std::vector<ReferenceValue> referenceValues() const { return {}; }
    // When the latest write through execute() happened: what the summary's error lines were
    // measured at (step -1: never written).
    struct WriteStamp {
        std::int64_t step = -1;
        double time = std::numeric_limits<double>::quiet_NaN();
        double cpuSeconds = std::numeric_limits<double>::quiet_NaN();
    };
    const WriteStamp& lastWrite() const { return lastWrite_; }
    // Lines for the end-of-run summary (conservation drift, ...).
    virtual std::vector<std::string> summary() const { return {}; }
    // Whether the run should end cleanly after this step (planeCrossing's stopAtCrossing): SolverRun
    // asks after the function objects ran, writes the state and exits with status 0, logging
    // stopReason().
    virtual bool stopRequested() const { return false; }
    virtual std::string stopReason() const { return {}; }

protected:
    const RunContext& context() const { return context_; }
    std::filesystem::path outputFile(const std::string& fileName) const;
    // The time the run started from: a CsvFile series keeps an earlier run's rows before it.
    double startTime() const { return startTime_; }
    // The run's field `name`, or an InputError at `key` listing the fields there are.
    const FieldBase& requireField(const Dictionary& dict, const std::string& key,
                                  const std::string& name) const;

private:
    friend class FunctionObjectList;
    // write() and its stamp.
    void writeStamped();

    std::string name_;
    const RunContext& context_;
    ParticleScope scope_;
    double startTime_;
    enum class Control { timeStep, runTime, writeTime } control_;
    double interval_;
    std::int64_t lastIndex_ = -1;
    WriteStamp lastWrite_;
};

// Writes errorNorms.csv and keeps the latest norms per field for the summary.
class ErrorNormWriter {
public:
    ErrorNormWriter(const std::filesystem::path& file, std::string source,
                    double startTime = std::numeric_limits<double>::quiet_NaN());
    void add(double time, const std::string& field, double L1, double L2, double Linf);
    // With the norms of the exact field (for the relative error; not written to the CSV).
    void add(double time, const std::string& field, double L1, double L2, double Linf, double exactL1,
             double exactL2, double exactLinf);
    const std::vector<ErrorNorm>& latest() const { return latest_; }

private:
    CsvFile csv_;
    std::string source_;
    std::vector<ErrorNorm> latest_;
};

class FunctionObjectList {
public:
    // Reads controlDict's `functions` (absent: none), and puts the health check first (Health.cpp):
    // controlDict's `health { ... }` gives its settings, `health off;` leaves it out, and a
    // `functions` entry of type health replaces it.
    FunctionObjectList(const Dictionary& controlDict, const RunContext& context);
    ~FunctionObjectList();
    // Called after every step (and once at the start).
    void execute(bool solverWrites);
    // Called with each step's vote before the step (FunctionObject::checkVote).
    void checkVote(const TimeStepVote& vote);
    std::vector<ErrorNorm> errorNorms() const;
    std::vector<std::string> summary() const;
    std::size_t size() const { return objects_.size(); }
    // "<name>: <reason>" of the first object that asks the run to stop; empty when none does.
    std::string stopRequest() const;
    // Every error against a reference, as the summary prints them (SolverRun::run).
    struct ErrorRecord {
        std::string name;  // <object>/<field>/<L1|L2|Linf> or <object>/<quantity>
        double value, exact, relative;
        bool norm;  // value is a norm of the error and exact the norm of the exact field
        FunctionObject::WriteStamp measured;
    };
    std::vector<ErrorRecord> errorRecords() const;
    // Several ranks: the particles gathered for the objects of scope all (null on one process);
    // for tests.
    const GatheredParticles* gathered() const { return gathered_.get(); }

private:
    // controlDict's objects in order, each constructed with contextFor().
    void constructObjects(const Dictionary& controlDict,
                          const std::function<const RunContext&()>& contextFor);

    // Several ranks only. Declared before the objects, which refer to them: destroyed after.
    std::unique_ptr<GatheredParticles> gathered_;
    std::vector<std::unique_ptr<FunctionObjectContext>> contexts_;  // one per object
    std::vector<std::unique_ptr<FunctionObject>> objects_;
};

}  // namespace mfdyn
