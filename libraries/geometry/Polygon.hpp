#pragma once
// `polygon`: a simple polygon in 2D, given by its vertices in order (either orientation); a
// triangle is a polygon of three. See Polygon.cpp.
//     shape { type polygon; vertices ((0 0) (0.2 0) (0.1 0.173205080757)); }
#include "geometry/Shape.hpp"

#include <vector>

namespace mfdyn {

class Polygon final : public Shape {
public:
    Polygon(const Dictionary& dict, int dimension);
    bool inside(const double* x) const override;
    BoundingBox bounds() const override { return box_; }
    std::optional<double> volume() const override { return area_; }

private:
    std::vector<std::array<double, 2>> vertices_;
    BoundingBox box_;
    double area_ = 0;
};

}  // namespace mfdyn
