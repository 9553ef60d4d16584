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
// write errorNorms.csv (time,field,L1,L2,Linf) and report their latest norms for the run summary.
#include "core/Registry.hpp"
#include "functionObjects/CsvFile.hpp"
#include "functionObjects/RunContext.hpp"

#include <filesystem>
#include <limits>
#include <memory>
#include <string>
#include <vector>

namespace mfdyn {

// writeControl and writeInterval, appended to every function object's schema.
KeywordSchema functionObjectKeywords();

// For summaries: "+1.23%", the relative error of `value` against `exact`; against an exact zero a
// relative error means nothing (it printed +inf% or nan%): "n/a (exact value 0; off by 1.2e-05)".
std::string relativeErrorText(double value, double exact);

struct ErrorNorm {
    std::string source;  // function object name
    std::string field;
    double time, L1, L2, Linf;
};

class FunctionObject {
public:
    static constexpr const char* familyName = "functionObject";
    using Selector = Registry<FunctionObject, const Dictionary&, const std::string&, const RunContext&>;
    static std::unique_ptr<FunctionObject> New(const Dictionary& dict, const std::string& name,
                                               const RunContext& context) {
        return Selector::New(dict, name, context);
    }

    // From the values of the type's schema, which appends functionObjectKeywords().
    FunctionObject(const KeywordValues& values, const std::string& name, const RunContext& context);
    // For a type without a schema of its own (a user's library): reads functionObjectKeywords().
    FunctionObject(const Dictionary& dict, const std::string& name, const RunContext& context);
    virtual ~FunctionObject();

    const std::string& name() const { return name_; }
    // Whether this step is one of this object's write times (`solverWrites`: the solver writes now).
    bool due(bool solverWrites);
    virtual void write() = 0;
    virtual std::vector<ErrorNorm> errorNorms() const { return {}; }
    // Lines for the end-of-run summary (conservation drift, ...).
    virtual std::vector<std::string> summary() const { return {}; }

protected:
    const RunContext& context() const { return context_; }
    std::filesystem::path outputFile(const std::string& fileName) const;
    // The time the run started from: a CsvFile series keeps an earlier run's rows before it.
    double startTime() const { return startTime_; }
    // The run's field `name`, or an InputError at `key` listing the fields there are.
    const FieldBase& requireField(const Dictionary& dict, const std::string& key,
                                  const std::string& name) const;

private:
    std::string name_;
    const RunContext& context_;
    double startTime_;
    enum class Control { timeStep, runTime, writeTime } control_;
    double interval_;
    std::int64_t lastIndex_ = -1;
};

// Writes errorNorms.csv and keeps the latest norms per field for the summary.
class ErrorNormWriter {
public:
    ErrorNormWriter(const std::filesystem::path& file, std::string source,
                    double startTime = std::numeric_limits<double>::quiet_NaN());
    void add(double time, const std::string& field, double L1, double L2, double Linf);
    const std::vector<ErrorNorm>& latest() const { return latest_; }

private:
    CsvFile csv_;
    std::string source_;
    std::vector<ErrorNorm> latest_;
};

class FunctionObjectList {
public:
    // Reads controlDict's `functions` (absent: none).
    FunctionObjectList(const Dictionary& controlDict, const RunContext& context);
    // Called after every step (and once at the start).
    void execute(bool solverWrites);
    std::vector<ErrorNorm> errorNorms() const;
    std::vector<std::string> summary() const;
    std::size_t size() const { return objects_.size(); }

private:
    std::vector<std::unique_ptr<FunctionObject>> objects_;
};

}  // namespace mfdyn
