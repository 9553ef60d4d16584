// tlSph: total-Lagrangian mixed {p, F, H, J} SPH with JST stabilisation for large-strain solid
// dynamics (Lee et al. 2016). See libraries/tlSph/TlSphSolver.hpp and tutorials/tlSph/.
#include "core/Application.hpp"
#include "solver/SolverRegistry.hpp"

int main(int argc, char** argv) {
    const mfdyn::ApplicationInfo info{
        "tlSph",
        "Total-Lagrangian mixed {p,F,H,J} JST-SPH for large-strain solid dynamics (constant/tlSphProperties, "
        "constant/materialProperties).",
        {},
        {},
        true,
        "tlSph"};
    return mfdyn::runApplication(argc, argv, info, [](const mfdyn::Arguments& args) {
        return mfdyn::runSolver(args, "tlSph");  // registered by libmfdyn_tlSph
    });
}
