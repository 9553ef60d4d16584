// pressureSmoothing `cellPressure` (CellPressure.hpp): the cell-averaged pressure against the
// pressure checkerboard of weakly compressible fluids on material points.
//
// After the stress update, per grid cell c and fluid material, over its particles p in c:
//
//     p_p     = P(rho0_p / J_p, e_p)                    (the equation of state's pressure, as in sigma_p)
//     V_p     = J_p m_p / rho0_p                        (the present volume)
//     pbar_c  = sum_p V_p p_p / sum_p V_p
//     sigma_p <- sigma_p + (p_p - pbar_c) I             (below 3D also the plane-strain sigma_zz)
//
// so every particle of the cell carries the same pressure pbar_c and keeps its own deviator
// (viscous stress). The force a cell's particles put on its nodes keeps their volume-weighted
// pressure, sum_p V_p p_p = pbar_c sum_p V_p, exactly (to round-off): the averaging removes the
// part of the pressure field that alternates between neighbouring points within a cell (the
// checkerboard the grid cannot see, and so cannot damp) and keeps the part the grid resolves.
//
// Source: the cell-constant pressure (volumetric stress) of mixed MPM formulations against
// volumetric locking and pressure oscillation, Mast, Mackenzie-Helnwein, Arduino, Miller and
// Shin (2012), "Mitigating kinematic locking in the material point method", J. Comput. Phys.
// 231, 5351-5373; used here in its simplest form, a volume-weighted average of the particles'
// pressures per background cell (no Hu-Washizu projection, no averaging across cells).
//
// Limits: J and F are left as they are (each particle's density still its own: the written
// density and the equation of state's next p^n differ from pbar_c; cellJacobian averages J
// instead); the energy e is not changed (the pressure work of the step used p_p); a cell with
// one particle is unchanged; the average is per cell of the solver's grid, so it smooths over
// dx, not over the kernel's support.
#include "mpm/pressureSmoothing/CellPressure.hpp"

#include "core/Parallel.hpp"

namespace mfdyn {

template <int Dim>
KeywordSchema CellPressure<Dim>::keywords() {
    return KeywordSchema(PressureSmoothing<Dim>::familyName, "cellPressure");
}

template <int Dim>
void CellPressure<Dim>::apply(const CartesianGrid<Dim>& grid, PressureSmoothingFields<Dim>& f) const {
    buckets_.build(grid, f);
    const std::size_t n = f.position.size();
    pressure_.resize(n);
    // Gather per bucket: each particle is in one bucket, so each is written by one iteration.
    parallelForWork(buckets_.count(), n, [&](std::size_t b) {
        const auto members = buckets_.members(b);
        double volume = 0, sum = 0;
        for (const std::uint32_t p : members) {
            const double V = f.jacobian[p] * f.mass[p] / f.referenceDensity[p];
            const double pressure = f.pressureAt(p, f.jacobian[p]);
            pressure_[p] = pressure;
            volume += V;
            sum += V * pressure;
        }
        const double mean = sum / volume;
        for (const std::uint32_t p : members) {
            const double shift = pressure_[p] - mean;
            for (int d = 0; d < Dim; ++d) f.cauchyStress[p](d, d) += shift;
            if (!f.cauchyStressZZ.empty()) f.cauchyStressZZ[p] += shift;
            if (!f.pressure.empty()) f.pressure[p] = mean;
        }
    });
}

template class CellPressure<1>;
template class CellPressure<2>;
template class CellPressure<3>;

MFDYN_REGISTER_DIM(PressureSmoothing, CellPressure, "cellPressure",
                   "each fluid particle's pressure the volume-weighted mean of its cell's (Mast et al. 2012)");

}  // namespace mfdyn
