#include "grid/CartesianGrid.hpp"

#include "core/Error.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

#include <unistd.h>

namespace mfdyn {

namespace {

// A bound on the node count: far above any grid that fits in memory (a velocity field of 2^40
// nodes is 24 TB), low enough that the index arithmetic never overflows an int64.
constexpr double maxNodes = 1099511627776.0;  // 2^40

// The machine's physical memory, or 0 where the system does not say.
double physicalMemoryBytes() {
    const long pages = ::sysconf(_SC_PHYS_PAGES), pageSize = ::sysconf(_SC_PAGESIZE);
    return pages > 0 && pageSize > 0 ? double(pages) * double(pageSize) : 0.0;
}

std::string axisWord(int dim) {
    return std::to_string(dim) + "D";
}

KeywordSchema boxKeywords() {
    return KeywordSchema("grid", "box")
        .vector("min", "m", "the lower corner of the box the grid covers")
        .vector("max", "m", "the upper corner (each component above min's)");
}

// One value per axis: exactly Dim numbers (a 2D grid has two cell counts and two sizes; a third
// would be a 3D grid's, so it is refused rather than ignored). `scalarAllowed`: a single number
// stands for every axis.
template <int Dim>
std::array<double, Dim> perAxis(const Dictionary& dict, const std::string& key, bool scalarAllowed,
                                const std::string& what) {
    const Entry& e = dict.entry(key);
    std::array<double, Dim> out{};
    if (scalarAllowed && e.tokens.size() == 1 && e.tokens[0].isNumber()) {
        out.fill(e.tokens[0].number());
        return out;
    }
    const auto values = dict.get<std::vector<double>>(key);
    if (values.size() != std::size_t(Dim))
        throw dict.error(key, "expected " + std::to_string(Dim) + " values (" + what +
                                  ", one per axis of the " + axisWord(Dim) + " grid" +
                                  (scalarAllowed ? ", or one value for all axes" : "") + "), found " +
                                  std::to_string(values.size()));
    std::copy(values.begin(), values.end(), out.begin());
    return out;
}

template <int Dim>
Vector<Dim> toVector(const std::array<double, Dim>& a) {
    Vector<Dim> v;
    for (int d = 0; d < Dim; ++d) v[d] = a[d];
    return v;
}

std::string vectorText(const double* x, int n) {
    std::string s = "(";
    for (int d = 0; d < n; ++d) s += (d ? " " : "") + formatKeywordNumber(x[d]);
    return s + ")";
}

}  // namespace

template <int Dim>
CartesianGrid<Dim>::CartesianGrid(const Vector<Dim>& origin, const Vector<Dim>& cellSize, const Ijk& cells)
    : origin_(origin), cellSize_(cellSize), cells_(cells), nodeCount_(0), nodes_(Dim, 0) {
    double nodes = 1.0;
    for (int d = 0; d < Dim; ++d) {
        if (!std::isfinite(origin[d])) throw Error("grid: the origin has a non-finite component");
        if (!(cellSize[d] > 0.0) || !std::isfinite(cellSize[d]))
            throw Error("grid: the cell size along axis " + std::to_string(d) + " is " +
                        formatKeywordNumber(cellSize[d]) + "; it must be positive and finite");
        if (cells[d] < 1)
            throw Error("grid: " + std::to_string(cells[d]) + " cells along axis " + std::to_string(d) +
                        "; there must be at least 1");
        if (!std::isfinite(origin[d] + double(cells[d]) * cellSize[d]))
            throw Error("grid: the upper corner along axis " + std::to_string(d) + " is not finite");
        nodes *= double(cells[d] + 1);
    }
    if (nodes > maxNodes)
        throw Error("grid: " + formatKeywordNumber(nodes) + " nodes, more than the 2^40 a grid may have");
    nodeCount_ = std::size_t(nodes);
    nodes_.resize(nodeCount_);
}

template <int Dim>
KeywordSchema CartesianGrid<Dim>::keywords() {
    return KeywordSchema("grid", "cartesian")
        .vector("origin", "m", "the lower corner of the grid (with cells and cellSize)")
        .optional()
        .table("cellSize", "m",
               "the cell size: one value for every axis, or one per axis (dx dy dz); with box, the "
               "size is then adjusted so that a whole number of cells fits the box")
        .optional()
        .example("(0.05 0.05 0.05)")
        .vector("cells", "-", "the number of cells per axis, each at least 1 (with origin, or with box)")
        .optional()
        .dictionary("box", "min and max of the box the grid covers (instead of origin)")
        .optional()
        .nested(&boxKeywords);
}

template <int Dim>
CartesianGrid<Dim> CartesianGrid<Dim>::fromDictionary(const Dictionary& dict) {
    const KeywordValues v = keywords().read(dict);
    const bool hasBox = v.given("box"), hasOrigin = v.given("origin");
    const bool hasSize = v.given("cellSize"), hasCells = v.given("cells");
    if (hasBox && hasOrigin)
        throw v.error("origin",
                      "give either `origin` (with cells and cellSize) or `box { min; max; }`, not both");
    if (!hasBox && !hasOrigin)
        throw InputError(dict.where(), dict.scope(),
                         "the grid needs `origin (...); cellSize ...; cells (...);` or `box { min (...); max "
                         "(...); } cellSize ...;`");

    std::array<double, Dim> size{};
    if (hasSize) {
        size = perAxis<Dim>(dict, "cellSize", true, "cell sizes");
        for (int d = 0; d < Dim; ++d)
            if (!(size[d] > 0.0) || !std::isfinite(size[d]))
                throw v.error("cellSize",
                              "expected a cell size > 0 (m), found " + formatKeywordNumber(size[d]));
    }
    Ijk cells{};
    if (hasCells) {
        const auto counts = perAxis<Dim>(dict, "cells", false, "cell counts");
        for (int d = 0; d < Dim; ++d) {
            if (counts[d] != std::floor(counts[d]) || counts[d] < 1.0 || counts[d] > maxNodes)
                throw v.error("cells", "expected whole numbers of cells, each at least 1, found " +
                                           formatKeywordNumber(counts[d]));
            cells[d] = Index(counts[d]);
        }
    }

    Vector<Dim> origin, cellSize;
    if (hasOrigin) {
        if (!hasSize || !hasCells)
            throw InputError(dict.where(), dict.scope(),
                             std::string("a grid given by its origin needs `") +
                                 (hasSize ? "cells" : "cellSize") + "` too (origin, cellSize and cells)");
        origin = dict.get<Vector<Dim>>("origin");
        cellSize = toVector<Dim>(size);
    } else {
        if (hasSize == hasCells)
            throw v.error("box",
                          "with `box`, give one of `cellSize` (the number of cells follows) or `cells` (the "
                          "size follows), not " +
                              std::string(hasSize ? "both" : "neither"));
        const Dictionary& box = v.dictionary("box");
        const Vector<Dim> lo = box.get<Vector<Dim>>("min"), hi = box.get<Vector<Dim>>("max");
        for (int d = 0; d < Dim; ++d)
            if (!(hi[d] > lo[d]) || !std::isfinite(hi[d] - lo[d]))
                throw box.error("max", "expected max > min along every axis, found " +
                                           formatKeywordNumber(hi[d]) + " <= " + formatKeywordNumber(lo[d]) +
                                           " along axis " + std::to_string(d));
        origin = lo;
        for (int d = 0; d < Dim; ++d) {
            const double length = hi[d] - lo[d];
            if (hasSize) {
                // The nearest whole number of cells, at least one; the size then fits the box exactly.
                const double n = std::max(1.0, std::round(length / size[d]));
                if (n > maxNodes)
                    throw v.error("cellSize", "a cell size of " + formatKeywordNumber(size[d]) + " m gives " +
                                                  formatKeywordNumber(n) + " cells along axis " +
                                                  std::to_string(d) + ", too many");
                cells[d] = Index(n);
            }
            cellSize[d] = length / double(cells[d]);
        }
    }
    // What the checks above cannot see (a node count above the limit, an upper corner that
    // overflows) is the constructor's Error, located here at the grid dictionary.
    std::optional<CartesianGrid> grid;
    try {
        grid.emplace(origin, cellSize, cells);
    } catch (const Error& e) {
        throw InputError(dict.where(), dict.scope(), e.what());
    }
    // A cell size typed a factor of ten too small in 3D asks for a thousand times the nodes: say
    // so here, at the entry, rather than as an allocation failure when the first node field is
    // made. The least a grid method stores per node is a mass, a momentum, a velocity and a force.
    const double bytes = double(grid->nodeCount()) * double(1 + 3 * Dim) * 8.0;
    const double memory = physicalMemoryBytes();
    if (memory > 0.0 && bytes > memory)
        throw v.error(hasSize ? "cellSize" : "cells", "the grid has " + std::to_string(grid->nodeCount()) +
                                                          " nodes, whose mass, momentum, velocity "
                                                          "and force alone need " +
                                                          formatKeywordNumber(std::round(bytes / 1e9)) +
                                                          " GB, more than the " +
                                                          formatKeywordNumber(std::round(memory / 1e9)) +
                                                          " GB of memory of this machine: a larger cell "
                                                          "size, or fewer cells?");
    return std::move(*grid);
}

template <int Dim>
double CartesianGrid<Dim>::smallestCellSize() const {
    return cellSize_.minCoeff();
}

template <int Dim>
typename CartesianGrid<Dim>::Ijk CartesianGrid<Dim>::nodesPerAxis() const {
    Ijk n;
    for (int d = 0; d < Dim; ++d) n[d] = cells_[d] + 1;
    return n;
}

template <int Dim>
Vector<Dim> CartesianGrid<Dim>::upperCorner() const {
    Vector<Dim> x;
    for (int d = 0; d < Dim; ++d) x[d] = origin_[d] + double(cells_[d]) * cellSize_[d];
    return x;
}

template <int Dim>
std::size_t CartesianGrid<Dim>::cellCount() const {
    std::size_t n = 1;
    for (int d = 0; d < Dim; ++d) n *= std::size_t(cells_[d]);
    return n;
}

template <int Dim>
typename CartesianGrid<Dim>::Index CartesianGrid<Dim>::nodeIndex(const Ijk& ijk) const {
    Index index = 0;
    for (int d = Dim - 1; d >= 0; --d) index = index * (cells_[d] + 1) + ijk[d];
    return index;
}

template <int Dim>
typename CartesianGrid<Dim>::Ijk CartesianGrid<Dim>::nodeIjk(Index node) const {
    Ijk ijk;
    for (int d = 0; d < Dim; ++d) {
        ijk[d] = node % (cells_[d] + 1);
        node /= (cells_[d] + 1);
    }
    return ijk;
}

template <int Dim>
Vector<Dim> CartesianGrid<Dim>::nodePosition(const Ijk& ijk) const {
    Vector<Dim> x;
    for (int d = 0; d < Dim; ++d) x[d] = origin_[d] + double(ijk[d]) * cellSize_[d];
    return x;
}

template <int Dim>
Vector<Dim> CartesianGrid<Dim>::nodePosition(Index node) const {
    return nodePosition(nodeIjk(node));
}

template <int Dim>
bool CartesianGrid<Dim>::contains(const Vector<Dim>& x) const {
    for (int d = 0; d < Dim; ++d) {
        const double u = (x[d] - origin_[d]) / cellSize_[d];
        // Also false for NaN.
        if (!(u >= -1e-12 && u <= double(cells_[d]) + 1e-12)) return false;
    }
    return true;
}

template <int Dim>
typename CartesianGrid<Dim>::Ijk CartesianGrid<Dim>::cellOf(const Vector<Dim>& x) const {
    Ijk ijk;
    for (int d = 0; d < Dim; ++d) {
        const double u = std::floor((x[d] - origin_[d]) / cellSize_[d]);
        // Clamped in double first: a far-away (or NaN) coordinate must not overflow the cast.
        const double clamped = u >= 0.0 ? std::min(u, double(cells_[d] - 1)) : 0.0;
        ijk[d] = Index(clamped);
    }
    return ijk;
}

template <int Dim>
Vector<Dim> CartesianGrid<Dim>::cellCoordinates(const Vector<Dim>& x) const {
    return ((x - origin_).array() / cellSize_.array()).matrix();
}

template <int Dim>
std::string CartesianGrid<Dim>::describe() const {
    std::string s = "grid: ";
    for (int d = 0; d < Dim; ++d) s += (d ? " x " : "") + std::to_string(cells_[d]);
    s += " cells of ";
    for (int d = 0; d < Dim; ++d) s += (d ? " x " : "") + formatKeywordNumber(cellSize_[d]);
    s += " m from " + vectorText(origin_.data(), Dim) + ", " + std::to_string(nodeCount_) + " nodes";
    return s;
}

template class CartesianGrid<1>;
template class CartesianGrid<2>;
template class CartesianGrid<3>;

}  // namespace mfdyn
