#include "solver/SolverRegistry.hpp"

#include "core/Application.hpp"

namespace mfdyn {

namespace solverRegistry {

void add(const char* name, const char* description, Factory make, const void* registrant,
         const char* sourceFile, KeywordSchema (*keywords)(), const char* propertiesDictionary) {
    RegistryIndex::global().add(
        familyName, RegistryItem{name, description, sharedObjectOf(registrant),
                                 std::make_shared<const Factory>(std::move(make)), typeid(Factory).name(),
                                 sourceFileRelative(sourceFile), keywords, 0, propertiesDictionary});
}

std::unique_ptr<Solver> create(const std::string& name, SolverRun& run) {
    RegistryIndex& index = RegistryIndex::global();
    index.checkConflicts();
    const RegistryItem* item = index.family(familyName).find(name);
    if (!item) {
        // The application is linked with its method's library (--no-as-needed), so this is for a
        // program that was not: the toolkit's libraries register every solver.
        loadToolkitLibraries();
        index.checkConflicts();
        item = index.family(familyName).find(name);
    }
    if (!item) throw InputError(index.family(familyName).unknownTypeMessage(name));
    return (*static_cast<const Factory*>(item->make.get()))(run);
}

}  // namespace solverRegistry

int runSolver(const Arguments& args, const std::string& name) {
    SolverRun run(args, name);
    const std::unique_ptr<Solver> solver = solverRegistry::create(name, run);
    return run.run(*solver);
}

}  // namespace mfdyn
