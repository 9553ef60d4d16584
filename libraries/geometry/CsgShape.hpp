#pragma once
// Constructive solid geometry: the common part of union, intersection and difference, which
// combine the shapes listed in `shapes`, either as a list of dictionaries
//     shape { type difference; shapes ( { type box; min (0 0); max (1 1); }
//                                       { type sphere; centre (0.5 0.5); radius 0.2; } ); }
// or as named sub-dictionaries
//     shape { type union; shapes { left { type box; ... } right { type sphere; ... } } }
// in the order given (difference takes the first and removes all the others).
#include "geometry/Shape.hpp"

#include <memory>
#include <vector>

namespace mfdyn {

class CsgShape : public Shape {
public:
    CsgShape(const Dictionary& dict, int dimension);
    ~CsgShape() override;

protected:
    const std::vector<std::unique_ptr<Shape>>& shapes() const { return shapes_; }

private:
    std::vector<std::unique_ptr<Shape>> shapes_;
};

}  // namespace mfdyn
