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
//
// The thesis's pair (p = p_o and S n = 0, each part its own) asks more than a free surface does: a
// traction-free surface has sigma n = -p_o n, d conditions, and leaves the stress along the surface
// free. With p = p_o and S n = 0 (S traceless) that stress is -p_o too, where a bent plate carries
// its largest bending stress (a surface layer that carries no sigma_tt makes the plate thinner in
// bending). The `traction` condition (applySurfaceStress) acts on the total stress
// sigma = S - p I instead:
//
//     sigma <- sigma - (n . sigma n + p_o) n n^T - (t n^T + n t^T),   t = P sigma n,
//
// so sigma n = -p_o n with sigma's tangential block (and, in plane strain, sigma_zz) kept, then
// re-split p = -tr sigma / 3 (the 3D trace; -tr sigma / d when the deviator is the plane's) and
// S = sigma + p I. Its characteristic velocity keeps the full system's outgoing invariants:
// Z = sqrt(rho (rho c^2 + 2 (1 - alpha) mu)) = rho c_L along n (both parts' stiffness of sigma_nn,
// alpha the deviator's trace weight) and sqrt(mu rho) along the surface.
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
inline void keepEntropyWave(double pOld, double pNew, double c, double& rho, double* e) {
    const double rhoNew = rho + (pNew - pOld) / (c * c);
    if (!(rhoNew > 0)) return;
    if (e) {
        const double pMean = 0.5 * (pOld + pNew), rhoMean = 0.5 * (rho + rhoNew);
        *e += pMean / (rhoMean * rhoMean) * (rhoNew - rho);
    }
    rho = rhoNew;
}

template <int Dim>
void applySurfacePressure(double outerPressure, const Vector<Dim>& n, double c, bool characteristic,
                          double& p, double& rho, double* e, Vector<Dim>& v) {
    if (characteristic && rho > 0 && c > 0) {
        v += ((p - outerPressure) / (rho * c)) * n;
        keepEntropyWave(p, outerPressure, c, rho, e);
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

// The `traction` condition (top of this file): sigma n = -p_o n on sigma = S - p I, its tangential
// block kept, re-split into p and S. alpha is the deviator's trace weight: 1/d (S traceless in the
// plane) or 1/3 with d < 3 (plane strain: sigma_zz = -p - tr S / (3 - d), kept, enters p). With
// `characteristic` (rho > 0), first v += (n . dt) / (rho c_L) n + P dt / sqrt(mu rho) with
// dt = sigma_new n - sigma n, and, c > 0, the entropy wave of the change of p kept (rho, e as in
// applySurfacePressure). mu = 0 (no shear stiffness) takes the pressure condition p = p_o.
template <int Dim>
void applySurfaceStress(double outerPressure, const Vector<Dim>& n, double alpha, double mu, double c,
                        bool characteristic, double& p, SymmTensor<Dim>& S, double& rho, double* e,
                        Vector<Dim>& v) {
    if (!(mu > 0)) {
        applySurfacePressure<Dim>(outerPressure, n, c, characteristic, p, rho, e, v);
        return;
    }
    const Tensor<Dim> identity = Tensor<Dim>::Identity();
    const Tensor<Dim> deviator = S.full();
    const bool outOfPlane = Dim < 3 && std::abs(alpha - 1.0 / Dim) > 1e-12;
    const double sigmaZ = outOfPlane ? -p - deviator.trace() / (3 - Dim) : 0.0;
    Tensor<Dim> sigma = deviator - p * identity;
    const Vector<Dim> traction = sigma * n;
    const double normal = n.dot(traction);
    const Vector<Dim> tangential = traction - normal * n;
    sigma -= (normal + outerPressure) * (n * n.transpose()) +
             (tangential * n.transpose() + n * tangential.transpose());
    const double pNew = outOfPlane ? -(sigma.trace() + (3 - Dim) * sigmaZ) / 3.0 : -sigma.trace() / Dim;
    if (characteristic && rho > 0) {
        const double normalChange = -(normal + outerPressure);  // n . (sigma_new n - sigma n)
        const double normalImpedance = std::sqrt(rho * (rho * c * c + 2.0 * (1.0 - alpha) * mu));
        if (normalImpedance > 0) v += (normalChange / normalImpedance) * n;
        v -= tangential / std::sqrt(mu * rho);
        if (c > 0) keepEntropyWave(p, pNew, c, rho, e);
    }
    p = pNew;
    S = SymmTensor<Dim>::fromFull(sigma + pNew * identity);
}

}  // namespace mfdyn::fpm
