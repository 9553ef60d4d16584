// `slip`: a frictionless axis-aligned wall (GridSlip.hpp): at each selected node, for each wall
// it lies on, v_n = a_n = 0 with n the wall's axis; the tangential components are untouched.
// Being axis-aligned, the normal component is one array entry set to exactly zero.
#include "grid/gridBoundaryConditions/GridSlip.hpp"

namespace mfdyn {

template <int Dim>
KeywordSchema GridSlip<Dim>::keywords() {
    return KeywordSchema("gridBoundaryCondition", "slip")
        .append(wallNormalKeywords())
        .append(commonGridBoundaryConditionKeywords());
}

template <int Dim>
GridSlip<Dim>::GridSlip(const Dictionary& dict, const CartesianGrid<Dim>& grid)
    : GridSlip(keywords().read(dict), grid) {}

template <int Dim>
GridSlip<Dim>::GridSlip(const KeywordValues& values, const CartesianGrid<Dim>& grid)
    : GridBoundaryCondition<Dim>(values, grid),
      walls_(this->wallNormals(values, grid)),
      normalText_(this->normalText(values)) {}

template <int Dim>
void GridSlip<Dim>::apply(const CartesianGrid<Dim>&, std::vector<Vector<Dim>>& velocity,
                          std::vector<Vector<Dim>>* acceleration, double, double) const {
    const auto& nodes = this->selection().nodes();
    for (std::size_t k = 0; k < nodes.size(); ++k)
        for (const WallNormal& wall : walls_[k]) {
            velocity[nodes[k]][wall.axis] = 0.0;
            if (acceleration) (*acceleration)[nodes[k]][wall.axis] = 0.0;
        }
}

template <int Dim>
std::string GridSlip<Dim>::describe() const {
    return GridBoundaryCondition<Dim>::describe() + ", " + normalText_;
}

MFDYN_REGISTER_DIM(GridBoundaryCondition, GridSlip, "slip",
                   "frictionless axis-aligned wall: the wall-normal component of v and a is zero");

}  // namespace mfdyn
