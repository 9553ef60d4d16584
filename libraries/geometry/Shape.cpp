#include "geometry/Shape.hpp"

namespace mfdyn {

Shape::Shape(const Dictionary&, int dimension) : dimension_(dimension) {}
Shape::~Shape() = default;

std::array<double, 3> Shape::readPoint(const Dictionary& dict, const std::string& key) const {
    const auto values = dict.get<std::vector<double>>(key);
    if (int(values.size()) < dimension_)
        throw dict.error(key, "expected a point of " + std::to_string(dimension_) + " components, found " +
                                  std::to_string(values.size()));
    std::array<double, 3> p{0, 0, 0};
    for (std::size_t k = 0; k < values.size(); ++k) {
        if (int(k) < dimension_)
            p[k] = values[k];
        else if (values[k] != 0)
            throw dict.error(key, "component " + std::to_string(k + 1) + " is non-zero in a " +
                                      std::to_string(dimension_) + "D case");
    }
    return p;
}

}  // namespace mfdyn
