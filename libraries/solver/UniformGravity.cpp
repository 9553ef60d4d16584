// uniformGravity: a = g, constant.
//
//   phi(x) = -g·x                         potential per unit mass
//   x(t) = x0 + v0 t + ½ g t²,  v(t) = v0 + g t    (exact trajectory)
//
// Velocity Verlet integrates a constant acceleration exactly, so any error the particleFlight
// solver shows on this force is round-off: the framework case's reference is exact.
#include "solver/UniformGravity.hpp"

namespace mfdyn {

KeywordSchema UniformGravity::keywords() {
    return KeywordSchema(familyName, "uniformGravity")
        .vector("g", "m/s^2", "the acceleration, at least one component per dimension (zero beyond it)");
}

UniformGravity::UniformGravity(const Dictionary& dict, int dimension) : BodyForce(dict, dimension) {
    const KeywordValues values = keywords().read(dict);
    const std::vector<double>& g = values.vector("g");
    if (int(g.size()) < dimension)
        throw dict.error("g", "expected a vector of at least " + std::to_string(dimension) +
                                  " components for a " + std::to_string(dimension) + "D case");
    for (std::size_t k = dimension; k < g.size(); ++k)
        if (g[k] != 0)
            throw dict.error("g", "component " + std::to_string(k + 1) + " is non-zero in a " +
                                      std::to_string(dimension) + "D case");
    for (int d = 0; d < dimension; ++d) g_[d] = g[d];
}

void UniformGravity::acceleration(const double*, double, double* a) const {
    for (int d = 0; d < dimension(); ++d) a[d] = g_[d];
}

double UniformGravity::potential(const double* x) const {
    double phi = 0;
    for (int d = 0; d < dimension(); ++d) phi -= g_[d] * x[d];
    return phi;
}

bool UniformGravity::exactTrajectory(const double* x0, const double* v0, double tau, double* x,
                                     double* v) const {
    for (int d = 0; d < dimension(); ++d) {
        x[d] = x0[d] + v0[d] * tau + 0.5 * g_[d] * tau * tau;
        v[d] = v0[d] + g_[d] * tau;
    }
    return true;
}

MFDYN_REGISTER(BodyForce, UniformGravity, "uniformGravity",
               "constant acceleration g (exact trajectory known)");

}  // namespace mfdyn
