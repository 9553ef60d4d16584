#pragma once
// pressureSmoothing: the family that damps the pressure checkerboard of weakly compressible fluids
// on material points (issue 18, item 4), selected by a word in constant/mpmProperties:
//
//     pressureSmoothing  none;     // none (default) | cellPressure | cellJacobian
//
//   none          each particle's pressure from its own J (the thesis)
//   cellPressure  sigma_p += (p_p - pbar_c) I, pbar_c the volume-weighted mean pressure of the
//                 fluid's particles in the cell (pressureSmoothing/CellPressure.cpp)
//   cellJacobian  F_p <- (Jbar_c / J_p)^(1/dim) F_p, J_p <- Jbar_c, the reference-volume-weighted
//                 mean J of the cell, and the pressure of the equation of state at Jbar_c
//                 (pressureSmoothing/CellJacobian.cpp)
//
// Both average over the particles of one fluid material in one grid cell (the solver's grid);
// particles of other materials, and solids, are left alone.
//
// A model is applied once per step, after the stress update, to the particles of fluid materials
// (an equation of state without a strength law): it may replace each particle's pressure, or its
// jacobian (F and J, with the pressure the equation of state gives at the new J), by an average
// over its cell. One virtual call per step; the loops are the model's.
#include "core/Dictionary.hpp"
#include "core/KeywordSchema.hpp"
#include "core/Registry.hpp"
#include "grid/CartesianGrid.hpp"

#include <cstdint>
#include <functional>
#include <memory>
#include <span>
#include <string>

namespace mfdyn {

// The particle state a smoothing model reads and changes, as spans over the solver's fields.
template <int Dim>
struct PressureSmoothingFields {
    std::span<const Vector<Dim>> position;
    std::span<const double> mass;
    std::span<const double> referenceDensity;  // rho0: V0 = mass / rho0, V = J V0
    std::span<const std::int64_t> material;
    std::span<Tensor<Dim>> deformationGradient;
    std::span<double> jacobian;
    std::span<SymmTensor<Dim>> cauchyStress;
    std::span<double> cauchyStressZZ;  // below 3D: the plane-strain sigma_zz; empty in 3D
    // Material k takes part (a fluid).
    std::function<bool(std::int64_t)> smoothed;
    // The equation of state's pressure of particle p at jacobian J (its present energy).
    std::function<double(std::size_t, double)> pressureAt;
    // Optional: the particles' stored pressure field (written and used as p^n by the next energy
    // update); a model that changes a particle's pressure writes it here when it is given.
    std::span<double> pressure;
    // Optional: the particles' global ids; a cell's particles are then summed in id order (the
    // serial run's index order), so that a rank, which numbers its owned and halo particles
    // otherwise, has the serial bits (issue 21).
    std::span<const std::int64_t> globalId;
};

template <int Dim>
class PressureSmoothing {
public:
    static constexpr const char* familyName = "pressureSmoothing";
    using Selector = Registry<PressureSmoothing<Dim>, const Dictionary&>;
    virtual ~PressureSmoothing() = default;
    // false for none: the solver skips the pass.
    virtual bool active() const = 0;
    virtual void apply(const CartesianGrid<Dim>& grid, PressureSmoothingFields<Dim>& fields) const = 0;
    virtual std::string describe() const { return type_; }
    const std::string& type() const { return type_; }
    void setType(std::string type) { type_ = std::move(type); }

private:
    std::string type_;
};

extern template class PressureSmoothing<1>;
extern template class PressureSmoothing<2>;
extern template class PressureSmoothing<3>;

}  // namespace mfdyn
