#pragma once
#include "geometry/Lattice.hpp"

namespace mfdyn {

class CubicLattice final : public Lattice {
public:
    CubicLattice(const Dictionary& dict, int dimension);
    std::vector<double> points(const BoundingBox& box) const override;
    double pointVolume() const override;
};

}  // namespace mfdyn
