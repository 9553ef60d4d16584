#pragma once
// `friction`: an axis-aligned rigid wall with Coulomb friction, coefficient mu (the rigid-wall
// case of Bardenhagen, Brackbill & Sulsky 2000's frictional contact). At a selected node with
// inward wall normal n, when the node moves into the wall (v.n < 0):
//
//     dv_n = -(v.n)                       the normal velocity removed (> 0), as slip removes it
//     v_t  = v - (v.n) n                  the tangential velocity
//     v   <- v_t max(0, 1 - mu dv_n/|v_t|)   slowed by mu dv_n, never reversed (stick when
//                                            |v_t| <= mu dv_n)
//     a   <- a - (a.n) n - (v_t - v_new)/dt  normal rate removed (as slip), the friction's
//                                            deceleration added
//
// A node moving away from the wall, or along it (v.n >= 0), is free: the wall does not hold the
// material. `normal` or the faces of the selection as for slip; a node on two walls (a corner)
// is treated for each in turn, in the order of the faces. mu = 0 is slip while in contact.
#include "grid/gridBoundaryConditions/GridBoundaryCondition.hpp"

namespace mfdyn {

template <int Dim>
class GridFriction : public GridBoundaryCondition<Dim> {
public:
    using typename GridBoundaryCondition<Dim>::WallNormal;
    GridFriction(const Dictionary& dict, const CartesianGrid<Dim>& grid);
    static KeywordSchema keywords();
    void apply(const CartesianGrid<Dim>& grid, std::vector<Vector<Dim>>& velocity,
               std::vector<Vector<Dim>>* acceleration, double t, double dt) const override;
    std::string describe() const override;

    double mu() const { return mu_; }

private:
    GridFriction(const KeywordValues& values, const CartesianGrid<Dim>& grid);
    double mu_ = 0.0;
    std::vector<std::vector<WallNormal>> walls_;  // per selected node
    std::string normalText_;
};

}  // namespace mfdyn
