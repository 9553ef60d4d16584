// `fixed`: v = a = 0 on the selected nodes (GridFixed.hpp). Setting the acceleration too keeps a
// FLIP update, which adds a_I dt to the particles, from moving material that the positions'
// update (from v_I) holds still.
#include "grid/gridBoundaryConditions/GridFixed.hpp"

namespace mfdyn {

template <int Dim>
KeywordSchema GridFixed<Dim>::keywords() {
    return KeywordSchema("gridBoundaryCondition", "fixed")
        .append(componentKeywords())
        .append(commonGridBoundaryConditionKeywords());
}

template <int Dim>
GridFixed<Dim>::GridFixed(const Dictionary& dict, const CartesianGrid<Dim>& grid)
    : GridFixed(keywords().read(dict), grid) {}

template <int Dim>
GridFixed<Dim>::GridFixed(const KeywordValues& values, const CartesianGrid<Dim>& grid)
    : GridBoundaryCondition<Dim>(values, grid), components_(readComponents(values, Dim)) {}

template <int Dim>
void GridFixed<Dim>::apply(const CartesianGrid<Dim>&, std::vector<Vector<Dim>>& velocity,
                           std::vector<Vector<Dim>>* acceleration, double, double) const {
    for (const auto node : this->selection().nodes())
        for (int d = 0; d < Dim; ++d)
            if (components_[d]) {
                velocity[node][d] = 0.0;
                if (acceleration) (*acceleration)[node][d] = 0.0;
            }
}

template <int Dim>
std::string GridFixed<Dim>::describe() const {
    const std::string components = componentsText(components_);
    return GridBoundaryCondition<Dim>::describe() + (components.empty() ? "" : ", " + components);
}

MFDYN_REGISTER_DIM(GridBoundaryCondition, GridFixed, "fixed",
                   "the selected grid nodes do not move: v = a = 0");

}  // namespace mfdyn
