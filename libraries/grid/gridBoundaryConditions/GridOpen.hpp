#pragma once
// `open`: nothing; the nodes of an open boundary are free. It exists so that a case can say so
// (and a particle leaving the grid there is the solver's business, issue 17 item 8), and so that
// a condition can be switched off by changing its type only.
#include "grid/gridBoundaryConditions/GridBoundaryCondition.hpp"

namespace mfdyn {

template <int Dim>
class GridOpen : public GridBoundaryCondition<Dim> {
public:
    GridOpen(const Dictionary& dict, const CartesianGrid<Dim>& grid);
    static KeywordSchema keywords();
    void apply(const CartesianGrid<Dim>&, std::vector<Vector<Dim>>&, std::vector<Vector<Dim>>*, double,
               double) const override {}

private:
    GridOpen(const KeywordValues& values, const CartesianGrid<Dim>& grid);
};

}  // namespace mfdyn
