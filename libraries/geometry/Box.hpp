#pragma once
#include "geometry/Shape.hpp"

namespace mfdyn {

class Box final : public Shape {
public:
    Box(const Dictionary& dict, int dimension);
    bool inside(const double* x) const override;
    BoundingBox bounds() const override { return box_; }
    std::optional<double> volume() const override;

private:
    BoundingBox box_;
};

}  // namespace mfdyn
