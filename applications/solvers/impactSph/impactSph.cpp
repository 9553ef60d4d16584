// impactSph: updated-Lagrangian SPH for shocks and hypervelocity impact through inhomogeneous
// media (Zisis 2017). See libraries/sph/SphSolver.hpp and tutorials/impactSph/.
#include "core/Application.hpp"
#include "solver/SolverRegistry.hpp"

int main(int argc, char** argv) {
    const mfdyn::ApplicationInfo info{
        "impactSph",
        "Updated-Lagrangian SPH for shocks and impact (constant/sphProperties, constant/materialProperties).",
        {},
        {},
        true,
        "impactSph"};
    return mfdyn::runApplication(argc, argv, info, [](const mfdyn::Arguments& args) {
        return mfdyn::runSolver(args, "impactSph");  // registered by libmfdyn_sph
    });
}
