#pragma once
// The free-surface conditions of the finite pointset method's parts (von Nida 2005 §5.1.2, §5.2.4;
// doc/methods/fpm.md §3.2, §3.3) on one surface particle with outward unit normal n:
//
//     Euler part:  p = p_o;        shear part:  S n = 0, so that sigma n = (S - p I) n = -p_o n,
//
// S projected as S <- P S P - tr(P S P) / (d - 1) P with P = I - n n^T (traceless, S n = 0, the
// tangential part kept). The thesis gives no enforcement; overwriting the state alone changes the
// outgoing characteristic too. The characteristic variant keeps it, as characteristic boundary
// conditions of hyperbolic systems do (e.g. Thompson 1987, J. Comput. Phys. 68): along n the 1D
// pair rho dv/dt = d(sigma n)/dn, d(sigma n)/dt = Z^2 / rho dv/dn has the invariant
//
//     w_out = Z v - sigma n   (travels along +n, out of the body: its update is upwind)
//
// and the condition sets only the incoming one, so overwriting sigma n by sigma_o n with w_out kept
// is v <- v - (sigma n - sigma_o n) / Z, per direction with the part's own impedance:
//     Euler part:  sigma n - sigma_o n = -(p - p_o) n,  Z = rho c (its sound speed), and its
//                  entropy wave w1 = rho - p / c^2 kept as well (below);
//     shear part:  sigma n - sigma_o n = S n (the part leaves p to the Euler part),
//                  Z = sqrt(mu rho) along the surface (S_tn' = mu dv_t/dn) and
//                  Z = sqrt(2 (1 - 1/d) mu rho) along n (S_nn' = 2 mu (1 - 1/d) dv_n/dn).
#include "core/Tensor.hpp"

#include <cmath>

namespace mfdyn::fpm {

// p <- p_o; with `characteristic`, first v <- v + (p - p_o) / (rho c) n (the outgoing
// w = rho c v.n + p kept) and, the Euler part's entropy wave w1 = rho - p / c^2 (its (5.11), speed 0)
// kept too, rho <- rho + (p_o - p) / c^2 with e <- e + p_m / rho_m^2 (rho_new - rho) (the part's
// de = p drho / rho^2, at the means of the old and new p and rho), so that (rho, e) stays on the
// isentrope through the new p: the state the equation of state reads (c^2, g) stays that of the
// pinned p, as the part's own update keeps it in the interior. A density that would not stay
// positive is left alone. e may be null (no energy).
template <int Dim>
void applySurfacePressure(double outerPressure, const Vector<Dim>& n, double c, bool characteristic,
                          double& p, double& rho, double* e, Vector<Dim>& v) {
    if (characteristic && rho > 0 && c > 0) {
        v += ((p - outerPressure) / (rho * c)) * n;
        const double rhoNew = rho + (outerPressure - p) / (c * c);
        if (rhoNew > 0) {
            if (e) {
                const double pMean = 0.5 * (p + outerPressure), rhoMean = 0.5 * (rho + rhoNew);
                *e += pMean / (rhoMean * rhoMean) * (rhoNew - rho);
            }
            rho = rhoNew;
        }
    }
    p = outerPressure;
}

// S <- P S P - tr(P S P) / (d - 1) P; with `characteristic`, v <- v - P (S n) / sqrt(mu rho)
// - (n . S n) / sqrt(2 (1 - 1/d) mu rho) n first.
template <int Dim>
void applySurfaceTraction(const Vector<Dim>& n, double mu, double rho, bool characteristic,
                          SymmTensor<Dim>& S, Vector<Dim>& v) {
    const Tensor<Dim> P = Tensor<Dim>::Identity() - n * n.transpose();
    const Tensor<Dim> full = S.full();
    if (characteristic && mu > 0 && rho > 0) {
        const Vector<Dim> traction = full * n;
        v -= (P * traction) / std::sqrt(mu * rho);
        if constexpr (Dim > 1)  // in 1D the deviator is 0 and so is S_nn's rate
            v -= (n.dot(traction) / std::sqrt(2.0 * (1.0 - 1.0 / Dim) * mu * rho)) * n;
    }
    Tensor<Dim> T = P * full * P;
    if constexpr (Dim > 1) T -= (T.trace() / (Dim - 1)) * P;
    S = SymmTensor<Dim>::fromFull(T);
}

}  // namespace mfdyn::fpm
