#include "solver/BodyForce.hpp"

#include <limits>

namespace mfdyn {

BodyForce::BodyForce(const Dictionary&, int dimension) : dimension_(dimension) {}
BodyForce::~BodyForce() = default;

TimeStepVote BodyForce::stableTimeStep() const {
    return {std::numeric_limits<double>::infinity(), "body force"};
}

}  // namespace mfdyn
