#pragma once
#include "geometry/Lattice.hpp"

namespace mfdyn {

class CubicLattice final : public Lattice {
public:
    static KeywordSchema keywords();
    CubicLattice(const Dictionary& dict, int dimension);
    double pointVolume() const override;

protected:
    std::vector<double> sites(const BoundingBox& box) const override;
    std::array<double, 3> siteCounts(const BoundingBox& box) const override;
};

}  // namespace mfdyn
