// fpmSolid: the finite pointset method for the dynamics of hypo-elastic solids (von Nida 2005;
// doc/methods/fpm.md). See libraries/fpm/FpmSolver.hpp and tutorials/fpmSolid/.
#include "core/Application.hpp"
#include "solver/SolverRegistry.hpp"

int main(int argc, char** argv) {
    const mfdyn::ApplicationInfo info{
        "fpmSolid",
        "Finite pointset method for hypo-elastic solids (constant/fpmProperties): the Euler, shear and "
        "rotation parts of von Nida 2005, split, with free surfaces and boundary conditions.",
        {},
        {},
        true,
        "fpmSolid"};
    return mfdyn::runApplication(argc, argv, info, [](const mfdyn::Arguments& args) {
        return mfdyn::runSolver(args, "fpmSolid");  // registered by libmfdyn_fpm
    });
}
