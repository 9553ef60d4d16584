// prescribedVelocity: v = v_p(t) and dv/dt = dv_p/dt on the selection while t < releaseTime;
// afterwards the particles move freely from the velocity they had.
//   Lee et al. 2016 section 2.7 and Fig. 15 (tl-jst-sph.md 2.7 and 8.7, the punch): p = rho0 v_pres,
//   dp/dt = 0, v = (0, -100, 0) m/s on the mid quarter of the top face, released at t = 0.007 s.
//   A total-Lagrangian solver working in momentum multiplies velocity(t) by rho0 itself.
// The rate is set to dv_p/dt (zero for a constant velocity, the paper's dp/dt = 0) rather than
// left to the forces, so that an integrator stage between two velocity resets follows v_p(t).
//
// Usage: name { type prescribedVelocity; regions (...); | shape { ... } | all yes;
//               velocity (0 -100 0); | table ((0 (0 0 0)) (1e-3 (0 -100 0)));  [releaseTime 0.007;] }
#include "boundaryConditions/PrescribedVelocity.hpp"

#include <algorithm>

namespace mfdyn {

namespace {

// A `(vx vy vz)` token as a Dim-vector; extra components must be zero, as for dictionary vectors.
template <int Dim>
Vector<Dim> vectorOf(const Token& token, const Dictionary& dict) {
    if (token.kind != Token::Kind::list)
        throw dict.error("table", "expected a vector (vx vy vz), found " + token.str());
    Vector<Dim> v = Vector<Dim>::Zero();
    for (std::size_t k = 0; k < token.list.size(); ++k) {
        if (!token.list[k].isNumber())
            throw dict.error("table", "expected a number, found " + token.list[k].str());
        const double x = token.list[k].number();
        if (int(k) < Dim)
            v[k] = x;
        else if (x != 0.0)
            throw dict.error("table", "component " + std::to_string(k + 1) + " of " + token.str() +
                                          " is non-zero but the case has fewer dimensions");
    }
    if (int(token.list.size()) < Dim)
        throw dict.error("table", "expected " + std::to_string(Dim) + " components, found " + token.str());
    return v;
}

}  // namespace

template <int Dim>
PrescribedVelocity<Dim>::PrescribedVelocity(const Dictionary& dict, const ParticleSet<Dim>& particles)
    : BoundaryCondition<Dim>(dict, particles, false) {
    const bool hasVelocity = dict.found("velocity"), hasTable = dict.found("table");
    if (hasVelocity == hasTable)
        throw InputError(
            dict.where(), dict.scope(),
            "give exactly one of `velocity (vx vy vz);` [m/s] and `table ((t (vx vy vz)) ...);`");
    if (hasVelocity) {
        times_ = {0.0};
        values_ = {dict.get<VectorType>("velocity")};
        return;
    }
    const Entry& entry = dict.entry("table");
    if (entry.tokens.size() != 1 || entry.tokens[0].kind != Token::Kind::list || entry.tokens[0].list.empty())
        throw dict.error("table", "expected a list of (time (vx vy vz)) pairs");
    for (const Token& row : entry.tokens[0].list) {
        if (row.kind != Token::Kind::list || row.list.size() != 2 || !row.list[0].isNumber())
            throw dict.error("table", "expected (time (vx vy vz)), found " + row.str());
        const double t = row.list[0].number();
        if (!times_.empty() && !(t > times_.back()))
            throw dict.error("table", "times must increase, found " + row.list[0].str() + " after " +
                                          std::to_string(times_.back()));
        times_.push_back(t);
        values_.push_back(vectorOf<Dim>(row.list[1], dict));
    }
}

template <int Dim>
typename PrescribedVelocity<Dim>::VectorType PrescribedVelocity<Dim>::velocity(double t) const {
    if (t <= times_.front()) return values_.front();
    if (t >= times_.back()) return values_.back();
    const auto k = std::size_t(std::upper_bound(times_.begin(), times_.end(), t) - times_.begin()) - 1;
    const double w = (t - times_[k]) / (times_[k + 1] - times_[k]);
    return (1.0 - w) * values_[k] + w * values_[k + 1];
}

template <int Dim>
typename PrescribedVelocity<Dim>::VectorType PrescribedVelocity<Dim>::acceleration(double t) const {
    if (t < times_.front() || t >= times_.back()) return VectorType::Zero();
    const auto k = std::size_t(std::upper_bound(times_.begin(), times_.end(), t) - times_.begin()) - 1;
    return (values_[k + 1] - values_[k]) / (times_[k + 1] - times_[k]);
}

template <int Dim>
void PrescribedVelocity<Dim>::velocityConstraint(ParticleSet<Dim>&, std::vector<VectorType>& v, double t) {
    this->assignOnSelection(v, velocity(t));
}

template <int Dim>
void PrescribedVelocity<Dim>::accelerationConstraint(ParticleSet<Dim>&, std::vector<VectorType>& a,
                                                     double t) {
    this->assignOnSelection(a, acceleration(t));
}

template class PrescribedVelocity<1>;
template class PrescribedVelocity<2>;
template class PrescribedVelocity<3>;

MFDYN_REGISTER_DIM(BoundaryCondition, PrescribedVelocity, "prescribedVelocity",
                   "v = v_p(t) (constant or table) on the selection until releaseTime (punch)");

}  // namespace mfdyn
