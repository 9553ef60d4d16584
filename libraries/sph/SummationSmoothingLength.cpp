// Smoothing length and density solved together (Zisis 2017 eqs. 4.3-4.8; Springel & Hernquist
// 2002; Price 2012): per particle,
//
//     c_i Σ_j b_j W_ij(h_i) = m_i (η/h_i)^d,
//
// the density sum of the density scheme (c, b its measure) equal to the density the smoothing
// length implies. Solved by SphSolver, which owns the neighbour sums, by Newton's method on h_i
// with a bisection fallback when a step leaves the bracket, to |Δh|/h < tolerance within
// maxIterations (the thesis gives no algorithm; doc/methods/sph-impact.md §2 [S]). The grad-h terms ω_i of
// the density scheme follow from the same sums. The initial h is η (m/ρ)^{1/d}.
#include "sph/SummationSmoothingLength.hpp"

namespace mfdyn {

KeywordSchema SummationSmoothingLength::keywords() {
    return etaKeyword("summation")
        .append(KeywordSchema(familyName, "summation")
                    .scalar("tolerance", "-", "relative change of h that ends the iteration")
                    .greaterThan(0)
                    .orDefault(1e-4)
                    .integer("maxIterations", "-", "Newton/bisection iterations allowed")
                    .atLeast(1)
                    .orDefault(30));
}

SummationSmoothingLength::SummationSmoothingLength(const Dictionary& dict)
    : SummationSmoothingLength(keywords().read(dict)) {}

SummationSmoothingLength::SummationSmoothingLength(const KeywordValues& v)
    : SmoothingLengthLaw(v.scalar("eta")),
      tolerance_(v.scalar("tolerance")),
      maxIterations_(int(v.integer("maxIterations"))) {}

double SummationSmoothingLength::initial(int dim, double mass, double rho) const {
    return eta() * dimensionRoot(mass / rho, dim);
}

MFDYN_REGISTER(SmoothingLengthLaw, SummationSmoothingLength, "summation",
               "h and rho solved together per particle (Newton with bisection fallback)");

}  // namespace mfdyn
