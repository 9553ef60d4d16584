#pragma once
// The Euler (volumetric, H) part of fpmSolid's split (von Nida 2005 §5.1; doc/methods/fpm.md §3.2):
// pressure-gradient upwinding. With n = grad p / |grad p| (the central fit's gradient at the
// particle), c the particle's sound speed and the shift length l = delta c (delta a time) or
// l = deltaFraction h, clamped to maxShift h (0.5 h, the note's [R]), the fit of the value form is
// rebuilt at the shifted points x_i - l n (Pi+) and x_i + l n (Pi-), and (5.20)-(5.23):
//
//     div v_uw = (tr Pi+ grad v + tr Pi- grad v)/2 + (1/(rho c)) n.(Pi+ grad p - Pi- grad p)/2
//     grad p_uw = (Pi+ grad p + Pi- grad p)/2 + rho c n sum_ik n_i n_k (Pi+ d_k v_i - Pi- d_k v_i)/2
//     v_uw - Pi^c v = (1/(rho c)) ((Pi+ p - Pi- p)/2) n          (the upwind velocity's correction)
//     p_uw - Pi^c p = rho c ((Pi+ v - Pi- v)/2).n
//
// The first two are what the update uses (EulerPart::advance: rho -= dt rho div v_uw,
// v -= dt grad p_uw / rho, p -= dt rho c^2 div v_uw, e -= dt p div v_uw / rho, all from the
// step's start values); v_uw (the particle's own v where central) moves the particles with
// `motion { velocity upwind; }`; the two corrections are returned for the tests. Central
// evaluation (the particle's own central gradients, no correction) where |grad p| <= gradientFloor
// x (|p| + pScale) / h (the corrections vanish there anyway, the note's [R]), or
// where a shifted fit fails (fewer than 2(d+1) neighbours with a positive weight, or a reciprocal
// condition below shiftedFitCondition) at l, l/2, l/4 and l/8 (the shortened shifts, counted):
// both counted. For linear v and p the derivative corrections vanish to round-off (R3 of §4b).
#include "core/Tensor.hpp"
#include "meshfreeOperators/LeastSquaresOperators.hpp"
#include "meshfreeOperators/fitWeights/FitWeight.hpp"
#include "particles/NeighbourList.hpp"

#include <cmath>
#include <cstddef>
#include <vector>

namespace mfdyn::fpm {

// The upwind direction n (§3.2): along grad p (the thesis's, its only stable choice), or its failing
// alternatives kept as negative controls (§4.1, R9 of §4b): `minimisation`, the direction s that
// minimises |s^T E s| with E = tr(epsdot) I - epsdot (5.25)-(5.27) (a zero of the form where E has
// eigenvalues of both signs, else the eigenvector of the eigenvalue of least magnitude), and
// `central`, no upwinding at all (every particle evaluated centrally).
enum class UpwindDirection { gradient, minimisation, central };

struct UpwindOptions {
    UpwindDirection direction = UpwindDirection::gradient;
    bool deltaIsTime = true;       // l = delta c; else l = delta h
    double delta = 0.3;            // s (deltaIsTime) or - (a fraction of h)
    double maxShift = 0.5;         // l <= maxShift h
    double gradientFloor = 1e-10;  // |grad p| h <= floor (|p| + pScale): central
    int shortenings = 3;           // a failed shifted fit: retried with l/2, l/4, ... this often
    double pScale = 0;             // the pressure scale added to |p| in the floor
    // The shifted fits' least reciprocal condition lambda_min / lambda_max of the scaled moment
    // matrix: a shifted point beyond a free surface sees nearly one plane of particles, a fit whose
    // normal gradient is ill-determined (1e-9 passes the central fit's 1e-10 and gave a surface
    // particle v_z = -23 in one step of the coupled shearing sphere); below it the fit fails (then
    // shortened or central). The note's [R] asks cond(M) < 1e8; 1e-6 is what the sphere needs.
    double shiftedFitCondition = 1e-6;
};

template <int Dim>
struct EulerUpwind {
    std::vector<double> divV;           // div v_uw
    std::vector<Vector<Dim>> gradP;     // grad p_uw
    std::vector<Vector<Dim>> vCorrect;  // v_uw - Pi^c v
    std::vector<double> pCorrect;       // p_uw - Pi^c p
    std::vector<Vector<Dim>> vUpwind;   // v_uw = Pi^c v + vCorrect (central: the particle's v)
    std::vector<double> shift;          // l (0 where central)
    std::size_t flat = 0;               // central: |grad p| ~ 0
    std::size_t tooFew = 0;             // central: a shifted fit failed at every shortened shift
    std::size_t shortened = 0;          // upwinded with a shortened shift
};

template <int Dim>
class EulerPart {
public:
    // fit: the central fit's options (value form); the shifted fits take them with no fallback and
    // failures flagged.
    EulerPart(typename LeastSquaresOperators<Dim>::Options fit, UpwindOptions upwind);

    // rows[i]: the neighbours of particle i within (1 + maxShift) h at least (the shifted points'
    // neighbours within h are among them); gradP, gradV: the central fit's gradients at the particles.
    // The particles evaluated are the rows' (rows.size()); x, p and v may hold more particles,
    // read as neighbours only (another rank's halo).
    void upwind(const std::vector<Vector<Dim>>& x, const NeighbourList& rows, double h,
                const FitWeight& weight, const std::vector<double>& rho, const std::vector<double>& p,
                const std::vector<Vector<Dim>>& v, const std::vector<double>& c,
                const std::vector<Vector<Dim>>& gradP, const std::vector<Tensor<Dim>>& gradV);
    const EulerUpwind<Dim>& result() const { return result_; }
    // Whether particle i is shifted at all (|grad p| above the floor): the caller searches the
    // wider rows only when some particle is.
    bool shifts(double gradPNorm, double p, double h) const {
        return gradPNorm * h > upwind_.gradientFloor * (std::abs(p) + upwind_.pScale);
    }

    // The forward-Euler update from the upwinded divergence and pressure gradient (rho, p and c
    // of the step's start for every particle); e may be null (a barotropic equation of state).
    void advance(double dt, std::vector<double>& rho, std::vector<Vector<Dim>>& v, std::vector<double>& p,
                 std::vector<double>* e, const std::vector<double>& c) const;

    const UpwindOptions& options() const { return upwind_; }

private:
    // The upwinded values of the particles `active` at their shifts; returns those whose shifted
    // fits failed (untouched).
    std::vector<std::size_t> evaluate(const std::vector<std::size_t>& active, const std::vector<Vector<Dim>>& dir,
                                      const std::vector<Vector<Dim>>& x, const NeighbourList& rows, double h,
                                      const FitWeight& weight, const std::vector<double>& rho,
                                      const std::vector<double>& p, const std::vector<Vector<Dim>>& v,
                                      const std::vector<double>& c);

    UpwindOptions upwind_;
    LeastSquaresOperators<Dim> shifted_;
    EulerUpwind<Dim> result_;
};

}  // namespace mfdyn::fpm
