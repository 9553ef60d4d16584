// `friction`: an axis-aligned rigid wall with Coulomb friction, coefficient mu. At a selected
// node with inward wall normal n (into the material), when the node moves into the wall,
// v.n < 0:
//
//     dv_n = -(v.n)                           the normal velocity removed (> 0), as slip does
//     v_t  = v - (v.n) n                      the tangential velocity
//     v   <- v_t max(0, 1 - mu dv_n / |v_t|)  slowed by mu dv_n, never reversed
//     a   <- a - (a.n) n - (v_t - v_new)/dt   the normal rate removed, the friction's
//                                             deceleration added
//
// The wall's impulse per unit mass on the node is dv_n; Coulomb's law bounds the tangential
// impulse by mu dv_n, so the tangential velocity is brought towards zero by at most that much
// and a node with |v_t| <= mu dv_n sticks. A node with v.n >= 0 (leaving, or sliding along the
// wall) is left free. This is the frictional contact of Bardenhagen, Brackbill & Sulsky, "The
// material-point method for granular materials", Comput. Methods Appl. Mech. Engrg. 187 (2000),
// with the second body a rigid wall at rest. Limits: axis-aligned walls only; mu = 0 is slip
// while in contact; a corner node meets its walls one after the other, in the order of `faces`.
#include "grid/gridBoundaryConditions/GridFriction.hpp"

#include <algorithm>

namespace mfdyn {

template <int Dim>
KeywordSchema GridFriction<Dim>::keywords() {
    return KeywordSchema("gridBoundaryCondition", "friction")
        .scalar("mu", "-", "the Coulomb friction coefficient")
        .atLeast(0)
        .append(wallNormalKeywords())
        .append(commonGridBoundaryConditionKeywords());
}

template <int Dim>
GridFriction<Dim>::GridFriction(const Dictionary& dict, const CartesianGrid<Dim>& grid)
    : GridFriction(keywords().read(dict), grid) {}

template <int Dim>
GridFriction<Dim>::GridFriction(const KeywordValues& values, const CartesianGrid<Dim>& grid)
    : GridBoundaryCondition<Dim>(values, grid),
      mu_(values.scalar("mu")),
      walls_(this->wallNormals(values, grid)),
      normalText_(this->normalText(values)) {}

template <int Dim>
void GridFriction<Dim>::apply(const CartesianGrid<Dim>&, std::vector<Vector<Dim>>& velocity,
                              std::vector<Vector<Dim>>* acceleration, double, double dt) const {
    const auto& nodes = this->selection().nodes();
    for (std::size_t k = 0; k < nodes.size(); ++k) {
        Vector<Dim>& v = velocity[nodes[k]];
        for (const WallNormal& wall : walls_[k]) {
            const double vn = wall.sign * v[wall.axis];  // v.n, n into the material
            if (!(vn < 0.0)) continue;                   // leaving or sliding along: free
            const double removed = -vn;                  // dv_n > 0
            v[wall.axis] = 0.0;
            const double speed = v.norm();  // |v_t|: the normal component is now zero
            const double factor = speed > 0.0 ? std::max(0.0, 1.0 - mu_ * removed / speed) : 0.0;
            const Vector<Dim> slowed = factor * v;
            if (acceleration) {
                Vector<Dim>& a = (*acceleration)[nodes[k]];
                a[wall.axis] = 0.0;
                if (dt > 0.0) a -= (v - slowed) / dt;
            }
            v = slowed;
        }
    }
}

template <int Dim>
std::string GridFriction<Dim>::describe() const {
    return GridBoundaryCondition<Dim>::describe() + ", mu " + formatKeywordNumber(mu_) + ", " + normalText_;
}

MFDYN_REGISTER_DIM(GridBoundaryCondition, GridFriction, "friction",
                   "axis-aligned rigid wall with Coulomb friction mu, acting while a node moves into it");

}  // namespace mfdyn
