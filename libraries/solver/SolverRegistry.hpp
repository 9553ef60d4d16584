#pragma once
// The solver registry: every method registers its solver with one line at the end of its .cpp, at
// namespace scope,
//
//     MFDYN_REGISTER_SOLVER(SphSolver, "impactSph", "Updated-Lagrangian SPH for shocks and impact");
//
// where SphSolver is the class template (SphSolver<Dim> constructed from a SolverRun&). The line
// adds one item to the registry family `solver` (core/Registry.hpp): a factory that builds
// Template<1>, <2> or <3> for the run's dimension, the schema of Template<3>::keywords() when the
// template declares it (the keywords of its properties dictionary: -listModels, -describe and
// the page doc/models/solver/<name>.md come from it), and the file that dictionary is, when the
// template declares `static constexpr const char* propertiesDictionary = "sphProperties";`. An
// application then selects its solver by name:
//
//     return mfdyn::runApplication(argc, argv, info, [](const mfdyn::Arguments& args) {
//         return mfdyn::runSolver(args, "impactSph");
//     });
//
// A registration is a static object in the method's shared library, which the application does
// not otherwise reference: the applications link with --no-as-needed (their CMakeLists.txt) so that
// the linker keeps the library, and runSolver loads the toolkit's libraries before it reports a
// solver it cannot find.
#include "core/Registry.hpp"
#include "solver/Solver.hpp"
#include "solver/SolverRun.hpp"

#include <functional>
#include <memory>
#include <string>

namespace mfdyn {

namespace solverRegistry {

// The family name under which solvers are registered.
inline constexpr const char* familyName = "solver";

using Factory = std::function<std::unique_ptr<Solver>(SolverRun&)>;

// Adds a solver to the family `solver` (what MFDYN_REGISTER_SOLVER expands to).
void add(const char* name, const char* description, Factory make, const void* registrant,
         const char* sourceFile, KeywordSchema (*keywords)(), const char* propertiesDictionary);

// The registered solver `name` built for `run`; an InputError listing the registered solvers when
// there is none of that name.
std::unique_ptr<Solver> create(const std::string& name, SolverRun& run);

template <template <int> class SolverType>
struct Registration {
    Registration(const char* name, const char* description, const char* sourceFile) {
        KeywordSchema (*keywords)() = nullptr;
        if constexpr (requires {
                          { SolverType<3>::keywords() } -> std::same_as<KeywordSchema>;
                      })
            keywords = &SolverType<3>::keywords;
        const char* dictionary = "";
        if constexpr (requires { SolverType<3>::propertiesDictionary; })
            dictionary = SolverType<3>::propertiesDictionary;
        add(
            name, description,
            [](SolverRun& run) {
                if (!runsOnSeveralRanks<SolverType>()) run.refuseSeveralRanks();
                return withDimension(run.dimension(), [&](auto dim) -> std::unique_ptr<Solver> {
                    return std::make_unique<SolverType<decltype(dim)::value>>(run);
                });
            },
            this, sourceFile, keywords, dictionary);
    }
};

}  // namespace solverRegistry

// Opens the case as `name` (the application), builds the registered solver of that name for the
// case's dimension and runs the time loop; returns the exit status.
int runSolver(const Arguments& args, const std::string& name);

#define MFDYN_REGISTER_SOLVER(Template, name, description)                                              \
    static const ::mfdyn::solverRegistry::Registration<Template> MFDYN_CONCAT(mfdynSolverRegistration_, \
                                                                              __LINE__) {               \
        name, description, __FILE__                                                                     \
    }

}  // namespace mfdyn
