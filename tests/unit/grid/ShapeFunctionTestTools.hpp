#pragma once
// Helpers of the shape-function tests: a type built through New as a user writes it, a grid with
// a different cell size per axis (so that a swapped axis or a missing 1/h shows), and a
// particle's entries as a node -> (N, grad N) map.
#include "core/Dictionary.hpp"
#include "grid/CartesianGrid.hpp"
#include "grid/shapeFunctions/ShapeFunction.hpp"

#include <map>
#include <memory>
#include <string>
#include <utility>

namespace mfdyn::test {

template <int Dim>
std::unique_ptr<ShapeFunction<Dim>> makeShapeFunction(const std::string& type) {
    const Dictionary dict = Dictionary::parse("shapeFunction { type " + type + "; }", "mpmProperties");
    return ShapeFunction<Dim>::New(dict.subDict("shapeFunction"));
}

// Origin off zero, cells of 0.1, 0.07, 0.13 m, 6 x 5 x 4 cells (enough for every type's fold).
template <int Dim>
CartesianGrid<Dim> testGrid() {
    const double origin[] = {-0.3, 1.1, 0.2}, size[] = {0.1, 0.07, 0.13};
    const std::int64_t cells[] = {6, 5, 4};
    Vector<Dim> o, h;
    typename CartesianGrid<Dim>::Ijk n;
    for (int d = 0; d < Dim; ++d) {
        o[d] = origin[d];
        h[d] = size[d];
        n[d] = cells[d];
    }
    return CartesianGrid<Dim>(o, h, n);
}

template <int Dim>
struct Entry {
    double weight = 0.0;
    Vector<Dim> gradient = Vector<Dim>::Zero();
};

template <int Dim>
std::map<std::int64_t, Entry<Dim>> entriesOf(const ParticleNodeList<Dim>& list, std::size_t p) {
    std::map<std::int64_t, Entry<Dim>> out;
    for (std::size_t e = p * list.stride; e < p * list.stride + list.count[p]; ++e)
        out[list.node[e]] = Entry<Dim>{list.weight[e], list.gradient[e]};
    return out;
}

}  // namespace mfdyn::test
