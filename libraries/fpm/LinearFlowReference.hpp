#pragma once
// The exact references of fpmSolid's academic validations (von Nida 2005 §6.1.4, §6.2.2, §7.3;
// doc/methods/fpm.md §4.4, §4.6, §4.10): a linear velocity field v = A x on a body of uniform
// rho, p, e and S. Every spatial derivative the parts take is then uniform and exact for a fit
// that reproduces linear fields, the upwind corrections vanish (R3), div S = grad p = 0, and the
// state stays uniform; it follows the ODE of the split system with the velocity gradient
//
//     G(t) = A                       frozen particles (the thesis's "claimed" solutions)
//     G(t) = A (I + t A)^-1          particles moving ballistically, x(t) = (I + t A) x0
//
// and, for the parts that run (Euler H, shear S, rotation R; doc/methods/fpm.md §3.1):
//
//     rho' = -rho tr G                                           (H)
//     p'   = -rho c^2 tr G                                       (H; c^2 as the Euler part takes it)
//          + (g/rho) (S - [literal] p I) : G                     (S; (5.48))
//     S'   = 2 mu (sym G - alpha tr G I)                         (S; (5.49))
//          + W S - S W,  W = skew G                              (R)
//     e'   = -p tr G / rho                                       (H)
//          + S : sym G / rho                                     (S)
//
// with c^2 and g from the material's equation of state at (rho, e). The reference integrates it
// with classical Runge-Kutta in steps of at most 1e-3 (its error, O(h^4),
// below 1e-12 relative for the note's cases), so the difference to the solver is the scheme's.
// The split is exact here: the parts' flows commute to O(dt^2) only, but the reference is of the
// unsplit ODE, so the forward-Euler and splitting errors of the solver are both what it measures.
#include "core/Tensor.hpp"

#include <functional>

namespace mfdyn {
class EquationOfState;
}

namespace mfdyn::fpm {

template <int Dim>
struct UniformState {
    double rho = 1, p = 0, e = 0;
    SymmTensor<Dim> S{};
};

template <int Dim>
class LinearFlowReference {
public:
    struct Parts {
        bool euler = false, shear = false, rotation = false;
        bool literal = false;  // the Euler part's c^2 = dp/drho|e, and p I in (5.48)
    };
    // eos may be null (then c^2 = g = 0); mu the shear modulus, alpha the deviator's trace weight.
    LinearFlowReference(const Tensor<Dim>& A, bool moving, Parts parts, const EquationOfState* eos, double mu,
                        double alpha, UniformState<Dim> start);

    // The state at time t (from t = 0), and the state s of time t0 carried on to t1.
    UniformState<Dim> at(double t) const { return advanced(start_, 0.0, t); }
    UniformState<Dim> advanced(UniformState<Dim> s, double t0, double t1) const;
    // The velocity gradient at time t.
    Tensor<Dim> gradient(double t) const;

private:
    UniformState<Dim> rate(double t, const UniformState<Dim>& s) const;

    Tensor<Dim> A_;
    bool moving_;
    Parts parts_;
    const EquationOfState* eos_;
    double mu_, alpha_;
    UniformState<Dim> start_;
};

}  // namespace mfdyn::fpm
