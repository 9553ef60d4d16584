#pragma once
// `prescribedVelocity`: chosen components of the node velocity follow a given history, the
// others are free.
//
//   velocity (vx vy vz);                            constant [m/s], or
//   table ((t0 (vx vy vz)) (t1 (vx vy vz)) ...);    linear in t [s] between rows (times
//                                                   increasing), constant before the first and
//                                                   after the last
//   components (x y);                               the components prescribed (default: all)
//
// On a prescribed component v_i = v_i(t) and a_i = dv_i/dt (zero for a constant and outside the
// table, the slope of the row pair inside), t the time of the updated velocity.
#include "grid/gridBoundaryConditions/GridBoundaryCondition.hpp"

#include <array>
#include <vector>

namespace mfdyn {

template <int Dim>
class GridPrescribedVelocity : public GridBoundaryCondition<Dim> {
public:
    GridPrescribedVelocity(const Dictionary& dict, const CartesianGrid<Dim>& grid);
    static KeywordSchema keywords();
    void apply(const CartesianGrid<Dim>& grid, std::vector<Vector<Dim>>& velocity,
               std::vector<Vector<Dim>>* acceleration, double t, double dt) const override;
    std::string describe() const override;

    Vector<Dim> velocity(double t) const;
    Vector<Dim> acceleration(double t) const;
    // Whether component d is prescribed.
    bool prescribes(int d) const { return prescribed_[d]; }

private:
    GridPrescribedVelocity(const KeywordValues& values, const CartesianGrid<Dim>& grid);
    std::vector<double> times_;  // one entry for a constant
    std::vector<Vector<Dim>> values_;
    std::vector<bool> prescribed_;  // per axis
};

}  // namespace mfdyn
