#include "geometry/Shape.hpp"

#include <cmath>
#include <cstdio>

namespace mfdyn {

namespace {

std::string format(double x) {
    char text[32];
    std::snprintf(text, sizeof text, "%.6g", x);
    return text;
}

}  // namespace

Shape::Shape(const Dictionary&, int dimension) : dimension_(dimension) {}
Shape::~Shape() = default;

std::array<double, 3> Shape::readPoint(const Dictionary& dict, const std::string& key) const {
    const auto values = dict.get<std::vector<double>>(key);
    if (int(values.size()) < dimension_)
        throw dict.error(key, "expected a point of " + std::to_string(dimension_) + " components, found " +
                                  std::to_string(values.size()));
    std::array<double, 3> p{0, 0, 0};
    for (std::size_t k = 0; k < values.size(); ++k) {
        // Beyond 1e150 m a squared distance (every neighbour search and kernel forms one)
        // overflows to inf; 1e400 already reads as inf.
        if (!(std::abs(values[k]) <= maxCoordinate))
            throw dict.error(key, "component " + std::to_string(k + 1) + " is " + format(values[k]) +
                                      ": coordinates must be finite and within +-1e150 m");
        if (int(k) < dimension_)
            p[k] = values[k];
        else if (values[k] != 0)
            throw dict.error(key, "component " + std::to_string(k + 1) + " is non-zero in a " +
                                      std::to_string(dimension_) + "D case");
    }
    return p;
}

double Shape::readLength(const Dictionary& dict, const std::string& key) const {
    const double value = dict.get<double>(key);
    if (!(value > 0) || !(value <= maxCoordinate))
        throw dict.error(key, key + " must be positive and at most 1e150 m, found " + format(value));
    return value;
}

void Shape::checkBounds(const Dictionary& dict, const std::string& key) const {
    const BoundingBox b = bounds();
    for (int d = 0; d < dimension_; ++d)
        if (!std::isfinite(b.min[d]) || !std::isfinite(b.max[d]) || !std::isfinite(b.max[d] - b.min[d]))
            throw dict.error(key, "the shape's extent in direction " + std::to_string(d + 1) +
                                      " overflows (from " + format(b.min[d]) + " to " + format(b.max[d]) +
                                      "): give coordinates and sizes within +-1e150 m");
}

}  // namespace mfdyn
