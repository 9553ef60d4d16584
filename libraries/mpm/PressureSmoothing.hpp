#pragma once
// pressureSmoothing: the family that damps the pressure checkerboard of weakly compressible fluids
// on material points (issue 18, item 4), selected by a word in constant/mpmProperties:
//
//     pressureSmoothing  none;     // none (default) | ... (the models document themselves)
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
