#pragma once
// The fused pair loop of impactSph's rates (its equations: the head of SphSolver.cpp), written
// once as a template on the dissipation model so that the model's pair terms are compiled into
// the loop (double dispatch, one virtual call a step and none a pair):
//
//     SphSolver::computeRates   fills an SphPairLoop<Dim> with this step's fields and calls
//     dissipation_->computeRates(loop)       (virtual, Dissipation.hpp), which calls
//     loop.run(*this)                        with the model's own type; run() calls the model's
//     model.prepare(loop)                    once, if it has one (per-particle factors: Balsara's
//                                            switch), then visits every pair (i, j) once and calls
//     model.pair(loop, pair, sums)           inline, adding the model's terms to i's sums.
//
// A dissipation model (built in or in a user library) derives from Dissipation, declares the
// three overrides computeRates(SphPairLoop<1|2|3>&) and defines them in its own .cpp as
// `{ loop.run(*this); }` next to its member templates pair() and, optionally, prepare():
//
//     template <int Dim>
//     void pair(const SphPairLoop<Dim>& loop, const SphPair<Dim>& q, SphPairSums<Dim>& s) const;
//     template <int Dim>
//     void prepare(const SphPairLoop<Dim>& loop);
//
// Included only by the sph sources and by dissipation models.
#include "core/Parallel.hpp"
#include "core/Tensor.hpp"
#include "kernels/KernelEvaluator.hpp"
#include "particles/NeighbourList.hpp"
#include "particles/ParticleSet.hpp"

#include <Eigen/Core>
#include <cmath>
#include <cstddef>
#include <span>

namespace mfdyn {

// Rows of the candidate list or, once SphSolver::selectNeighbours() has run this step, of the
// pairs within either support (row i: count[i] entries from selected + the candidate row's offset).
struct SphNeighbourRows {
    const NeighbourList* list = nullptr;
    const NeighbourList::Index* selected = nullptr;
    const NeighbourList::Index* count = nullptr;
    std::span<const NeighbourList::Index> operator[](std::size_t i) const {
        if (count) return {selected + list->offsets()[i], count[i]};
        return (*list)[i];
    }
};

// One pair of the loop: i owned, j any particle (ghosts included) with 0 < r < max(H_i, H_j).
template <int Dim>
struct SphPair {
    std::size_t i, j;
    Vector<Dim> xij;   // x_i − x_j [m]
    double r;          // |x_ij| [m]
    Vector<Dim> rhat;  // x_ij/r
    Vector<Dim> vij;   // v_i − v_j [m/s]
    double vr;         // v_ij·r̂ [m/s], < 0 when approaching
    double dWi, dWj;   // dW/dr at r with h_i and with h_j [1/m^(d+1)], ≤ 0
    // Particle i's values, loaded once a row: m [kg], ρ [kg/m³], P [Pa], c [m/s], h [m], e [J/kg]
    // (e = 0 without an energy equation).
    double mi, rhoi, Pi, ci, hi, ei;
};

// Particle i's sums a model adds to. `force` is the whole pair force m_i dv_i/dt [N] (the
// pressure term of the pair is already in it); `massFlux` is added to dρ_i/dt [kg/(m³ s)] and
// `heating` to de_i/dt [J/(kg s)].
template <int Dim>
struct SphPairSums {
    Vector<Dim> force = Vector<Dim>::Zero();
    double massFlux = 0;
    double heating = 0;
};

// This step's state, as the solver fills it: every array holds the owned particles [0, owned)
// followed by the ghosts [owned, size), except the outputs and velocityGradient (owned only).
template <int Dim>
struct SphPairLoop {
    std::size_t owned = 0, size = 0;
    const ParticleSet<Dim>* particles = nullptr;  // its copyToGhosts() for a model's factors
    KernelEvaluator<Dim> W;
    SphNeighbourRows neighbours;
    std::size_t pairCount = 0;  // candidate pairs, for the threads' load balance
    const Vector<Dim>* x = nullptr;
    const Vector<Dim>* v = nullptr;
    const double *m = nullptr, *rho = nullptr, *p = nullptr, *c = nullptr, *h = nullptr;
    const double* e = nullptr;      // null without an energy equation
    const double* omega = nullptr;  // null: ω = 1 (no gradH terms)
    // The density scheme's a, b, c (DensityScheme.hpp); H_i⁻¹ = 1/(κ h_i) and dW/dr's factor
    // (SphSolver's kernel factors); m/ρ; a_j P_j/ω_j.
    const double *a = nullptr, *b = nullptr, *cc = nullptr, *invH = nullptr, *gradNorm = nullptr;
    const double *volume = nullptr, *pressureTerm = nullptr;
    bool differenceForm = false;
    // Strength: τ (null without), L (owned); Monaghan's artificial stress R (null: off).
    const SymmTensor<Dim>* tau = nullptr;
    const Tensor<Dim>* velocityGradient = nullptr;
    const Tensor<Dim>* artificialStress = nullptr;
    double artificialStressExponent = 4, eta = 1;
    // The rates of the owned particles, written by run().
    Vector<Dim>* dvdt = nullptr;
    double *drhodt = nullptr, *dedt = nullptr;

