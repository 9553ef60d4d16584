#pragma once
// The shear (deviatoric, S) part of fpmSolid's split (von Nida 2005 §5.2; doc/methods/fpm.md §3.3):
// dimensional upwinding. A single upwind direction cannot make the shear system's four
// characteristic sources vanish together (§5.2.2), so the part averages d upwinded evaluations,
// one along each axis e_l (Def. 5.2, (5.38)). With c_S = sqrt(mu/rho0) the transversal wave speed,
// Z = sqrt(mu rho0) the shear impedance and the shift length l = delta c_S (delta a time) or
// l = deltaFraction h, clamped to maxShift h, the fit of the value form is rebuilt at
// x_i - l e_l (Pi_l+) and x_i + l e_l (Pi_l-), Pi_l^c = (Pi_l+ + Pi_l-)/2, and, with no sum over j
// in the corrections (the 2D (5.50)-(5.53) with 1/2 -> 1/d, the note's [R] for 3D):
//
//     d_j v_D^(i)  = (1/d) sum_l Pi_l^c d_j v_i - (1/(d Z)) (Pi_j+ d_j S^ij - Pi_j- d_j S^ij)/2   (5.50)
//     d_j S_D^(ij) = (1/d) sum_l Pi_l^c d_j S^ij - (Z/d)     (Pi_j+ d_j v_i  - Pi_j- d_j v_i)/2    (5.51)
//     v_D^(i)      = (1/d) sum_l Pi_l^c v_i          [- (1/(d Z)) sum_l (Pi_l+ S^il - Pi_l- S^il)/2]  (5.52)
//
// The bracket of (5.52) is the consistent analogue of the Euler part's upwind velocity (5.22),
// which the thesis prints without (the note's §7 item 7): `velocity printed` leaves it out,
// `velocity corrected` adds it; for linear fields both equal v (R3 of §4b). The signs follow from
// the characteristic variables of the 1D pair (v_i, S^ij) along e_j, w = Z v -+ S, which travel
// along -+e_j: Pi_j- (data from x + l e_j) for Z v + S, Pi_j+ for Z v - S.
//
// The update (ShearPart::advance; forward Euler from the step's start values rho0, p0, S0):
//
//     v_i += dt (1/rho0) sum_j d_j S_D^ij                                        (5.47)
//     p   += dt (g/rho0) sigma0 : grad v_D,  sigma0 = S0 - p0 I                  (5.48)
//     S   += dt 2 mu (sym grad v_D - alpha tr(grad v_D) I)                       (5.49, alpha = 1/d)
//     e   += dt S0 : sym grad v_D / rho0                                         (the deviatoric work)
//
// With `literalSoundSpeed` false (the Euler part takes the isentropic c^2 = dp/drho|_e + g p/rho^2,
// which holds the -(g p/rho) div v part already) the p0 I term of (5.48) is left out, so that it is
// not counted twice. A particle whose shifted fits fail (a shifted point beyond the cloud's edge:
// fewer than 2(d+1) neighbours with a positive weight, or singular) is tried again with half the
// shift, up to `shortenings` times (the shift "clamped inside the support"), then evaluated
// centrally; both counted. Caveats stated by the note and kept as the thesis has them: in 3D the
// longitudinal pair (v_l, S^ll) travels at sqrt(4 mu/(3 rho0)), not c_S; and a particle with mu = 0
// is not shifted (central values, no correction: its S stays what it is).
#include "core/Tensor.hpp"
#include "meshfreeOperators/LeastSquaresOperators.hpp"
#include "meshfreeOperators/fitWeights/FitWeight.hpp"
#include "particles/NeighbourList.hpp"

#include <cstddef>
#include <vector>

