#include "solver/Solver.hpp"

#include "solver/SolverRun.hpp"

namespace mfdyn {

Solver::Solver(SolverRun& run) : run_(run) {}
Solver::~Solver() = default;

const Case& Solver::runCase() const {
    return run_.runCase();
}
const Time& Solver::time() const {
    return run_.time();
}
const std::string& Solver::startTimeName() const {
    return run_.startTimeName();
}

}  // namespace mfdyn
