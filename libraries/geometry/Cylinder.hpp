#pragma once
#include "geometry/Shape.hpp"

namespace mfdyn {

class Cylinder final : public Shape {
public:
    Cylinder(const Dictionary& dict, int dimension);
    bool inside(const double* x) const override;
    BoundingBox bounds() const override;
    std::optional<double> volume() const override;

private:
    std::array<double, 3> point1_, point2_;
    std::array<double, 3> axis_{0, 0, 0};  // unit vector point1 → point2
    double length_ = 0;
    double radius_;
};

}  // namespace mfdyn
