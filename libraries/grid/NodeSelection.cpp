#include "grid/NodeSelection.hpp"

#include "geometry/Shape.hpp"

#include <algorithm>
#include <cmath>

namespace mfdyn {

std::string GridFace::name() const {
    return std::string(1, char('x' + axis)) + (upper ? "Max" : "Min");
}

std::optional<GridFace> GridFace::fromName(const std::string& name, int dim) {
    for (int axis = 0; axis < dim; ++axis)
        for (bool upper : {false, true})
            if (GridFace{axis, upper}.name() == name) return GridFace{axis, upper};
    return std::nullopt;
}

std::vector<std::string> GridFace::names(int dim) {
    std::vector<std::string> out;
    for (int axis = 0; axis < dim; ++axis)
        for (bool upper : {false, true}) out.push_back(GridFace{axis, upper}.name());
    return out;
}

KeywordSchema nodeSelectionPlaneKeywords() {
    return KeywordSchema("gridBoundaryCondition", "plane")
        .vector("point", "m", "a point of the plane")
        .vector("normal", "-", "the plane's normal, pointing into the material (normalised when read)")
        .example("(0 1 0)");
}

KeywordSchema nodeSelectionKeywords() {
    return KeywordSchema("gridBoundaryCondition", "nodeSelection")
        .words("faces", "the nodes on these faces of the grid box (xMin xMax yMin yMax zMin zMax), exactly")
        .optional()
        .dictionary("plane",
                    "the nodes on the plane `point (...); normal (...);` or behind it (the normal "
                    "points into the material)")
        .optional()
        .nested(&nodeSelectionPlaneKeywords)
        .dictionary("shape", "the nodes inside this shape (geometry/Shape.hpp)")
        .optional()
        .flag("all", "every node (instead of faces, plane and shape)")
        .optional();
}

namespace {

template <int Dim>
Vector<Dim> readVector(const Dictionary& dict, const std::string& key) {
    return dict.get<Vector<Dim>>(key);
}

std::string joined(const std::vector<std::string>& names) {
    std::string s;
    for (const auto& n : names) s += (s.empty() ? "" : " ") + n;
    return s;
}

}  // namespace

template <int Dim>
NodeSelection<Dim>::NodeSelection(const Dictionary& dict, const CartesianGrid<Dim>& grid)
    : NodeSelection(nodeSelectionKeywords().read(dict), grid) {}

template <int Dim>
NodeSelection<Dim>::NodeSelection(const KeywordValues& values, const CartesianGrid<Dim>& grid) {
    const bool hasFaces = values.given("faces"), hasPlane = values.given("plane"),
               hasShape = values.given("shape"), allGiven = values.given("all");
    all_ = allGiven && values.flag("all");
    if (all_ && (hasFaces || hasPlane || hasShape))
        throw values.error("all",
                           "`all yes` selects every node; remove `faces`, `plane` and `shape`, or `all`");
    if (!all_ && !hasFaces && !hasPlane && !hasShape)
        throw InputError(
            values.dict().where(), values.dict().scope(),
            std::string(allGiven ? "`all no` and nothing else: " : "") +
                "no grid nodes selected: give `faces (" + joined(GridFace::names(Dim)) +
                ");`, `plane { point (...); normal (...); }`, `shape { type ...; }` or `all yes;`");

    if (hasFaces) {
        for (const auto& name : values.words("faces")) {
            const auto face = GridFace::fromName(name, Dim);
            if (!face) {
                const auto valid = GridFace::names(Dim);
                std::string message = "unknown face '" + name + "' of a " + std::to_string(Dim) + "D grid";
                const std::string guess = closestMatch(name, valid);
                if (!guess.empty()) message += "; did you mean '" + guess + "'?";
                throw values.error("faces", message + " Valid faces: " + joined(valid));
            }
            if (std::find(faces_.begin(), faces_.end(), *face) == faces_.end()) faces_.push_back(*face);
        }
    }
    if (hasPlane) {
        const Dictionary& plane = values.dictionary("plane");
        planePoint_ = readVector<Dim>(plane, "point");
        planeNormal_ = readVector<Dim>(plane, "normal");
        const double length = planeNormal_.norm();
        if (!(length > 0.0) || !std::isfinite(length))
            throw plane.error("normal", "the normal must be a non-zero vector (it is normalised)");
        planeNormal_ /= length;
        hasPlane_ = true;
    }
    if (hasShape) {
        const Dictionary& shapeDict = values.dictionary("shape");
        shape_ = Shape::New(shapeDict, Dim);
        shapeType_ = shapeDict.get<std::string>("type");
    }

    // A node on the plane has its position computed with round-off (origin + i dx): 1e-9 of the
    // smallest cell is far above that error and far below the spacing of the node layers.
    const double tolerance = 1e-9 * grid.smallestCellSize();
    const Index n = Index(grid.nodeCount());
    for (Index node = 0; node < n; ++node) {
        if (!all_) {
            if (!faces_.empty() && std::none_of(faces_.begin(), faces_.end(),
                                                [&](const GridFace& f) { return onFace(grid, node, f); }))
                continue;
            if (hasPlane_ || shape_) {
                const Vector<Dim> x = grid.nodePosition(node);
                if (hasPlane_ && (x - planePoint_).dot(planeNormal_) > tolerance) continue;
                if (shape_ && !shape_->inside(x.data())) continue;
            }
        }
        nodes_.push_back(node);
    }
}

template <int Dim>
NodeSelection<Dim>::NodeSelection(NodeSelection&&) noexcept = default;
template <int Dim>
NodeSelection<Dim>& NodeSelection<Dim>::operator=(NodeSelection&&) noexcept = default;
template <int Dim>
NodeSelection<Dim>::~NodeSelection() = default;

template <int Dim>
bool NodeSelection<Dim>::onFace(const CartesianGrid<Dim>& grid, Index node, const GridFace& face) {
    const auto ijk = grid.nodeIjk(node);
    return ijk[face.axis] == (face.upper ? grid.cells()[face.axis] : 0);
}

template <int Dim>
std::string NodeSelection<Dim>::describe() const {
    if (all_) return "all nodes";
    std::vector<std::string> parts;
    if (!faces_.empty()) {
        std::vector<std::string> names;
        for (const auto& f : faces_) names.push_back(f.name());
        parts.push_back("faces (" + joined(names) + ")");
    }
    if (hasPlane_) parts.push_back("plane");
    if (shape_) parts.push_back("shape " + shapeType_);
    std::string s;
    for (const auto& p : parts) s += (s.empty() ? "" : " and ") + p;
    return s;
}

template class NodeSelection<1>;
template class NodeSelection<2>;
template class NodeSelection<3>;

}  // namespace mfdyn
