#pragma once
// `prescribedTraction`: a traction t [Pa] on a face of area A [m^2] carried by the selected
// surface particles, as boundary forces f_a = t A V_a / Σ_b V_b (addBoundaryForce hook).
//
//   traction (tx ty tz);                            constant [Pa], or
//   table ((t0 (tx ty tz)) (t1 (tx ty tz)) ...);    piecewise linear in t [s], held constant
//                                                   before the first and after the last time.
//   area A;                                         the loaded face's area [m^2], required.
//
// The particles and their shares V_a/Σ V_b are fixed when the condition is built (V = mass /
// density then) and kept by globalId through reorders. See PrescribedTraction.cpp.
#include "boundaryConditions/BoundaryCondition.hpp"
#include "boundaryConditions/VectorTable.hpp"

#include <cstdint>
#include <vector>

namespace mfdyn {

template <int Dim>
class PrescribedTraction : public BoundaryCondition<Dim> {
public:
    using typename BoundaryCondition<Dim>::VectorType;
    PrescribedTraction(const Dictionary& dict, const ParticleSet<Dim>& particles);
    static KeywordSchema keywords();

    // t(t) [Pa].
    VectorType traction(double t) const;
    double area() const { return area_; }
    bool appliesForces() const override { return true; }

protected:
    void boundaryForce(const ParticleSet<Dim>& particles, std::vector<VectorType>& force,
                       double t) const override;
    void selectionUpdated(const ParticleSet<Dim>& particles) override;

private:
    PrescribedTraction(const KeywordValues& values, const ParticleSet<Dim>& particles);

    VectorTable<Dim> table_;
    double area_ = 0;
    std::vector<std::int64_t> ids_;     // globalId of the loaded particles
    std::vector<std::size_t> indices_;  // their current indices
    std::vector<double> share_;         // A V_a / Σ V_b [m^2]
};

}  // namespace mfdyn
