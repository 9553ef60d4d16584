// pressureSmoothing `cellJacobian` (CellJacobian.hpp): the cell-averaged jacobian (F-bar, J-bar)
// against the pressure checkerboard of weakly compressible fluids on material points.
//
// After the stress update, per grid cell c and fluid material, over its particles p in c:
//
//     V0_p    = m_p / rho0_p                              (the reference volume)
//     Jbar_c  = sum_p V0_p J_p / sum_p V0_p               (the cell's present volume of this fluid
//                                                          over its reference volume)
//     F_p     <- (Jbar_c / J_p)^(1/dim) F_p,  J_p <- Jbar_c    (det F_p = Jbar_c; in plane strain
//                                                          dim = 2: F_zz = 1 stays; where the
//                                                          run carries F: a fluid-only scene has J)
//     sigma_p <- sigma_p + (P(rho0/J_p) - P(rho0/Jbar_c)) I  (the pressure of the equation of state
//                                                          at Jbar_c with the particle's energy;
//                                                          below 3D also sigma_zz)
//
// The cell's present volume sum_p V0_p J_p is kept exactly (to round-off), and so its mass
// density; the density, and with it the pressure, is constant over the cell's particles of a
// fluid. The isochoric part of F (the viscous fluid does not use it; a solid is never smoothed)
// is kept.
//
// Source: the F-bar method of de Souza Neto, Peric, Dettmer and Owen (1996), "Design of simple
// low order finite elements for large strain analysis of nearly incompressible solids", Int. J.
// Solids Struct. 33, 3277-3296, in the material point form of Coombs, Charlton, Cortis and
// Augarde (2018), "Overcoming volumetric locking in material point methods", Comput. Methods
// Appl. Mech. Engrg. 333, 1-21 (there the volume ratio averaged over the particles of a cell).
// Here the average replaces J after the update (the next step starts from Jbar), not only in the
// stress.
//
// Limits: the energy e is not changed for the jump J_p -> Jbar_c (its pressure work, second order
// in the jump, is not booked; exact for a barotropic law such as Tait, whose pressure does not
// depend on e); a cell with one particle is unchanged; the average is per cell of the solver's
// grid.
#include "mpm/pressureSmoothing/CellJacobian.hpp"

#include "core/Parallel.hpp"

#include <cmath>

namespace mfdyn {

template <int Dim>
KeywordSchema CellJacobian<Dim>::keywords() {
    return KeywordSchema(PressureSmoothing<Dim>::familyName, "cellJacobian");
}

template <int Dim>
void CellJacobian<Dim>::apply(const CartesianGrid<Dim>& grid, PressureSmoothingFields<Dim>& f) const {
    buckets_.build(grid, f);
    const std::size_t n = f.position.size();
    // Gather per bucket: each particle is in one bucket, so each is written by one iteration.
    parallelForWork(buckets_.count(), n, [&](std::size_t b) {
        const auto members = buckets_.members(b);
        if (members.size() < 2) return;
        double reference = 0, present = 0;
        for (const std::uint32_t p : members) {
            const double V0 = f.mass[p] / f.referenceDensity[p];
            reference += V0;
            present += V0 * f.jacobian[p];
        }
        const double mean = present / reference;
        for (const std::uint32_t p : members) {
            const double J = f.jacobian[p];
            const double shift = f.pressureAt(p, J) - f.pressureAt(p, mean);
            if (!f.deformationGradient.empty()) f.deformationGradient[p] *= std::pow(mean / J, 1.0 / Dim);
            f.jacobian[p] = mean;
            for (int d = 0; d < Dim; ++d) f.cauchyStress[p](d, d) += shift;
            if (!f.cauchyStressZZ.empty()) f.cauchyStressZZ[p] += shift;
            if (!f.pressure.empty()) f.pressure[p] = f.pressureAt(p, mean);
        }
    });
}

template class CellJacobian<1>;
template class CellJacobian<2>;
template class CellJacobian<3>;

MFDYN_REGISTER_DIM(
    PressureSmoothing, CellJacobian, "cellJacobian",
    "each fluid particle's J the reference-volume-weighted mean of its cell's, F scaled to it (F-bar)");

}  // namespace mfdyn
