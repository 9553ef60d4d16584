#pragma once
// Grid boundary conditions: the family `gridBoundaryCondition`, for grid methods (MPM). A case
// lists them in the method's properties (constant/mpmProperties), one sub-dictionary each:
//
//     gridBoundaryConditions
//     {
//         floor  { type friction;           faces (yMin); mu 0.3; }
//         walls  { type slip;               faces (xMin xMax); }
//         lid    { type prescribedVelocity; faces (yMax); velocity (0.1 0); components (x); }
//         anchor { type fixed;              shape { type box; min (0 0); max (0.1 0.1); } }
//         top    { type open;               faces (yMax); }
//     }
//
// Each acts on a NodeSelection (NodeSelection.hpp: `faces (...)`, `plane { }`, `shape { }`,
// `all yes`) and is applied after the grid solve, once per step, to the node velocity and
// acceleration (GridBoundaryConditionList::apply runs them in the order written, so where two
// selections overlap the later condition has the last word):
//
//   velocity      the nodes' updated velocity v_I^{n+1} [m/s], which the particles' positions
//                 (and PIC/APIC velocities) are interpolated from;
//   acceleration  (may be null) the nodes' rate a_I = (v_I^{n+1} - v_I^n)/dt [m/s^2], which a
//                 FLIP update interpolates to the particles' velocity.
//
// A component a condition fixes to a value is set in both: fixed v = a = 0 (all components, or
// those of `components (y)`: the thesis's spring fixes only v_y), slip the wall-normal
// components of both zero, prescribedVelocity v_i = v_i(t) and a_i = dv_i/dt(t) (so fixed is
// prescribedVelocity (0 0 0)), with t the time v belongs to (t^{n+1}). friction removes the
// normal components as slip does and decelerates the tangential velocity by mu times the
// normal velocity removed (a Coulomb impulse), the same change divided by dt going into the
// acceleration; see GridFriction.hpp. Conditions read nothing but the arrays they are given, so
// a node's result does not depend on the order of nodes or on threads.
//
// Wall normals (slip, friction) are axis-aligned: `normal (0 1 0)` (one non-zero component),
// or, when omitted, the faces of the selection, each node taking the normal of every listed
// face it lies on (a corner of `faces (xMin yMin)` gets both). The normal points into the
// material, as the particle planes' do: +e_x on xMin, -e_x on xMax.
#include "core/Registry.hpp"
#include "core/Tensor.hpp"
#include "grid/CartesianGrid.hpp"
#include "grid/NodeSelection.hpp"

#include <memory>
#include <string>
#include <vector>

namespace mfdyn {

// The keywords of every condition: the node selection's (nodeSelectionKeywords()). A type's
// schema declares its own keywords and appends these.
KeywordSchema commonGridBoundaryConditionKeywords();

template <int Dim>
class GridBoundaryCondition {
public:
    static constexpr const char* familyName = "gridBoundaryCondition";
    using Selector = Registry<GridBoundaryCondition, const Dictionary&, const CartesianGrid<Dim>&>;
    using Index = typename CartesianGrid<Dim>::Index;
    static std::unique_ptr<GridBoundaryCondition> New(const Dictionary& dict,
                                                      const CartesianGrid<Dim>& grid) {
        return Selector::New(dict, grid);
    }

    virtual ~GridBoundaryCondition();
    GridBoundaryCondition(const GridBoundaryCondition&) = delete;
    GridBoundaryCondition& operator=(const GridBoundaryCondition&) = delete;

    // The dictionary key (`floor`) and the type name (`friction`).
    const std::string& name() const { return name_; }
    const std::string& type() const { return type_; }
    const NodeSelection<Dim>& selection() const { return selection_; }
    // For the log: "floor: friction on faces (yMin), 21 nodes, mu 0.3".
    virtual std::string describe() const;

    // See the header comment. `velocity` and `*acceleration` have grid.nodeCount() entries; `t`
    // is the time the updated velocity belongs to, `dt` the step (> 0 when acceleration is given).
    virtual void apply(const CartesianGrid<Dim>& grid, std::vector<Vector<Dim>>& velocity,
                       std::vector<Vector<Dim>>* acceleration, double t, double dt) const = 0;

protected:
    // From the values of the type's schema, which appends commonGridBoundaryConditionKeywords().
    GridBoundaryCondition(const KeywordValues& values, const CartesianGrid<Dim>& grid);

    // The axis-aligned inward wall normals of slip and friction: from `normal` when given
    // (InputError when it is not +-e_i), else from the selection's faces (InputError when the
    // selection has none). Call from the derived constructor with its values.
    struct WallNormal {
        int axis = 0;
        double sign = 1.0;  // +1: the material is on the +axis side
    };
    // For each selected node (in selection().nodes() order), the walls it lies on.
    std::vector<std::vector<WallNormal>> wallNormals(const KeywordValues& values,
                                                     const CartesianGrid<Dim>& grid) const;
    // "normal (0 1 0)" or "faces' normals", for describe().
    static std::string normalText(const KeywordValues& values);

private:
    std::string name_;
    std::string type_;
    NodeSelection<Dim> selection_;
};

// The `normal` keyword of slip and friction (optional; the faces' normals when omitted).
KeywordSchema wallNormalKeywords();

// `components (x y)`: which velocity components a condition sets (fixed, prescribedVelocity),
// optional, default all. readComponents gives one flag per axis; InputError at the entry for a
// name that is not an axis of the `dim`-dimensional grid, listing the valid ones.
KeywordSchema componentKeywords();
std::vector<bool> readComponents(const KeywordValues& values, int dim);
// "components (x z)", or "" when all are set.
std::string componentsText(const std::vector<bool>& set);

// The conditions of one `gridBoundaryConditions { name { type ...; } ... }` dictionary, in the
// order written; an empty list when `dict` is null (no conditions: every node free).
template <int Dim>
class GridBoundaryConditionList {
public:
    GridBoundaryConditionList() = default;
    // `dict` holds one sub-dictionary per condition; a primitive entry in it is an InputError.
    GridBoundaryConditionList(const Dictionary& dict, const CartesianGrid<Dim>& grid);

    std::size_t size() const { return conditions_.size(); }
    bool empty() const { return conditions_.empty(); }
    const GridBoundaryCondition<Dim>& operator[](std::size_t k) const { return *conditions_[k]; }

    // Every condition's apply(), in order.
    void apply(const CartesianGrid<Dim>& grid, std::vector<Vector<Dim>>& velocity,
               std::vector<Vector<Dim>>* acceleration, double t, double dt) const;

    // One describe() line per condition, for the log.
    std::vector<std::string> describe() const;

private:
    std::vector<std::unique_ptr<GridBoundaryCondition<Dim>>> conditions_;
};

extern template class GridBoundaryCondition<1>;
extern template class GridBoundaryCondition<2>;
extern template class GridBoundaryCondition<3>;
extern template class GridBoundaryConditionList<1>;
extern template class GridBoundaryConditionList<2>;
extern template class GridBoundaryConditionList<3>;

}  // namespace mfdyn
