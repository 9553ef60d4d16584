#include "geometry/Lattice.hpp"

namespace mfdyn {

Lattice::Lattice(const Dictionary& dict, int dimension)
    : dimension_(dimension), spacing_(dict.get<double>("spacing")) {
    if (!(spacing_ > 0)) throw dict.error("spacing", "spacing must be positive");
}

Lattice::~Lattice() = default;

}  // namespace mfdyn
