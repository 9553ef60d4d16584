// mpmFsi: the explicit material point method for solids (doc/methods/mpm.md). See
// libraries/mpm/MpmSolver.hpp and tutorials/mpmFsi/.
#include "core/Application.hpp"
#include "solver/SolverRegistry.hpp"

int main(int argc, char** argv) {
    const mfdyn::ApplicationInfo info{
        "mpmFsi",
        "The explicit material point method (USL/USF/MUSL, FLIP/PIC/APIC) on a Cartesian background grid "
        "(constant/mpmProperties, constant/materialProperties).",
        {},
        {},
        true,
        "mpmFsi"};
    return mfdyn::runApplication(argc, argv, info, [](const mfdyn::Arguments& args) {
        return mfdyn::runSolver(args, "mpmFsi");  // registered by libmfdyn_mpm
    });
}
