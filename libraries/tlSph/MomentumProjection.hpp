#pragma once
// The least-squares projections of Lee et al. 2016 section 5 (doc/methods/tl-jst-sph.md 2.5) that make the
// internal forces and the dissipation of a total-Lagrangian solver conserve linear and angular
// momentum exactly, whatever the kernel corrections and mixed strains do to their symmetry.
//
//   momentum(f, V, x~):  f~_a = f_a + lambda_ang x x~_a + lambda_lin minimising sum V |f~ - f|^2
//                        subject to sum V f~ = 0 and sum V x~ x f~ = 0;
//   mean(g, V):          g~_a = g_a - sum V g / sum V (the J-dissipation, eq. 51).
//
// x~ is shifted to its volume-weighted centroid c, which decouples the 6x6 system of the paper:
//   lambda_lin = -sum V f / sum V,
//   [sum V (|x'|^2 I - x' x'^T)] lambda_ang = -sum V x' x f,   x' = x~ - c.
// In 2D the angular multiplier is the z component only, in 1D there is none. Every sum goes
// through GlobalReduce::exactSum (core/Parallel.hpp: exact, rounded once), so the multipliers, and
// with them the projected rates, have the same bits for any thread count and on any number of
// ranks as serially: a sum rounded per block and per rank differed in its last bits, and fed back
// into the state that grew to 1e-11 of the pressure on the oscillating plate in 776 steps (issue 21).
#include "core/Tensor.hpp"

#include <vector>

namespace mfdyn {

template <int Dim>
struct MomentumProjection {
    // The projection of f in place; `angular` false enforces only the linear momentum.
    static void momentum(std::vector<Vector<Dim>>& f, const std::vector<double>& volume,
                         const std::vector<Vector<Dim>>& xTilde, bool angular = true);
    static void mean(std::vector<double>& g, const std::vector<double>& volume);
    // The same over the particles with skip[a] == 0 only (the others keep g); skip empty: all.
    static void mean(std::vector<double>& g, const std::vector<double>& volume,
                     const std::vector<char>& skip);
};

extern template struct MomentumProjection<1>;
extern template struct MomentumProjection<2>;
extern template struct MomentumProjection<3>;

}  // namespace mfdyn
