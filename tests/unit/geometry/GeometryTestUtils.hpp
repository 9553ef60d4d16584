#pragma once
// Shared by the geometry tests: the volume a lattice gives a shape, as particleGen computes it
// (points of the lattice over the shape's bounds that fall inside, times the volume per point).
#include "core/Dictionary.hpp"
#include "geometry/Lattice.hpp"
#include "geometry/Shape.hpp"

#include <string>

namespace mfdyn::test {

inline std::unique_ptr<Shape> shape(const std::string& text, int dim) {
    return Shape::New(Dictionary::parse(text, "test"), dim);
}
inline std::unique_ptr<Lattice> lattice(const std::string& text, int dim) {
    return Lattice::New(Dictionary::parse(text, "test"), dim);
}

struct Filled {
    std::size_t count = 0;
    double volume = 0;
};

inline Filled fill(const Shape& s, const Lattice& l) {
    const auto p = l.points(s.bounds());
    const int dim = s.dimension();
    Filled f;
    for (std::size_t i = 0; i * dim < p.size(); ++i)
        if (s.inside(&p[i * dim])) ++f.count;
    f.volume = double(f.count) * l.pointVolume();
    return f;
}

}  // namespace mfdyn::test
