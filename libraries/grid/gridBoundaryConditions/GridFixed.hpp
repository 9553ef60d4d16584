#pragma once
// `fixed`: the selected nodes do not move, v = a = 0 (a clamped edge, the anchor of a hanging
// block); with `components (y)`, only those components (the thesis's spring and truss fix v_y
// on the top nodes and leave v_x free).
#include "grid/gridBoundaryConditions/GridBoundaryCondition.hpp"

namespace mfdyn {

template <int Dim>
class GridFixed : public GridBoundaryCondition<Dim> {
public:
    GridFixed(const Dictionary& dict, const CartesianGrid<Dim>& grid);
    static KeywordSchema keywords();
    void apply(const CartesianGrid<Dim>& grid, std::vector<Vector<Dim>>& velocity,
               std::vector<Vector<Dim>>* acceleration, double t, double dt) const override;
    std::string describe() const override;

private:
    GridFixed(const KeywordValues& values, const CartesianGrid<Dim>& grid);
    std::vector<bool> components_;
};

}  // namespace mfdyn
