#pragma once
// contact: how the bodies of an mpmFsi run interact through the grid (issue 18 item 2,
// doc/methods/mpm.md note 6.3), selected by a word in constant/mpmProperties:
//
//     contact          singleField;   // singleField (default, the thesis) | multiField
//     multiFieldCoeffs                 // multiField only (MultiFieldContact.cpp)
//     {
//         friction     0;             // Coulomb mu of every pair (0: frictionless)
//         separation   0.8;           // optional: the position check, in cells
//         volumeFraction 1;           // optional: the volume check (bodies fill the node's support)
//         surfaceGap   yes;           // optional: the surface-gap check (surfaces from the centres)
//         pairs { gate { bodies (water gate); friction 0.1; } }   // optional, per pair
//     }
//
// singleField: every body maps into one node field, so bodies share one velocity and contact
// (sticking, early by one or two cells) comes from the mapping itself (note 2.3); the solver
// allocates nothing more.
// multiField: a node field per body (a body is a particleGen region), each body's grid solve and
// grid conditions on its own; where two or more bodies have mass the model corrects each body's
// node velocity towards the nodes' centre-of-mass velocity (Bardenhagen, Guilkey, Roessig,
// Brackbill, Witzel & Foster 2001; Nairn 2013). The correction is one call per step on the
// node arrays (the loops are the model's), so a unit test can drive it on hand-made nodes.
#include "core/Dictionary.hpp"
#include "core/KeywordSchema.hpp"
#include "core/Registry.hpp"
#include "core/Tensor.hpp"
#include "grid/CartesianGrid.hpp"
#include "grid/shapeFunctions/ShapeFunction.hpp"

#include <memory>
#include <string>
#include <vector>

namespace mfdyn {

// The node state of every body, body b's arrays at index b, each of the grid's node count.
template <int Dim>
struct ContactNodes {
    const std::vector<std::vector<double>>* mass = nullptr;               // m_bI
    const std::vector<std::vector<Vector<Dim>>>* massGradient = nullptr;  // sum_p m_p grad N_Ip
    // sum_p N_Ip m_p x_p (the nodal centre of mass times m_bI), for the position check; may be null.
    const std::vector<std::vector<Vector<Dim>>>* massPosition = nullptr;
    // sum_p N_Ip V_p (the body's volume at the node, V_p = J_p V0_p), for the volume check; may be null.
    const std::vector<std::vector<double>>* volume = nullptr;
    std::vector<std::vector<Vector<Dim>>>* velocity = nullptr;      // v_bI, corrected in place
    std::vector<std::vector<Vector<Dim>>>* acceleration = nullptr;  // a_bI += dv / dt; may be null
    // The grid (node positions) and the shape function, for the surface-gap check; may be null.
    const CartesianGrid<Dim>* grid = nullptr;
    const ShapeFunction<Dim>* shape = nullptr;
    double massCutoff = 1e-10;  // a body takes part at a node where its mass is at least this
    double cellSize = 1.0;      // the grid's smallest spacing (the position check's unit)
    double cellVolume = 1.0;    // the product of the spacings: int N_I dV at a node off the edges
    // Several ranks: the nodes whose pair forces this rank adds (each node on one rank); null: all.
    const std::vector<char>* countedNodes = nullptr;
};

template <int Dim>
class Contact {
public:
    static constexpr const char* familyName = "contact";
    using Selector = Registry<Contact<Dim>, const Dictionary&>;
    virtual ~Contact() = default;
    // false for singleField: one node field, nothing to correct.
    virtual bool multiField() const = 0;
    // The run's body names (the regions, in region-id order): checks the pairs the dictionary
    // names (InputError naming the file, line and valid bodies) and sizes the pair table.
    virtual void bind(const std::vector<std::string>& bodies) { (void)bodies; }
    // Corrects the node velocities (and accelerations, when given) of `nodes` for a step dt;
    // returns the contact force on the first body of each pair from the second, sum_I m_aI
    // dv_aI / dt, pair k = pairIndex(a, b) (empty for singleField).
    virtual std::vector<Vector<Dim>> correct(ContactNodes<Dim>& nodes, double dt) const {
        (void)nodes, (void)dt;
        return {};
    }
    // Pairs a < b in the order (0,1), (0,2), ..., (1,2), ...; pairs() of them.
    static std::size_t pairIndex(std::size_t a, std::size_t b, std::size_t bodies) {
        return a * bodies - a * (a + 1) / 2 + (b - a - 1);
    }
    virtual std::size_t pairs() const { return 0; }
    virtual std::string describe() const { return type_; }
    const std::string& type() const { return type_; }
    void setType(std::string type) { type_ = std::move(type); }

private:
    std::string type_;
};

extern template class Contact<1>;
extern template class Contact<2>;
extern template class Contact<3>;

}  // namespace mfdyn
