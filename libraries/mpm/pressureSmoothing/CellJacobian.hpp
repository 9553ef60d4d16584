#pragma once
// pressureSmoothing `cellJacobian`: each fluid particle's J replaced by the reference-volume-
// weighted mean J of its cell's particles of the same fluid, F scaled to it, and the pressure of
// the equation of state at that J (CellJacobian.cpp for the equations; the F-bar idea).
//
//     pressureSmoothing cellJacobian;     // constant/mpmProperties; no keywords
#include "mpm/PressureSmoothing.hpp"
#include "mpm/pressureSmoothing/CellBuckets.hpp"

namespace mfdyn {

template <int Dim>
class CellJacobian final : public PressureSmoothing<Dim> {
public:
    explicit CellJacobian(const Dictionary&) {}
    static KeywordSchema keywords();
    bool active() const override { return true; }
    void apply(const CartesianGrid<Dim>& grid, PressureSmoothingFields<Dim>& fields) const override;

private:
    // Work buffer kept between steps (apply is const to the solver, the buffer is not state).
    mutable CellBuckets<Dim> buckets_;
};

}  // namespace mfdyn
