#pragma once
#include "geometry/CsgShape.hpp"

namespace mfdyn {

class Difference final : public CsgShape {
public:
    using CsgShape::CsgShape;
    bool inside(const double* x) const override;
    BoundingBox bounds() const override;
};

}  // namespace mfdyn
