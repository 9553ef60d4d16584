// `open`: the selected nodes are free (GridOpen.hpp).
#include "grid/gridBoundaryConditions/GridOpen.hpp"

namespace mfdyn {

template <int Dim>
KeywordSchema GridOpen<Dim>::keywords() {
    return KeywordSchema("gridBoundaryCondition", "open").append(commonGridBoundaryConditionKeywords());
}

template <int Dim>
GridOpen<Dim>::GridOpen(const Dictionary& dict, const CartesianGrid<Dim>& grid)
    : GridOpen(keywords().read(dict), grid) {}

template <int Dim>
GridOpen<Dim>::GridOpen(const KeywordValues& values, const CartesianGrid<Dim>& grid)
    : GridBoundaryCondition<Dim>(values, grid) {}

MFDYN_REGISTER_DIM(GridBoundaryCondition, GridOpen, "open",
                   "nothing: the selected grid nodes are free (an open boundary, said explicitly)");

}  // namespace mfdyn
