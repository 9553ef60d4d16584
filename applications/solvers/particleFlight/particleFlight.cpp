// particleFlight: particles in free flight under a runtime-selected body force. The framework's
// proof case (exact answer for uniformGravity); see tutorials/particleFlight/.
#include "core/Application.hpp"
#include "solver/SolverRegistry.hpp"

int main(int argc, char** argv) {
    const mfdyn::ApplicationInfo info{
        "particleFlight",
        "Particles in free flight under a body force (constant/particleFlightProperties), velocity Verlet.",
        {},
        {},
        true,
        "particleFlight"};
    return mfdyn::runApplication(argc, argv, info, [](const mfdyn::Arguments& args) {
        return mfdyn::runSolver(args, "particleFlight");  // registered by libmfdyn_ballistics
    });
}
