#pragma once
// How each particle's smoothing length follows the flow (the family `smoothingLength`; Zisis
// 2017 §4.1; doc/methods/sph-impact.md §2):
//
//     smoothingLength { type massDensity; eta 1.2; }
//
//     fixed           h stays at its initial value (`h`, else η (m/ρ)^{1/d})
//     massDensity     h_i = η (m_i/ρ_i)^{1/d}                 (4.2)
//     numberDensity   h_i = η ñ_i^{-1/d}, ñ_i = Σ_j W_ij(h_i)  (4.1), from the last neighbour sum
//     summation       h_i and ρ_i solved together (4.3–4.8), by the solver, which has the neighbours
//
// Each law's equations and keywords are in its own .cpp and in doc/models/smoothingLength/. η is
// relative to the kernel's own h (with the default Gaussian, h = 1.2 Δx for η = 1.2).
#include "core/KeywordSchema.hpp"
#include "core/Registry.hpp"

#include <cstddef>
#include <memory>

namespace mfdyn {

class SmoothingLengthLaw {
public:
    static constexpr const char* familyName = "smoothingLength";
    using Selector = Registry<SmoothingLengthLaw, const Dictionary&>;
    static std::unique_ptr<SmoothingLengthLaw> New(const Dictionary& dict) { return Selector::New(dict); }

    virtual ~SmoothingLengthLaw();

    // New h for n particles in `dim` dimensions. numberDensity may be null when the law does not
    // need it (needsNumberDensity()).
    virtual void update(int dim, std::size_t n, const double* mass, const double* rho,
                        const double* numberDensity, double* h) const = 0;
    virtual bool needsNumberDensity() const { return false; }
    // True when h must be solved with the density sums (the solver does it: it owns the sums).
    virtual bool iterative() const { return false; }
    // The Newton iteration's relative tolerance on h and its iteration limit (summation only).
    virtual double tolerance() const { return 0.0; }
    virtual int maxIterations() const { return 0; }
    // The initial h of a particle with this mass and density (fixed: the `h` keyword).
    virtual double initial(int dim, double mass, double rho) const = 0;

    double eta() const { return eta_; }

protected:
    explicit SmoothingLengthLaw(double eta) : eta_(eta) {}
    // The schema of η, shared by every law: `eta`, default 1.2.
    static KeywordSchema etaKeyword(const char* type);
    // x^{1/dim}
    static double dimensionRoot(double x, int dim);

private:
    double eta_;
};

}  // namespace mfdyn
