#include "grid/gridBoundaryConditions/GridBoundaryCondition.hpp"

#include <algorithm>
#include <cmath>

namespace mfdyn {

namespace {

// The last component of "gridBoundaryConditions/floor".
std::string lastScope(const std::string& scope) {
    const auto slash = scope.find_last_of('/');
    return slash == std::string::npos ? scope : scope.substr(slash + 1);
}

}  // namespace

KeywordSchema commonGridBoundaryConditionKeywords() {
    return KeywordSchema("gridBoundaryCondition", "common").append(nodeSelectionKeywords());
}

KeywordSchema wallNormalKeywords() {
    return KeywordSchema("gridBoundaryCondition", "wallNormal")
        .vector("normal", "-",
                "the wall's normal, along one axis, pointing into the material (default: the normal "
                "of each face of `faces` a node lies on)")
        .optional()
        .example("(0 1 0)");
}

KeywordSchema componentKeywords() {
    return KeywordSchema("gridBoundaryCondition", "components")
        .words("components", "the velocity components set, by axis name (x y z); default: all")
        .optional();
}

std::vector<bool> readComponents(const KeywordValues& values, int dim) {
    std::vector<bool> set(std::size_t(dim), !values.given("components"));
    if (!values.given("components")) return set;
    std::vector<std::string> valid;
    for (int d = 0; d < dim; ++d) valid.emplace_back(1, char('x' + d));
    for (const auto& name : values.words("components")) {
        const auto it = std::find(valid.begin(), valid.end(), name);
        if (it == valid.end()) {
            std::string list;
            for (const auto& v : valid) list += (list.empty() ? "" : " ") + v;
            throw values.error("components", "unknown component '" + name + "' of a " + std::to_string(dim) +
                                                 "D grid; valid components: " + list);
        }
        set[std::size_t(it - valid.begin())] = true;
    }
    return set;
}

std::string componentsText(const std::vector<bool>& set) {
    if (std::all_of(set.begin(), set.end(), [](bool b) { return b; })) return "";
    std::string s;
    for (std::size_t d = 0; d < set.size(); ++d)
        if (set[d]) s += (s.empty() ? "" : " ") + std::string(1, char('x' + d));
    return "components (" + s + ")";
}

template <int Dim>
GridBoundaryCondition<Dim>::GridBoundaryCondition(const KeywordValues& values, const CartesianGrid<Dim>& grid)
    : name_(lastScope(values.dict().scope())),
      type_(values.dict().get<std::string>("type")),
      selection_(values, grid) {}

template <int Dim>
GridBoundaryCondition<Dim>::~GridBoundaryCondition() = default;

template <int Dim>
std::string GridBoundaryCondition<Dim>::describe() const {
    return name_ + ": " + type_ + " on " + selection_.describe() + ", " + std::to_string(selection_.size()) +
           " nodes";
}

template <int Dim>
std::vector<std::vector<typename GridBoundaryCondition<Dim>::WallNormal>>
GridBoundaryCondition<Dim>::wallNormals(const KeywordValues& values, const CartesianGrid<Dim>& grid) const {
    const auto& nodes = selection_.nodes();
    std::vector<std::vector<WallNormal>> walls(nodes.size());
    if (values.given("normal")) {
        const Vector<Dim> n = values.dict().get<Vector<Dim>>("normal");
        int axis = -1, nonZero = 0;
        for (int d = 0; d < Dim; ++d)
            if (n[d] != 0.0) {
                axis = d;
                ++nonZero;
            }
        // Axis-aligned only: the wall's normal component is then one array component, removed
        // exactly, with no projection whose round-off would leave a normal velocity behind.
        if (nonZero != 1)
            throw values.error("normal",
                               "expected a normal along one axis of the grid (one non-zero component, "
                               "such as (0 1 0)); an inclined wall is not supported");
        const WallNormal wall{axis, n[axis] > 0.0 ? 1.0 : -1.0};
        for (auto& w : walls) w.assign(1, wall);
        return walls;
    }
    const auto& faces = selection_.faces();
    if (faces.empty())
        throw InputError(values.dict().where(), values.dict().scope(),
                         "a " + type_ +
                             " wall needs its normal: give `normal (...)` (along one axis, into the "
                             "material) or select its nodes with `faces (...)`");
    for (std::size_t k = 0; k < nodes.size(); ++k)
        for (const GridFace& f : faces)
            if (NodeSelection<Dim>::onFace(grid, nodes[k], f))
                walls[k].push_back(WallNormal{f.axis, f.upper ? -1.0 : 1.0});
    return walls;
}

template <int Dim>
std::string GridBoundaryCondition<Dim>::normalText(const KeywordValues& values) {
    if (!values.given("normal")) return "the faces' normals";
    std::string s = "normal (";
    const auto& n = values.vector("normal");
    for (std::size_t d = 0; d < n.size(); ++d) s += (d ? " " : "") + formatKeywordNumber(n[d]);
    return s + ")";
}

template <int Dim>
GridBoundaryConditionList<Dim>::GridBoundaryConditionList(const Dictionary& dict,
                                                          const CartesianGrid<Dim>& grid) {
    for (const auto& entry : dict.entries()) {
        if (!entry->isDict())
            throw dict.error(entry->key, "expected a grid boundary condition `" + entry->key +
                                             " { type ...; faces (...); }`, found a plain entry");
        entry->read = true;
        conditions_.push_back(GridBoundaryCondition<Dim>::New(*entry->dict, grid));
    }
}

template <int Dim>
void GridBoundaryConditionList<Dim>::apply(const CartesianGrid<Dim>& grid, std::vector<Vector<Dim>>& velocity,
                                           std::vector<Vector<Dim>>* acceleration, double t,
                                           double dt) const {
    for (const auto& c : conditions_) c->apply(grid, velocity, acceleration, t, dt);
}

template <int Dim>
std::vector<std::string> GridBoundaryConditionList<Dim>::describe() const {
    std::vector<std::string> lines;
    for (const auto& c : conditions_) lines.push_back(c->describe());
    return lines;
}

template class GridBoundaryCondition<1>;
template class GridBoundaryCondition<2>;
template class GridBoundaryCondition<3>;
template class GridBoundaryConditionList<1>;
template class GridBoundaryConditionList<2>;
template class GridBoundaryConditionList<3>;

}  // namespace mfdyn