    template <class Model>
    void run(Model& model) const;
};

template <int Dim>
template <class Model>
void SphPairLoop<Dim>::run(Model& model) const {
    if constexpr (requires { model.prepare(*this); }) model.prepare(*this);
    const Model& dissipation = model;
    const KernelEvaluator<Dim> W = this->W;
    const SphNeighbourRows rows = neighbours;
    const Vector<Dim>* x = this->x;
    const Vector<Dim>* v = this->v;
    const double *m = this->m, *rho = this->rho, *p = this->p, *c = this->c, *h = this->h;
    const double *a = this->a, *b = this->b, *invH = this->invH, *gradNorm = this->gradNorm;
    const double* volume = this->volume;
    const double* e = this->e;
    const double* omega = this->omega;
    const SymmTensor<Dim>* tau = this->tau;
    const double* pressureJ = pressureTerm;
    const bool differenceForm = this->differenceForm;

    parallelForWork(owned, pairCount, [&](std::size_t i) {
        const double Pi = p[i], oi = omega ? omega[i] : 1.0, hi = h[i], ci = c[i], rhoi = rho[i],
                     ei = e ? e[i] : 0.0;
        const double mi = m[i], bi = b[i], invHi = invH[i], gradNormi = gradNorm[i];
        const double pressureI = a[i] * Pi / oi;
        const Vector<Dim> xi = x[i], vi = v[i];
        SphPairSums<Dim> sums;  // sums.force = m_i dv_i/dt
        // Deviatoric stress terms ride in the same pair loop (r, r̂ and dW/dr computed once).
        const Tensor<Dim> taui = tau ? tau[i].full() : Tensor<Dim>::Zero();
        Vector<Dim> stressForce = Vector<Dim>::Zero();
        double continuity = 0;
        for (const auto j : rows[i]) {
            const Vector<Dim> xij = xi - x[j];
            const double r = xij.norm();
            if (r == 0) continue;  // coincident particles exert no pairwise force
            // Every term carries ∇W(h_i) or ∇W(h_j): a candidate beyond both supports adds zeros.
            const double ui = r * invHi, uj = r * invH[j];
            if (ui >= 1.0 && uj >= 1.0) continue;
            double w, dwi, dwj;
            W.shape(ui, w, dwi);
            W.shape(uj, w, dwj);
            const double dWi = gradNormi * dwi, dWj = gradNorm[j] * dwj;
            const Vector<Dim> rhat = xij * (1.0 / r);
            const Vector<Dim> vij = vi - v[j];
            const double vr = vij.dot(rhat);
            continuity += b[j] * vr * dWi;
            if (tau) stressForce += volume[j] * (dWi * (taui * rhat) + dWj * (tau[j].full() * rhat));
            if (differenceForm)
                sums.force -= (mi / rhoi * volume[j] * (p[j] - Pi) * dWi) * rhat;
            else
                sums.force -= (pressureI * b[j] * dWi + bi * pressureJ[j] * dWj) * rhat;
            dissipation.pair(
                *this,
                SphPair<Dim>{i, std::size_t(j), xij, r, rhat, vij, vr, dWi, dWj, mi, rhoi, Pi, ci, hi, ei},
                sums);
        }
        const double drho = cc[i] / oi * continuity;
        drhodt[i] = drho + sums.massFlux;
        dvdt[i] = sums.force / mi;
        dedt[i] = Pi / (rhoi * rhoi) * drho + sums.heating;
        if (tau) {
            dvdt[i] += stressForce / rhoi;
            if (artificialStress) {
                Vector<Dim> extra = Vector<Dim>::Zero();
                double work = 0;  // −½ Σ_j v_ij·(pair force)/m_i: the energy the pair force moves, kept
                for (const auto j : rows[i]) {
                    const Vector<Dim> xij = x[i] - x[j];
                    const double r = xij.norm();
                    if (r == 0) continue;
                    const double hBar = 0.5 * (hi + h[j]);
                    const double f = std::pow(W.W(r, hBar) / W.W(hBar / eta, hBar), artificialStressExponent);
                    const double gradBar = 0.5 * (W.dWdr(r, hi) + W.dWdr(r, h[j]));
                    const Vector<Dim> pairForce =
                        m[j] * f * gradBar / r * ((artificialStress[i] + artificialStress[j]) * xij);
                    extra += pairForce;
                    work -= 0.5 * (v[i] - v[j]).dot(pairForce);
                }
                dvdt[i] += extra;
                if (e) dedt[i] += work;
            }
            dedt[i] += (taui.cwiseProduct(velocityGradient[i])).sum() / rhoi;
        }
    });
}

}  // namespace mfdyn
