#pragma once
// Numerical dissipation of the total-Lagrangian mixed SPH: the family `dissipation` of the method
// tlSph ("dissipation (tlSph)" in listings; impactSph has a family of the same name), in
// constant/tlSphProperties:
//
//     dissipation { type jst; momentum (0 0.125); jacobian (0 0); }      // (eps2 eps4) per variable
//     dissipation { type jst; momentumSpeed shear; jacobian (0 0.125); } // D(p) on c_s, D(J) on c_p
//     dissipation { type artificialViscosity; viscosity 50; }           // mu_vis [Pa s]
//     dissipation { type none; }
//
// A model is behaviour evaluated per block of particles, as an equation of state's evaluate():
// it says which discrete operators of p = rho0 v and of J it needs (the corrected Laplacian
// L[U]_a = sum_b V_b (U_b - U_a) Lap~W_b(X_a) and the bi-Laplacian L^2[U] = L[L[U]]), the solver
// computes those in its pair loops, and evaluate() turns them, with c_p (or c_s), h and rho0, into the rates
// D(p) and D(J) that the solver adds to dp/dt and dJ/dt (after its conservation projections). The
// equations of each model are at the top of its .cpp (JstDissipation.cpp, ArtificialViscosity.cpp).
#include "core/KeywordSchema.hpp"
#include "core/Registry.hpp"

#include <cstddef>
#include <memory>
#include <string>

namespace mfdyn {

class TlDissipation {
public:
    static constexpr const char* familyName = "dissipation";
    static constexpr const char* methodName = "tlSph";
    using Selector = Registry<TlDissipation, const Dictionary&>;
    static std::unique_ptr<TlDissipation> New(const Dictionary& dict);
    virtual ~TlDissipation();

    // The operators evaluate() reads (the solver computes only those).
    virtual bool needsMomentumLaplacian() const { return false; }
    virtual bool needsMomentumBiLaplacian() const { return false; }
    virtual bool needsJacobianLaplacian() const { return false; }
    virtual bool needsJacobianBiLaplacian() const { return false; }
    // Whether evaluate() writes D(p), D(J) at all (the solver then adds them to the rates).
    virtual bool actsOnMomentum() const { return needsMomentumLaplacian(); }
    virtual bool actsOnJacobian() const { return needsJacobianLaplacian(); }

    // One block of particles. Vectors are `dimension` doubles per particle, contiguous. An operator
    // the model did not ask for is null; so are lapJ, lap2J and dissipationJ when the formulation
    // does not evolve J.
    struct Block {
        std::size_t size = 0;
        int dimension = 3;
        double waveSpeed = 0;   // c_p, the largest p-wave speed [m/s]
        double shearSpeed = 0;  // c_s, the largest shear-wave speed sqrt(mu/rho0) [m/s]
        double spacing = 0;     // h, the particle spacing [m]
        const double* rho0 = nullptr;
        const double* lapP = nullptr;    // L[p]
        const double* lap2P = nullptr;   // L^2[p]
        const double* lapJ = nullptr;    // L[J]
        const double* lap2J = nullptr;   // L*[L[J]]: L* the V-adjoint of L (dissipative), on the
                                         // body without its clamped particles (TlSphSolver)
        double* dissipationP = nullptr;  // D(p), written when actsOnMomentum()
        double* dissipationJ = nullptr;  // D(J), written when actsOnJacobian() and J is evolved
    };
    virtual void evaluate(const Block& block) const = 0;

    // A warning for the log when the model is unstable with the time step's Courant number
    // (maxCo, on c_p), else "": shearOverPressure is c_s/c_p (a model may scale a term with c_s),
    // evolvesJ whether the formulation integrates J (so that its D(J) acts).
    virtual std::string stabilityWarning(double courant, double shearOverPressure, bool evolvesJ) const {
        (void)courant, (void)shearOverPressure, (void)evolvesJ;
        return "";
    }
    virtual std::string describe() const = 0;
};

}  // namespace mfdyn
