// box: the closed axis-aligned box min <= x <= max. Volume Π (max_d - min_d).
// Closed, so that a lattice with nodes on the faces (nodal, doc/methods/tl-jst-sph.md 2.1) keeps them and
// a selection box drawn up to a face takes the particles on it. Two regions whose boxes share a
// face both contain a point on it: with `override yes` (the default) the later region takes it;
// the cell-centred lattices (cubic) put no point on a face whose box is a whole number of cells.
#include "geometry/Box.hpp"

namespace mfdyn {

Box::Box(const Dictionary& dict, int dimension) : Shape(dict, dimension) {
    box_.min = readPoint(dict, "min");
    box_.max = readPoint(dict, "max");
    for (int d = 0; d < dimension; ++d)
        if (!(box_.max[d] > box_.min[d]))
            throw dict.error(
                "max", "max must exceed min in every direction (direction " + std::to_string(d + 1) + ")");
    checkBounds(dict, "max");
}

bool Box::inside(const double* x) const {
    for (int d = 0; d < dimension(); ++d)
        if (x[d] < box_.min[d] || x[d] > box_.max[d]) return false;
    return true;
}

std::optional<double> Box::volume() const {
    double v = 1;
    for (int d = 0; d < dimension(); ++d) v *= box_.max[d] - box_.min[d];
    return v;
}

MFDYN_REGISTER(Shape, Box, "box", "axis-aligned box between min and max");

}  // namespace mfdyn
