#pragma once
// pressureSmoothing `cellPressure`: each fluid particle's pressure replaced by the volume-weighted
// mean pressure of its cell's particles of the same fluid (CellPressure.cpp for the equations).
//
//     pressureSmoothing cellPressure;     // constant/mpmProperties; no keywords
#include "mpm/PressureSmoothing.hpp"
#include "mpm/pressureSmoothing/CellBuckets.hpp"

#include <vector>

namespace mfdyn {

template <int Dim>
class CellPressure final : public PressureSmoothing<Dim> {
public:
    explicit CellPressure(const Dictionary&) {}
    static KeywordSchema keywords();
    bool active() const override { return true; }
    void apply(const CartesianGrid<Dim>& grid, PressureSmoothingFields<Dim>& fields) const override;

private:
    // Work buffers kept between steps (apply is const to the solver, the buffers are not state).
    mutable CellBuckets<Dim> buckets_;
    mutable std::vector<double> pressure_;
};

}  // namespace mfdyn
