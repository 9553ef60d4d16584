#pragma once
// `materialPoints`: the material points of the material point method (doc/methods/mpm.md section
// 3, the thesis's mpm_rect/mpm_circ/mpm_tria generators): the shape's bounding box cut into
// sub-cells, one point at each sub-cell centre (pattern centre, the thesis's pattern 1) or the
// 2 x 2 (x 2) Gauss points of each sub-cell (pattern gauss, its pattern 2), kept where inside the
// shape; each kept point stands for the shape's exact volume / N. See MaterialPointLattice.cpp.
//     lattice { type materialPoints; cells (10 10); pattern gauss; }
//     lattice { type materialPoints; spacing 0.002; pattern centre; }
#include "geometry/Lattice.hpp"

#include <array>
#include <string>

namespace mfdyn {

class MaterialPointLattice final : public Lattice {
public:
    static KeywordSchema keywords();
    MaterialPointLattice(const Dictionary& dict, int dimension);

    std::vector<double> points(const BoundingBox& box) const override;
    // Always an InputError: asked only by `mass equalMass`, which cannot apply here since the
    // particles' volume is the shape's exact volume / N (volumeFromShape()).
    double pointVolume() const override;
    // Sub-cell volume / points per sub-cell: the volume when the shape has no closed-form volume.
    std::vector<double> pointVolumes(const BoundingBox& box,
                                     const std::vector<double>& points) const override;
    bool volumeFromShape() const override { return true; }

    // Sub-cells per direction over `box` (1 in unused directions) and their sizes.
    std::array<long, 3> cells(const BoundingBox& box) const;
    std::array<double, 3> cellSizes(const BoundingBox& box) const;
    bool gauss() const { return gauss_; }

protected:
    std::vector<double> sites(const BoundingBox& box) const override;
    std::array<double, 3> siteCounts(const BoundingBox& box) const override;

private:
    MaterialPointLattice(const Dictionary& dict, const KeywordValues& v, int dimension);
    std::array<long, 3> cells_{0, 0, 0};  // from `cells`, else 0
    bool gauss_ = false;
    std::string where_;  // the dictionary's scope, for messages
};

}  // namespace mfdyn
