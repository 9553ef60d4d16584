#pragma once
// `slip`: a frictionless axis-aligned wall. The wall-normal component of v and a is zero at
// every selected node, whichever way the node moves (the wall holds the material on both sides
// of the step: no separation, as cb-geo MPM's velocity constraints); the tangential components
// are left as they are. `normal (0 1 0)` or, without it, the normal of each face of the
// selection the node lies on (GridBoundaryCondition.hpp).
#include "grid/gridBoundaryConditions/GridBoundaryCondition.hpp"

namespace mfdyn {

template <int Dim>
class GridSlip : public GridBoundaryCondition<Dim> {
public:
    using typename GridBoundaryCondition<Dim>::WallNormal;
    GridSlip(const Dictionary& dict, const CartesianGrid<Dim>& grid);
    static KeywordSchema keywords();
    void apply(const CartesianGrid<Dim>& grid, std::vector<Vector<Dim>>& velocity,
               std::vector<Vector<Dim>>* acceleration, double t, double dt) const override;
    std::string describe() const override;

private:
    GridSlip(const KeywordValues& values, const CartesianGrid<Dim>& grid);
    std::vector<std::vector<WallNormal>> walls_;  // per selected node
    std::string normalText_;
};

}  // namespace mfdyn
