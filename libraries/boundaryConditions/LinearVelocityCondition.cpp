// linearVelocity: a velocity Dirichlet condition linear in space,
//
//     frame current:  v(x_i, t) = v0 + G (x_i - origin)   (the particles' current positions; von Nida
//                     2005 §6.2.2 and §7.3, "v = v0(x) on the boundary", doc/methods/fpm.md §4.6, §4.10)
//     frame initial:  v_i = v0 + G (X_i - origin)          (X_i the position at the run's start: the
//                     Lagrangian condition v = v0(xi) of the note's caveat to §4.6, under which a
//                     linear flow is ballistic, x = (I + t G) X)
//
// until releaseTime. The rate on the selection is set to 0 in the initial frame (v_i is constant)
// and to G v_i in the current one (d/dt of G x along the particle path), so that an integrator
// stage between two velocity resets follows the condition.
//
// Usage: name { type linearVelocity; shape { ... } | regions (...) | all yes;
//               gradient (G11 G12 G13 G21 G22 G23 G31 G32 G33); [velocity (v0); origin (x0);
//               frame current | initial;] }
#include "boundaryConditions/LinearVelocityCondition.hpp"

#include "core/TensorEntry.hpp"

#include <sstream>

namespace mfdyn {

template <int Dim>
KeywordSchema LinearVelocityCondition<Dim>::keywords() {
    return KeywordSchema("boundaryCondition", "linearVelocity")
        .vector("gradient", "1/s",
                "G = dv_i/dx_j, row by row: Dim^2 or 9 values (a 3 x 3 G in a 2D case must be 0 outside its "
                "leading 2 x 2 block)")
        .vector("velocity", "m/s", "v0, the velocity at the origin")
        .orDefault(std::vector<double>{0, 0, 0})
        .vector("origin", "m", "the point where v = v0")
        .orDefault(std::vector<double>{0, 0, 0})
        .word("frame", {"current", "initial"},
              "the positions G acts on: the particles' current ones (v = v0(x)) or those of the run's start "
              "(v = v0(xi), the particles then keep their velocity)")
        .orDefault("current")
        .append(commonBoundaryConditionKeywords());
}

template <int Dim>
LinearVelocityCondition<Dim>::LinearVelocityCondition(const Dictionary& dict,
                                                      const ParticleSet<Dim>& particles)
    : LinearVelocityCondition(dict, keywords().read(dict), particles) {}

template <int Dim>
LinearVelocityCondition<Dim>::LinearVelocityCondition(const Dictionary& dict, const KeywordValues& values,
                                                      const ParticleSet<Dim>& particles)
    : BoundaryCondition<Dim>(values, particles, false),
      v0_(dict.getOrDefault<VectorType>("velocity", VectorType::Zero())),
      origin_(dict.getOrDefault<VectorType>("origin", VectorType::Zero())),
      gradient_(readTensor<Dim>(dict, "gradient")),
      initialFrame_(values.word("frame") == "initial") {
    if (!initialFrame_) return;
    const auto& x = particles.position();
    const auto& id = particles.globalId();
    for (std::size_t i : this->selection_.indices()) {
        ids_.push_back(id[i]);
        startVelocity_.push_back(velocityAt(x[i]));
    }
    index_ = this->indicesOf(particles, ids_);
}

template <int Dim>
void LinearVelocityCondition<Dim>::selectionUpdated(const ParticleSet<Dim>& particles) {
    if (initialFrame_) index_ = this->indicesOf(particles, ids_);
}

template <int Dim>
void LinearVelocityCondition<Dim>::velocityConstraint(ParticleSet<Dim>& particles, std::vector<VectorType>& v,
                                                      double) {
    if (initialFrame_) {
        for (std::size_t k = 0; k < index_.size(); ++k)
            if (index_[k] != this->npos) v[index_[k]] = startVelocity_[k];
        return;
    }
    const auto& x = particles.position();
    for (std::size_t i : this->selection_.indices()) v[i] = velocityAt(x[i]);
}

template <int Dim>
void LinearVelocityCondition<Dim>::accelerationConstraint(ParticleSet<Dim>& particles,
                                                          std::vector<VectorType>& a, double) {
    if (initialFrame_) {
        for (std::size_t k = 0; k < index_.size(); ++k)
            if (index_[k] != this->npos) a[index_[k]] = VectorType::Zero();
        return;
    }
    const auto& x = particles.position();
    for (std::size_t i : this->selection_.indices()) a[i] = gradient_ * velocityAt(x[i]);
}

template <int Dim>
std::string LinearVelocityCondition<Dim>::describe() const {
    std::ostringstream s;
    s << BoundaryCondition<Dim>::describe() << ", v = v0 + G (" << (initialFrame_ ? "X" : "x")
      << " - origin), |G| " << gradient_.norm();
    return s.str();
}

template class LinearVelocityCondition<1>;
template class LinearVelocityCondition<2>;
template class LinearVelocityCondition<3>;

MFDYN_REGISTER_DIM(
    BoundaryCondition, LinearVelocityCondition, "linearVelocity",
    "v = v0 + G (x - origin) on the selection, x current or the run's start (FPM validations)");

}  // namespace mfdyn
