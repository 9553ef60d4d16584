#pragma once
// The per-particle measures behind tlSph's health indicators (TlSphSolver::healthIndicators), kept
// apart from the solver so that unit tests can set a deformation and read them back
// (tests/unit/tlSph/TlSphHealthTest.cpp). Every measure lives on the reference neighbourhoods,
// which total-Lagrangian SPH builds once (meshfreeOperators/ReferenceOperators.hpp).
//
// hourglass (Ganzenmueller 2015, "An hourglass control algorithm for Lagrangian Smooth Particle
// Hydrodynamics", CMAME 286:87-106): the pair's deviation from its particle's own
// deformation, with X_ab = X_b - X_a and x_ab = x_b - x_a,
//     e_ab = F_a X_ab - x_ab,      indicator_a = max_b |e_ab| / |X_ab|   (dimensionless).
// Zero for any affine motion x = F X + c (F_a, the corrected gradient of x, is then F); an
// hourglass (zero-energy) mode, which the particle's F does not see, makes it of the order of the
// mode's amplitude over the spacing. A smooth deformation gives about |grad F| |X_ab| / 2, at most
// |grad F| times the support radius.
//
// neighbourDeficiency: the reciprocal condition number of the gradient correction matrix
//     B_a = sum_b V_b grad W_b(X_a) (x) (X_b - X_a),     L_a = B_a^-1 (Bonet & Lok 1999; eq. 21),
// sigma_min(B_a) / sigma_max(B_a): 1 in a uniform lattice's interior, about 0.3 at a cube's
// corner; ReferenceOperators refuses a particle below 1e-8. The weights of the corrected gradient
// grow like 1 / sigma_min: a small value means a particle whose gradient (and so its force) is
// amplified in one direction, a sliver or a thin layer.
#include "core/Tensor.hpp"
#include "kernels/Kernel.hpp"
#include "particles/NeighbourList.hpp"

#include <Eigen/SVD>
#include <algorithm>
#include <cstddef>

namespace mfdyn {

// max_b |F_a X_ab - x_ab| / |X_ab| over the neighbours b of row a with b < real (the neighbours at
// or past `real` are mirror ghosts, whose current positions nobody keeps); 0 without any.
template <int Dim>
double hourglassIndicator(std::size_t a, const NeighbourList& rows, const Vector<Dim>* X,
                          const Vector<Dim>* x, const Tensor<Dim>& Fa, std::size_t real) {
    double largest = 0;
    for (std::size_t k = rows.offsets()[a]; k < rows.offsets()[a + 1]; ++k) {
        const std::size_t b = rows.indices()[k];
        if (b >= real) continue;
        const Vector<Dim> Xab = X[b] - X[a];
        const Vector<Dim> e = Fa * Xab - (x[b] - x[a]);
        largest = std::max(largest, e.norm() / Xab.norm());
    }
    return largest;
}

// sigma_min(B_a) / sigma_max(B_a) of the gradient correction matrix of row a (X and V over the
// real particles and the ghosts, as the rows index them); 0 for a row without neighbours.
template <int Dim>
double correctionConditioning(std::size_t a, const NeighbourList& rows, const Vector<Dim>* X, const double* V,
                              const Kernel& kernel, double h) {
    Tensor<Dim> B = Tensor<Dim>::Zero();
    for (std::size_t k = rows.offsets()[a]; k < rows.offsets()[a + 1]; ++k) {
        const std::size_t b = rows.indices()[k];
        B += V[b] * kernel.gradW<Dim>(Vector<Dim>(X[a] - X[b]), h) * (X[b] - X[a]).transpose();
    }
    if constexpr (Dim == 1) {
        return B(0, 0) != 0 ? 1.0 : 0.0;  // one direction: nothing to compare
    } else {
        const Eigen::JacobiSVD<Tensor<Dim>> svd(B);
        const auto& s = svd.singularValues();
        return s(0) > 0 ? s(Dim - 1) / s(0) : 0.0;
    }
}

}  // namespace mfdyn
