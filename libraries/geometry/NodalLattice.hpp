#pragma once
// `nodal`: the Cartesian lattice of total-Lagrangian SPH, nodes on the boundary faces included,
// each node carrying its tributary (dual-cell) volume. See NodalLattice.cpp.
//     lattice { type nodal; spacing 0.05; }
//     lattice { type nodal; points (21 11 3); }
#include "geometry/Lattice.hpp"

#include <array>
#include <string>

namespace mfdyn {

class NodalLattice final : public Lattice {
public:
    static KeywordSchema keywords();
    NodalLattice(const Dictionary& dict, int dimension);

    // Jittered sites: only the coordinates of a node that are not on a face of the box move, so a
    // node on a face stays exactly on it.
    std::vector<double> points(const BoundingBox& box) const override;
    // Δx^dim for an interior node of the nominal spacing. With `points` the spacing depends on
    // the box, so there is no volume per point before it is known: an InputError.
    double pointVolume() const override;
    // Π_d Δx_d, halved once per face of `box` the point lies on: Σ V = |box|.
    std::vector<double> pointVolumes(const BoundingBox& box,
                                     const std::vector<double>& points) const override;

    // Nodes per direction and the spacing L_d/(n_d − 1) they give on `box` (unused directions: 1, 0).
    std::array<long, 3> counts(const BoundingBox& box) const;
    std::array<double, 3> spacings(const BoundingBox& box) const;

protected:
    std::vector<double> sites(const BoundingBox& box) const override;
    std::array<double, 3> siteCounts(const BoundingBox& box) const override;

private:
    NodalLattice(const Dictionary& dict, const KeywordValues& v, int dimension);
    std::array<long, 3> points_{0, 0, 0};  // from `points`, else 0
    std::string where_;                    // the dictionary's scope, for messages
};

}  // namespace mfdyn
