#pragma once
// A region of space that particles are generated in, selected by name:
//     shape { type box; min (0 0 0); max (1 1 1); }
// Shapes work in the case's dimension (1, 2 or 3); points have that many components.
// Types: box, sphere, cylinder (2D/3D), stlSurface (3D), and union, intersection and difference
// of a list of shapes (CsgShape.hpp); `particleGen -listModels` prints them with their libraries.
#include "core/Registry.hpp"

#include <array>
#include <memory>
#include <optional>

namespace mfdyn {

struct BoundingBox {
    std::array<double, 3> min{0, 0, 0}, max{0, 0, 0};
};

class Shape {
public:
    static constexpr const char* familyName = "shape";
    using Selector = Registry<Shape, const Dictionary&, int>;
    static std::unique_ptr<Shape> New(const Dictionary& dict, int dimension) {
        return Selector::New(dict, dimension);
    }

    Shape(const Dictionary& dict, int dimension);
    virtual ~Shape();
    int dimension() const { return dimension_; }

    virtual bool inside(const double* x) const = 0;
    virtual BoundingBox bounds() const = 0;
    // The exact volume (length in 1D, area in 2D), when known in closed form.
    virtual std::optional<double> volume() const { return std::nullopt; }

protected:
    // Reads a point with at least `dimension` components (extra ones must be zero).
    std::array<double, 3> readPoint(const Dictionary& dict, const std::string& key) const;

private:
    int dimension_;
};

}  // namespace mfdyn
