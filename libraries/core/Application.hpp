#pragma once
// The top of every application: argument parsing, -help, -listModels, -case, -version, and the
// one place where errors become a message and exit status 1.
//
//     int main(int argc, char** argv) {
//         mfdyn::ApplicationInfo info{"mfDictionary", "Print, query and edit a dictionary.",
//                                     {{"entry", "key", "the scoped entry to print or set"}}, {"file"}};
//         return mfdyn::runApplication(argc, argv, info, [](const mfdyn::Arguments& args) { ...; return 0;
//         });
//     }
#include <filesystem>
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace mfdyn {

struct ApplicationOption {
    std::string name;      // without the leading '-'
    std::string argument;  // empty for a flag
    std::string help;
};

struct ApplicationInfo {
    std::string name;
    std::string synopsis;
    std::vector<ApplicationOption> options;  // beyond the common ones
    std::vector<std::string> positional;     // names of required positional arguments
    bool usesCase = true;                    // accepts -case and loads its controlDict libs for -listModels
    // A solver application's solver (its name in the registry family "solver"): -listModels
    // lists its keywords first.
    std::string solver = {};
};

class Arguments {
public:
    bool has(const std::string& option) const { return options_.count(option) != 0; }
    // The option's argument; throws InputError when absent.
    const std::string& value(const std::string& option) const;
    std::optional<std::string> find(const std::string& option) const;
    const std::vector<std::string>& positional() const { return positional_; }
    const std::filesystem::path& caseDir() const { return caseDir_; }
    const std::string& commandLine() const { return commandLine_; }

    static Arguments parse(int argc, char** argv, const ApplicationInfo& info);

private:
    std::map<std::string, std::string> options_;
    std::vector<std::string> positional_;
    std::filesystem::path caseDir_ = ".";
    std::string commandLine_;
};

std::string usage(const ApplicationInfo& info);

// dlopen every toolkit library (libmfdyn_*.so) beside libmfdyn_core, so that every family's
// registrations are made (-listModels, -describe, mfDoc).
void loadToolkitLibraries();

// OpenMP's wait policy, chosen before the runtime starts. libgomp reads OMP_WAIT_POLICY and
// GOMP_SPINCOUNT once, in a constructor that runs before main (measured with Debian 12's libgomp
// 12.2: a setenv of OMP_WAIT_POLICY=ACTIVE in main is not honoured), and by default a waiting
// thread spins before it sleeps. Beside another busy process on as many cores as threads, the
// spinning thread takes the core that the thread it waits for needs: a run was 100-200 times
// slower. So when neither variable is set, this sets OMP_WAIT_POLICY=PASSIVE (and the marker
// MFDYN_WAIT_POLICY_SET=1) and replaces the process once with itself (execv of /proc/self/exe,
// the same argv); the new image's runtime starts passive. A variable set by the user is kept.
// Called first by runApplication; returns only when no exec was needed (or exec failed).
void preferPassiveWaitPolicy(char** argv);

// Parses arguments, answers -help/-listModels/-version itself, otherwise runs `body`, whose
// return value is the exit status: 0 for a finished run, 128 + the signal number when a solver
// was stopped by SIGINT (130) or SIGTERM (143) after writing its state (SolverRun::run).
// Any mfdyn::Error (or other exception) is printed as "Error: ..." on stderr and gives status 1.
int runApplication(int argc, char** argv, const ApplicationInfo& info,
                   const std::function<int(const Arguments&)>& body);

}  // namespace mfdyn
