#pragma once
#include "geometry/Shape.hpp"

namespace mfdyn {

class Sphere final : public Shape {
public:
    Sphere(const Dictionary& dict, int dimension);
    bool inside(const double* x) const override;
    BoundingBox bounds() const override;
    std::optional<double> volume() const override;

private:
    std::array<double, 3> centre_;
    double radius_;
};

}  // namespace mfdyn
