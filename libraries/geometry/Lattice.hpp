#pragma once
// Where particles sit inside a shape, selected by name:
//     lattice { type cubic; spacing 0.01; }
// A lattice fills a bounding box with points, each carrying the volume it represents.
#include "core/Registry.hpp"
#include "geometry/Shape.hpp"

#include <memory>
#include <vector>

namespace mfdyn {

class Lattice {
public:
    static constexpr const char* familyName = "lattice";
    using Selector = Registry<Lattice, const Dictionary&, int>;
    static std::unique_ptr<Lattice> New(const Dictionary& dict, int dimension) {
        return Selector::New(dict, dimension);
    }

    Lattice(const Dictionary& dict, int dimension);
    virtual ~Lattice();
    int dimension() const { return dimension_; }
    double spacing() const { return spacing_; }

    // Points covering `box`, `dimension()` coordinates each, in a fixed order (so generation is
    // identical run to run).
    virtual std::vector<double> points(const BoundingBox& box) const = 0;
    // Volume per lattice point (spacing^dim for cubic).
    virtual double pointVolume() const = 0;

private:
    int dimension_;
    double spacing_;
};

}  // namespace mfdyn
