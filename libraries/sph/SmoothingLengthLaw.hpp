#pragma once
// How each particle's smoothing length follows the flow (Zisis 2017 §4.1; sph-impact.md §2):
//
//     smoothingLength { type massDensity; eta 1.2; }
//
//     fixed           h stays at its initial value (the `smoothingLength` field, or `h`)
//     massDensity     h_i = η (m_i/ρ_i)^{1/d}                 (4.2)
//     numberDensity   h_i = η ñ_i^{-1/d}, ñ_i = Σ_j W_ij(h_i)  (4.1), from the last neighbour sum
//     summation       h_i and ρ_i solved together: c_i Σ_j b_j W_ij(h_i) = m_i (η/h_i)^d  (4.3–4.8),
//                     per particle by Newton's method with a bisection fallback, |Δh|/h < tolerance
//                     (the thesis gives no algorithm; sph-impact.md §2 [S]); by the solver, which
//                     has the neighbours
//
// η is relative to the kernel's own h (with the default Gaussian, h = 1.2 Δx for η = 1.2).
#include "core/Registry.hpp"

#include <cstddef>
#include <memory>

namespace mfdyn {

class SmoothingLengthLaw {
public:
    static constexpr const char* familyName = "smoothingLength";
    using Selector = Registry<SmoothingLengthLaw, const Dictionary&>;
    static std::unique_ptr<SmoothingLengthLaw> New(const Dictionary& dict) { return Selector::New(dict); }

    explicit SmoothingLengthLaw(const Dictionary& dict);
    virtual ~SmoothingLengthLaw();

    // New h for n particles in `dim` dimensions. numberDensity may be null when the law does not
    // need it (needsNumberDensity()).
    virtual void update(int dim, std::size_t n, const double* mass, const double* rho, const double* numberDensity,
                        double* h) const = 0;
    virtual bool needsNumberDensity() const { return false; }
    // True when h must be solved with the density sums (the solver does it: it owns the sums).
    virtual bool iterative() const { return false; }
    double tolerance() const { return tolerance_; }
    int maxIterations() const { return maxIterations_; }
    // The initial h of a particle with this mass and density (fixed: the `h` keyword).
    virtual double initial(int dim, double mass, double rho) const = 0;

    double eta() const { return eta_; }

private:
    double eta_;
    double tolerance_;
    int maxIterations_;
};

}  // namespace mfdyn
