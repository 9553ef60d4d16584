#pragma once
// A region of space that particles are generated in, selected by name:
//     shape { type box; min (0 0 0); max (1 1 1); }
// Shapes work in the case's dimension (1, 2 or 3); points have that many components.
// Types: box, sphere, cylinder (2D/3D), polygon (2D), stlSurface (3D), and union, intersection and difference
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

    // The largest coordinate or length accepted: the square of a distance between two points
    // within it, (2 × 1e150)², is still a finite double.
    static constexpr double maxCoordinate = 1e150;

protected:
    // Reads a point with at least `dimension` components (extra ones must be zero), each within
    // ±maxCoordinate.
    std::array<double, 3> readPoint(const Dictionary& dict, const std::string& key) const;
    // A radius or length: positive and at most maxCoordinate, else an InputError at `key`.
    double readLength(const Dictionary& dict, const std::string& key) const;
    // InputError at `key` when bounds() is not finite (a centre near 1e308 plus a radius overflows),
    // so that no lattice is asked to cover an infinite box.
    void checkBounds(const Dictionary& dict, const std::string& key) const;

private:
    int dimension_;
};

}  // namespace mfdyn
