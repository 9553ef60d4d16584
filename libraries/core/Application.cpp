#include "core/Application.hpp"

#include "core/Communicator.hpp"

#include "core/Dictionary.hpp"
#include "core/Error.hpp"
#include "core/LibraryLoader.hpp"
#include "core/Registry.hpp"

#include <dlfcn.h>
#include <unistd.h>

#include <cctype>
#include <cstdlib>
#include <iostream>
#include <sstream>
#include <streambuf>

namespace mfdyn {

namespace {

const std::vector<ApplicationOption>& commonOptions() {
    static const std::vector<ApplicationOption> options{
        {"case", "dir", "the case directory (default: the current directory)"},
        {"listModels", "", "list every model family, its types and their keywords, then exit"},
        {"describe", "family|type",
         "describe a model family, or one type with its keywords and their meaning (type or family/type), "
         "then exit"},
        {"help", "", "print this usage and exit"},
        {"version", "", "print the version and exit"},
    };
    return options;
}

const ApplicationOption* findOption(const ApplicationInfo& info, const std::string& name) {
    for (const auto* list : {&info.options, &commonOptions()})
        for (const auto& option : *list)
            if (option.name == name) return &option;
    return nullptr;
}

std::vector<std::string> optionNames(const ApplicationInfo& info) {
    std::vector<std::string> names;
    for (const auto* list : {&info.options, &commonOptions()})
        for (const auto& option : *list) names.push_back(option.name);
    return names;
}

std::filesystem::path sharedObjectPath(const void* address) {
    Dl_info info{};
    if (dladdr(address, &info) && info.dli_fname) return info.dli_fname;
    return {};
}

}  // namespace

void preferPassiveWaitPolicy(char** argv) {
    // The user's (or a script's) choice stands; the marker stops a second exec should the variable
    // somehow not reach the new image.
    if (std::getenv("OMP_WAIT_POLICY") || std::getenv("GOMP_SPINCOUNT") ||
        std::getenv("MFDYN_WAIT_POLICY_SET"))
        return;
    if (::setenv("OMP_WAIT_POLICY", "PASSIVE", 1) != 0 || ::setenv("MFDYN_WAIT_POLICY_SET", "1", 1) != 0)
        return;
    std::cout.flush();
    ::execv("/proc/self/exe", argv);
    // No /proc (or exec refused): run on in this image, whose OpenMP runtime already chose the
    // default policy; only the speed beside other work suffers. What this process starts inherits
    // the passive policy all the same.
}

const std::string& Arguments::value(const std::string& option) const {
    auto it = options_.find(option);
    if (it == options_.end()) throw InputError("missing option -" + option);
    return it->second;
}

std::optional<std::string> Arguments::find(const std::string& option) const {
    auto it = options_.find(option);
    if (it == options_.end()) return std::nullopt;
    return it->second;
}

Arguments Arguments::parse(int argc, char** argv, const ApplicationInfo& info) {
    Arguments args;
    for (int i = 0; i < argc; ++i) args.commandLine_ += (i ? " " : "") + std::string(argv[i]);
    for (int i = 1; i < argc; ++i) {
        std::string word = argv[i];
        if (word.size() > 1 && word[0] == '-' && !(std::isdigit(word[1]) || word[1] == '.')) {
            std::string name = word.substr(word[1] == '-' ? 2 : 1);
            const ApplicationOption* option = findOption(info, name);
            if (!option) {
                std::string message = "unknown option '" + word + "'";
                if (auto guess = closestMatch(name, optionNames(info)); !guess.empty())
                    message += "; did you mean '-" + guess + "'?";
                throw InputError(message + "\n" + usage(info));
            }
            if (option->argument.empty()) {
                args.options_[name] = "";
            } else {
                if (i + 1 >= argc)
                    throw InputError("option '" + word + "' needs an argument <" + option->argument + ">");
                args.options_[name] = argv[++i];
            }
        } else {
            args.positional_.push_back(word);
        }
    }
    if (auto c = args.find("case")) args.caseDir_ = *c;
    return args;
}

std::string usage(const ApplicationInfo& info) {
    std::ostringstream s;
    s << "Usage: " << info.name << " [OPTIONS]";
    for (const auto& p : info.positional) s << " <" << p << ">";
    s << "\n\n" << info.synopsis << "\n\nOptions:\n";
    for (const auto* list : {&info.options, &commonOptions()}) {
        for (const auto& option : *list) {
            if (option.name == "case" && !info.usesCase) continue;
            std::string head =
                "  -" + option.name + (option.argument.empty() ? "" : " <" + option.argument + ">");
            s << head << std::string(head.size() < 24 ? 24 - head.size() : 1, ' ') << option.help << "\n";
        }
    }
    return s.str();
}

void loadToolkitLibraries() {
    const std::filesystem::path self = sharedObjectPath(reinterpret_cast<const void*>(&runApplication));
    std::error_code ec;
    for (const auto& item : std::filesystem::directory_iterator(self.parent_path(), ec)) {
        const std::string name = item.path().filename().string();
        if (name.rfind("libmfdyn_", 0) == 0 && item.path().extension() == ".so")
            dlopen(item.path().c_str(), RTLD_NOW | RTLD_GLOBAL);
    }
}

namespace {

// Ranks other than 0 write nothing to the standard output: the log, progress and summary come
// from rank 0 (whose figures are global reductions). Errors go to the standard error.
class NullBuffer : public std::streambuf {
protected:
    int overflow(int c) override { return traits_type::not_eof(c); }
    std::streamsize xsputn(const char*, std::streamsize n) override { return n; }
};

// Finalises MPI however runApplication leaves (return or exception).
struct CommunicatorSession {
    CommunicatorSession(int& argc, char**& argv) {
        Communicator::initialise(argc, argv);
        if (Communicator::rank() != 0) {
            static NullBuffer quiet;
            std::cout.rdbuf(&quiet);
        }
    }
    ~CommunicatorSession() { Communicator::finalise(); }
};

// An error ends the process with status 1. On several ranks an error is either collective (every
// rank threw it together: a bad dictionary, a diagnosis made through a global reduction, which
// gives every rank the same words) or one rank's own; a rank cannot tell which, so it waits a
// few seconds for the others at a barrier. All there: rank 0 reports, every rank returns 1. Some
// missing (they are inside a collective this rank will never join): this rank reports with its
// rank named and ends the whole job, never a hang.
int failWith(const std::string& text) {
    std::cout.flush();
    if (!Communicator::distributed()) {
        std::cerr << text << std::endl;
        return 1;
    }
    constexpr double waitForOthers = 3.0;
    if (Communicator::barrierWithin(waitForOthers)) {
        if (Communicator::rank() == 0) std::cerr << text << std::endl;
        return 1;
    }
    std::cerr << "\n(" << Communicator::rankName()
              << ", the other ranks did not stop with it: the job is ended)" << text << std::endl;
    Communicator::abortAll(1);
}

}  // namespace

int runApplication(int argc, char** argv, const ApplicationInfo& info,
                   const std::function<int(const Arguments&)>& body) {
    preferPassiveWaitPolicy(argv);
    CommunicatorSession session(argc, argv);
    try {
        Arguments args = Arguments::parse(argc, argv, info);
        if (args.has("help")) {
            std::cout << usage(info);
            return 0;
        }
        if (args.has("version")) {
            std::cout << info.name << " (mfdyn " << MFDYN_VERSION << ")\n";
            return 0;
        }
        if (args.has("listModels") || args.has("describe")) {
            // Every toolkit library beside this one, so any application lists every family.
            loadToolkitLibraries();
            // A case's own libraries extend the listing, so a user sees what their case can select.
            const auto controlDict = args.caseDir() / "system" / "controlDict";
            if (info.usesCase && std::filesystem::exists(controlDict))
                LibraryLoader::load(Dictionary::read(controlDict), args.caseDir());
            if (auto what = args.find("describe"))
                std::cout << RegistryIndex::global().describe(*what);
            else
                std::cout << RegistryIndex::global().listing(info.solver);
            return 0;
        }
        if (args.positional().size() < info.positional.size())
            throw InputError("missing argument <" + info.positional[args.positional().size()] + ">\n" +
                             usage(info));
        // A utility under mpirun would run once per rank on the same case (N copies of particleGen's
        // particles, N writers of one file): the solvers alone run distributed (info.solver; the
        // solver registry refuses those that do not).
        if (Communicator::distributed() && info.solver.empty())
            throw InputError(info.name +
                             " runs on one process: start it without mpirun (the solvers run on several "
                             "ranks and read what it writes on any number)");
        return body(args);
    } catch (const Error& e) {
        return failWith(std::string("\nError: ") + e.what() + "\n");
    } catch (const std::filesystem::filesystem_error& e) {
        // A path the system refuses to look at (a link to itself, no permission) is bad input,
        // not a bug: name the path and the system's reason.
        return failWith("\nError: cannot access '" + e.path1().string() + "': " + e.code().message() + "\n");
    } catch (const std::exception& e) {
        return failWith(std::string("\nError (internal): ") + e.what() + "\n");
    }
}

}  // namespace mfdyn
