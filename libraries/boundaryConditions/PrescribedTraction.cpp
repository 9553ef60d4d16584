// prescribedTraction: a traction t(t) [Pa] on the selected surface particles, which carry the
// total force t A, A the loaded face's area, shared in proportion to their volumes:
//     f_a = t A V_a / Σ_b V_b,   Σ_a f_a = t A.
//   Lee, Gil, Greto, Karim & Bonet 2016 section 2.7 (doc/methods/tl-jst-sph.md 2.7, "natural BCs enter
//   through E_a = (A_a/V_a) t_a"): A_a, the area particle a stands for, is not given there; on
//   a nodal lattice with tributary volumes (NodalLattice.cpp) the face particles' volumes are
//   Δx/2 times their tributary face areas, so A V_a/Σ V_b = A_a exactly, and f_a = A_a t a
//   uniform traction. On other lattices the shares are an approximation of A_a.
// The forces are boundary forces [N] per particle (hook addBoundaryForce): a total-Lagrangian
// solver adds f_a/V_a to dp_a/dt, an updated-Lagrangian one f_a/m_a to dv_a/dt.
//
// The particles and V_a = mass/density are taken when the condition is built (the reference
// volumes when built at the start of a run) and kept by globalId through reorders; a particle
// the solver removes takes its share of the force with it.
//
// Usage: name { type prescribedTraction; regions (...); | shape { ... } | all yes;
//               traction (0 -1e6 0); | table ((0 (0 0 0)) (1e-3 (0 -1e6 0)));
//               area 0.25;  [releaseTime t;] }
// A selection is required (the loaded face); the particle set needs the fields mass and density.
#include "boundaryConditions/PrescribedTraction.hpp"

#include "core/Parallel.hpp"

#include <algorithm>
#include <cmath>

namespace mfdyn {

template <int Dim>
KeywordSchema PrescribedTraction<Dim>::keywords() {
    return KeywordSchema("boundaryCondition", "prescribedTraction")
        .append(vectorTableKeywords("traction", "Pa", "the traction on the loaded face"))
        .scalar("area", "m^2", "the area of the loaded face, which carries the total force traction × area")
        .greaterThan(0)
        .append(commonBoundaryConditionKeywords());
}

template <int Dim>
PrescribedTraction<Dim>::PrescribedTraction(const Dictionary& dict, const ParticleSet<Dim>& particles)
    : PrescribedTraction(keywords().read(dict), particles) {}

template <int Dim>
PrescribedTraction<Dim>::PrescribedTraction(const KeywordValues& values, const ParticleSet<Dim>& particles)
    : BoundaryCondition<Dim>(values, particles, false), table_(values, "traction", "Pa") {
    const Dictionary& dict = values.dict();
    area_ = values.scalar("area");

    const auto* mass = particles.template findField<double>("mass");
    const auto* density = particles.template findField<double>("density");
    if (!mass || !density)
        throw dict.error("type",
                         "prescribedTraction shares the force by particle volume, mass/density: the "
                         "particles need the fields `mass` and `density`");
    const auto& id = particles.globalId();
    double mine = 0;
    for (const std::size_t i : this->selection_.indices()) {
        const double v = (*mass)[i] / (*density)[i];
        if (!(v > 0.0) || !std::isfinite(v))
            throw dict.error("type", "particle " + std::to_string(id[i]) + " has volume mass/density = " +
                                         std::to_string(v) + "; expected > 0");
        indices_.push_back(i);
        ids_.push_back(id[i]);
        share_.push_back(v);
        mine += v;
    }
    // The loaded face's whole volume, over every rank's part of it (summed in order here, as ever).
    const double total = globalSum(mine);
    for (double& s : share_) s *= area_ / total;
}

template <int Dim>
typename PrescribedTraction<Dim>::VectorType PrescribedTraction<Dim>::traction(double t) const {
    return table_.value(t);
}

template <int Dim>
void PrescribedTraction<Dim>::boundaryForce(const ParticleSet<Dim>&, std::vector<VectorType>& force,
                                            double t) const {
    const VectorType tr = traction(t);
    for (std::size_t k = 0; k < indices_.size(); ++k) force[indices_[k]] += share_[k] * tr;
}

template <int Dim>
void PrescribedTraction<Dim>::selectionUpdated(const ParticleSet<Dim>& particles) {
    const auto index = this->indicesOf(particles, ids_);
    std::vector<std::int64_t> ids;
    std::vector<double> share;
    indices_.clear();
    for (std::size_t k = 0; k < ids_.size(); ++k)
        if (index[k] != this->npos) {
            indices_.push_back(index[k]);
            ids.push_back(ids_[k]);
            share.push_back(share_[k]);
        }
    ids_ = std::move(ids);
    share_ = std::move(share);
}

template class PrescribedTraction<1>;
template class PrescribedTraction<2>;
template class PrescribedTraction<3>;

MFDYN_REGISTER_DIM(BoundaryCondition, PrescribedTraction, "prescribedTraction",
                   "traction t(t) on a face of given area, as forces shared by particle volume");

}  // namespace mfdyn
