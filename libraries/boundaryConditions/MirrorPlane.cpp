// mirrorPlane: ghost particles mirrored through a plane, made (when the solver asks: impactSph at
// its list rebuilds, SphSolver.cpp) from the particles within a layer of thickness 3 h_max
// (Zisis 2017 section 5.5, the shock-bubble tube; doc/methods/sph-impact.md section 4.3;
// Libersky, Petschek, Carney, Hipp & Allahdadi 1993 for mirror ghosts in SPH). For a source
// particle at x with d = (x - point)·n, 0 < d < thickness:
//     x_ghost = x - 2 d n                                   (exact mirror image)
//     v_ghost = v - 2 (v·n) n        free slip (default): normal velocity reversed, tangential kept
//     v_ghost = -v                   noSlip yes: the wall velocity (zero) at the plane
// and every scalar of the ghost is its source's (GhostBlock::source), so the interaction across
// the plane pushes approaching particles back and the kernel sums near the plane are complete.
// 3 h_max covers the support of the Gaussian truncated at 3h (doc/methods/sph-impact.md section 1); give
// `thicknessFactor 2` for a kernel with support 2h, or `thickness` in metres.
// Images of images: the ghosts already made by the conditions written before this one (other
// mirror planes) are mirrored too, where within the layer and made from a selected particle,
// with their maps composed (GhostBlock::map = R2 R1): two perpendicular planes give the corner
// quadrant, three the octant, as the reflection group of perpendicular planes needs. Planes at
// other angles generate larger groups that one pass in the written order does not close.
// Limits: particles on the plane (d within tolerance) make no ghost, since it would sit on top of
// its source.
//
// Usage: name { type mirrorPlane; point (0 0 0); normal (1 0 0);  [noSlip no;]
//               [thicknessFactor 3; | thickness 0.01;] [tolerance 1e-9;]
//               [regions (...); | shape { ... }] }    (default: all particles)
// The normal points into the material.
#include "boundaryConditions/MirrorPlane.hpp"

namespace mfdyn {

template <int Dim>
KeywordSchema MirrorPlane<Dim>::keywords() {
    return KeywordSchema("boundaryCondition", "mirrorPlane")
        .append(planeKeywords())
        .flag("noSlip", "ghost velocity -v (no slip) instead of the reflected v (free slip)")
        .orDefault(false)
        .scalar("thicknessFactor", "-", "the mirrored layer's thickness in units of h_max")
        .greaterThan(0)
        .orDefault(3.0)
        .scalar("thickness", "m", "the mirrored layer's thickness (instead of thicknessFactor)")
        .greaterThan(0)
        .optional()
        .append(commonBoundaryConditionKeywords());
}

template <int Dim>
MirrorPlane<Dim>::MirrorPlane(const Dictionary& dict, const ParticleSet<Dim>& particles)
    : MirrorPlane(keywords().read(dict), particles) {}

template <int Dim>
MirrorPlane<Dim>::MirrorPlane(const KeywordValues& values, const ParticleSet<Dim>& particles)
    : BoundaryCondition<Dim>(values, particles, true),
      plane_(values, particles.position()),
      noSlip_(values.flag("noSlip")),
      thicknessFactor_(values.scalar("thicknessFactor")),
      thickness_(values.optionalScalar("thickness")) {
    if (values.given("thickness") && values.given("thicknessFactor"))
        throw values.error("thickness",
                           "give `thickness` [m] or `thicknessFactor` [-] (times h_max), not both");
}

template <int Dim>
GhostBlock<Dim> MirrorPlane<Dim>::ghosts(const ParticleSet<Dim>& particles,
                                         const std::vector<VectorType>& velocity, double hMax) const {
    GhostBlock<Dim> block;
    ghostLayer(particles, velocity, hMax, block);
    return block;
}

template <int Dim>
void MirrorPlane<Dim>::ghostLayer(const ParticleSet<Dim>& particles, const std::vector<VectorType>& velocity,
                                  double hMax, GhostBlock<Dim>& block) const {
    const auto& x = particles.position();
    const VectorType& n = plane_.normal();
    const double layer = thickness(hMax);
    using TensorType = Tensor<Dim>;
    const TensorType reflection = TensorType::Identity() - 2.0 * n * n.transpose();
    const auto image = [&](const VectorType& v) {
        return noSlip_ ? VectorType(-v) : VectorType(reflection * v);
    };
    const std::size_t earlier = block.size();  // ghosts of the conditions written before this one
    // Serial, in index order: the block is the same for any thread count, and the pass is one
    // dot product per particle, cheap next to the neighbour search it feeds.
    // The owned particles, then (MPI) the halo's: an image of another rank's particle near the
    // plane is a neighbour of this rank's particles too.
    std::vector<std::size_t> haloSources;
    if (particles.haloCount() != 0) haloSources = this->selection_.haloIndices(particles);
    std::vector<std::size_t> ownedAndHalo;
    if (!haloSources.empty()) {
        ownedAndHalo = this->selection_.indices();
        ownedAndHalo.insert(ownedAndHalo.end(), haloSources.begin(), haloSources.end());
    }
    const auto& selected = haloSources.empty() ? this->selection_.indices() : ownedAndHalo;
    for (std::size_t i : selected) {
        const double d = plane_.signedDistance(x[i]);
        if (d <= plane_.tolerance() || d >= layer) continue;
        block.position.push_back(x[i] - 2.0 * d * n);
        block.velocity.push_back(image(velocity[i]));
        block.source.push_back(i);
        block.map.push_back(reflection);
        block.parity.push_back(1.0);
    }
    if (earlier == 0) return;
    std::vector<char> isSelected(x.size(), 0);
    for (std::size_t i : selected) isSelected[i] = 1;
    for (std::size_t g = 0; g < earlier; ++g) {
        if (!isSelected[block.source[g]]) continue;
        const VectorType position = block.position[g];
        const double d = plane_.signedDistance(position);
        if (d <= plane_.tolerance() || d >= layer) continue;
        const VectorType velocity = image(block.velocity[g]);
        const TensorType map = reflection * block.map[g];
        block.position.push_back(position - 2.0 * d * n);
        block.velocity.push_back(velocity);
        block.source.push_back(block.source[g]);
        block.map.push_back(map);
        block.parity.push_back(double(block.parity[g]));
    }
}

template class MirrorPlane<1>;
template class MirrorPlane<2>;
template class MirrorPlane<3>;

MFDYN_REGISTER_DIM(BoundaryCondition, MirrorPlane, "mirrorPlane",
                   "mirror ghost particles within 3 h_max of a plane, free-slip or no-slip");

}  // namespace mfdyn