namespace mfdyn::fpm {

struct ShearOptions {
    bool deltaIsTime = true;         // l = delta c_S; else l = delta h
    double delta = 0.3;              // s (deltaIsTime) or - (a fraction of h)
    double maxShift = 0.5;           // l <= maxShift h
    bool correctedVelocity = false;  // v_D with the bracket of (5.52)
    bool literalSoundSpeed = true;   // (5.48) with sigma0 = S0 - p0 I (else S0 only)
    int shortenings = 3;             // a failed shifted fit: retried with l/2, l/4, ... this often
    bool central = false;            // no upwinding (the thesis's failing central scheme, R9)
    // The shifted fits' least reciprocal condition lambda_min / lambda_max of the scaled moment
    // matrix: a shifted point beyond a free surface sees nearly one plane of particles, a fit whose
    // normal gradient is ill-determined (1e-9 passes the central fit's 1e-10 and gave a surface
    // particle v_z = -23 in one step of the coupled shearing sphere); below it the fit fails (then
    // shortened or central). The note's [R] asks cond(M) < 1e8; 1e-6 is what the sphere needs.
    double shiftedFitCondition = 1e-6;
};

template <int Dim>
struct ShearUpwind {
    std::vector<Tensor<Dim>> gradV;     // d_j v_D^(i)
    std::vector<Vector<Dim>> divS;      // sum_j d_j S_D^ij
    std::vector<Vector<Dim>> vD;        // the dimensional velocity (the chosen variant)
    std::vector<Vector<Dim>> vCorrect;  // the bracket of (5.52) (0 where central)
    std::vector<double> shift;          // l (0 where central)
    std::size_t tooFew = 0;             // central: a shifted fit failed at every shortened shift
    std::size_t unstrained = 0;         // central: mu = 0
    std::size_t shortened = 0;          // upwinded with a shortened shift
};

template <int Dim>
class ShearPart {
public:
    // fit: the central fit's options (value form); the shifted fits take them with no fallback and
    // failures flagged.
    ShearPart(typename LeastSquaresOperators<Dim>::Options fit, ShearOptions shear);

    // rows[i]: the neighbours of particle i within (1 + maxShift) h at least; gradV, divS: the
    // central fit's grad v and div S at the particles; mu: each particle's shear modulus. The
    // particles evaluated are the rows' (rows.size()); x, v and S may hold more particles, read as
    // neighbours only (another rank's halo).
    void upwind(const std::vector<Vector<Dim>>& x, const NeighbourList& rows, double h,
                const FitWeight& weight, const std::vector<double>& rho, const std::vector<Vector<Dim>>& v,
                const std::vector<SymmTensor<Dim>>& S, const std::vector<double>& mu,
                const std::vector<Tensor<Dim>>& gradV, const std::vector<Vector<Dim>>& divS);
    const ShearUpwind<Dim>& result() const { return result_; }

    // The forward-Euler update of (5.47)-(5.49) from the last upwind(); g: each particle's
    // dp/de|rho, alpha the deviator's trace weight (1/d); e may be null.
    void advance(double dt, const std::vector<double>& rho, std::vector<Vector<Dim>>& v,
                 std::vector<double>& p, std::vector<SymmTensor<Dim>>& S, std::vector<double>* e,
                 const std::vector<double>& g, const std::vector<double>& mu, double alpha) const;

    // div S at the particles from a fit (the d components of each row of S).
    static std::vector<Vector<Dim>> divergence(const LeastSquaresOperators<Dim>& fit,
                                               const std::vector<SymmTensor<Dim>>& S);

    const ShearOptions& options() const { return shear_; }

private:
    // The upwinded values of the particles `active` at their shifts r.shift; returns those whose
    // shifted fits failed (untouched).
    std::vector<std::size_t> evaluate(const std::vector<std::size_t>& active,
                                      const std::vector<Vector<Dim>>& x, const NeighbourList& rows, double h,
                                      const FitWeight& weight, const std::vector<double>& rho,
                                      const std::vector<Vector<Dim>>& v,
                                      const std::vector<SymmTensor<Dim>>& S, const std::vector<double>& mu);

    ShearOptions shear_;
    LeastSquaresOperators<Dim> shifted_;
    ShearUpwind<Dim> result_;
};

}  // namespace mfdyn::fpm
