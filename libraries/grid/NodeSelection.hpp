#pragma once
// The nodes of a CartesianGrid that a grid boundary condition acts on, read from the
// condition's own dictionary with the geometric keywords of the particle selections
// (boundaryConditions/Selection.hpp) plus two grid-native ones, as cb-geo MPM and karamelo users
// pick nodes:
//
//     faces (xMin yMax);                              nodes on these faces of the grid box
//     plane { point (0 0 0); normal (0 1 0); }        nodes on the plane or behind it
//     shape { type box; min (0 0 0); max (1 0.1 1); } nodes inside the shape (Shape::New)
//     all   yes;                                      every node
//
// `faces` is exact: a node lies on xMin when its index i is 0 and on xMax when i = cells[0], with
// no floating-point compare, so the corners belong to every face they touch. A plane's normal
// points into the material (the side that stays free), as the particle planes' do: selected are
// the nodes with (x - point).n <= 1e-9 of the smallest cell, so a plane through a node layer
// takes that layer whatever the round-off of the node positions. Two or more of faces, plane and
// shape select the nodes that satisfy all of them (the part of a face inside a box); `all yes`
// stands alone. Nothing given is an error, not an empty selection: a forgotten `faces` would
// otherwise give a run in which the wall does nothing.
//
// The selection is resolved once, at construction, to a sorted list of node indices (the grid's
// geometry never changes during a run).
#include "core/Dictionary.hpp"
#include "core/KeywordSchema.hpp"
#include "core/Tensor.hpp"
#include "grid/CartesianGrid.hpp"

#include <array>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace mfdyn {

class Shape;

// One face of the grid box: `axis` 0, 1, 2 (x, y, z) and `upper` (xMax) or not (xMin).
struct GridFace {
    int axis = 0;
    bool upper = false;

    // "xMin", "yMax", ...
    std::string name() const;
    // The face called `name` in a `dim`-dimensional grid, or nullopt (zMin in 2D is none).
    static std::optional<GridFace> fromName(const std::string& name, int dim);
    // The valid names in `dim` dimensions: "xMin xMax yMin yMax" in 2D.
    static std::vector<std::string> names(int dim);
    // The unit normal pointing into the grid (the material side): +e_axis on a lower face,
    // -e_axis on an upper one.
    template <int Dim>
    Vector<Dim> inwardNormal() const {
        Vector<Dim> n = Vector<Dim>::Zero();
        n[axis] = upper ? -1.0 : 1.0;
        return n;
    }
    bool operator==(const GridFace&) const = default;
};

// The selection keywords (faces, plane, shape, all), appended to every grid boundary condition's
// schema (gridBoundaryConditions/GridBoundaryCondition.hpp).
KeywordSchema nodeSelectionKeywords();
// The schema of a `plane { point (...); normal (...); }` sub-dictionary.
KeywordSchema nodeSelectionPlaneKeywords();

template <int Dim>
class NodeSelection {
public:
    using Index = typename CartesianGrid<Dim>::Index;

    // From values read through a schema that includes nodeSelectionKeywords().
    NodeSelection(const KeywordValues& values, const CartesianGrid<Dim>& grid);
    // Reads `dict` through nodeSelectionKeywords() alone.
    NodeSelection(const Dictionary& dict, const CartesianGrid<Dim>& grid);
    NodeSelection(NodeSelection&&) noexcept;
    NodeSelection& operator=(NodeSelection&&) noexcept;
    ~NodeSelection();

    // Node indices, ascending, each once.
    const std::vector<Index>& nodes() const { return nodes_; }
    std::size_t size() const { return nodes_.size(); }
    bool selectsAll() const { return all_; }
    // The faces given with `faces (...)`, in the order written (empty when not given).
    const std::vector<GridFace>& faces() const { return faces_; }
    // Whether `node` lies on `face` (by its indices, exactly).
    static bool onFace(const CartesianGrid<Dim>& grid, Index node, const GridFace& face);

    // "faces (xMin yMax)", "plane", "shape box", "all nodes", joined with " and ": for the log.
    std::string describe() const;

private:
    bool all_ = false;
    std::vector<GridFace> faces_;
    bool hasPlane_ = false;
    Vector<Dim> planePoint_ = Vector<Dim>::Zero(), planeNormal_ = Vector<Dim>::Zero();
    std::unique_ptr<Shape> shape_;
    std::string shapeType_;
    std::vector<Index> nodes_;
};

extern template class NodeSelection<1>;
extern template class NodeSelection<2>;
extern template class NodeSelection<3>;

}  // namespace mfdyn
