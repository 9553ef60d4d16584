// JST dissipation for total-Lagrangian mixed SPH (Lee et al. 2016 eqs. 35-38; Jameson, Schmidt,
// Turkel 1981):
//     D(U_a)  = D2 + D4,   D2 = eps2_U c_p h L[U]_a,   D4 = -eps4_U c_p h^3 L^2[U]_a,
// on U = p (eps4_p removes hourglass modes, eps2_p shock over/undershoots) and U = J (pressure
// checkerboarding near incompressibility); D(F) = D(H) = 0 keeps the involutions CURL F = 0,
// DIV H = 0. Defaults are the paper's: momentum (0 1/8), jacobian (0 0).
// Stability of the RK2 scheme needs eps4 > maxCo^3/8 (the note's App. C: the modified
// equation's u_xxxx coefficient -(eps4 - maxCo^3/8) c h^3, maxCo the paper's alpha_CFL); the
// model warns below it. c_p is the largest p-wave speed, h the particle spacing, L the corrected
// Laplacian (TlDissipation.hpp); per particle a, with k2 = eps2 c_p h and k4 = eps4 c_p h^3:
//     D(p)_a = k2_p L[p]_a - k4_p L^2[p]_a,   D(J)_a = k2_J L[J]_a - k4_J L*[L[J]]_a,
// with L* the V-adjoint of L (sum_a V_a W_a L[U]_a = sum_a V_a U_a L*[W]_a), so that
// sum V J D4(J) = -k4 sum V L[J]^2 <= 0: the J term only dissipates (with the law's pressure
// taken at J, the energy kappa/2 (J - 1)^2), and its volume mean is zero. The solver computes it
// on the body without the clamped (fixed) particles, whose J stays det F (issue 16).
//
// The wave speed of the momentum term (`momentumSpeed`, issue 16). Lee et al. scale every term
// with c_p (eqs. 35-38; the note's §2.4); we keep that as the default (`pressure`). D(p) acts on the
// whole velocity field, and in a nearly incompressible solid its smooth motion (bending, shear) is
// carried by c_s, while c_p/c_s = sqrt(kappa/mu + 4/3) grows without bound (3.3 at nu 0.45, 22.4 at
// nu 0.499): k4 = eps4 c_p h^3 then damps a bending plate 22 times more than its own waves need
// (the plate at 4 mm lost 8.5% of its energy in 0.3 s at nu 0.499). `momentumSpeed shear` takes
// k2_p = eps2_p c_s h, k4_p = eps4_p c_s h^3; the J terms keep c_p, as the volumetric (pressure)
// waves that D(J) smooths travel at c_p.
// Stability [D]: a pressure wave is carried by two equations, p and J ({p,F,J}; p and F in {p,F}),
// and the RK2 amplification of the pair u_t = c w_x - a u, w_t = c u_x - b w (a, b the damping
// rates of the two terms at wavenumber k) is that of the scalar equation of App. C with damping
// (a + b)/2: the short pressure waves need (eps4_p c/c_p + eps4_J)/2 > maxCo^3/8, c the momentum
// term's speed (eps4_J = 0 in {p,F}). With c = c_p and eps4_p = 1/8 that holds to maxCo 0.79 and
// we keep the old warning (the scalar floor). With c = c_s that floor is necessary but not enough:
// measured, the pressure-wave coefficient eps4_p c_s/c_p + eps4_J must stay near the paper's 1/8
// on c_p. At nu 0.499 the 4 mm plate in {p,F,J} ran with eps4_J 1/16 (coefficient 0.068) and grew
// its energy 2.3e3-fold by 0.2 s with 1/32 (0.037) and 2.5e5-fold with 0 (0.0056); the bending
// column (3 x 13 x 3) in {p,F} at maxCo 0.15 (0.0056, the App. C floor 4.2e-4) grew 170-fold by
// 1.5 s. So the model warns when the coefficient is below 1/16 or below the App. C floor: use a
// jacobian eps4 in {p,F,J} (1/8, the nearly incompressible punch's), or momentumSpeed pressure.
// The shear waves see maxCo c_s/c_p and eps4_p on c_s: they are safe whenever the pressure waves are.
#include "tlSph/JstDissipation.hpp"

#include "core/Parallel.hpp"

#include <sstream>
#include <vector>

namespace mfdyn {

KeywordSchema JstDissipation::keywords() {
    return KeywordSchema(familyName, "jst")
        .vector("momentum", "-", "(eps2_p eps4_p): Laplacian and bi-Laplacian coefficients on p")
        .atLeast(0)
        .ofLength(2)
        .orDefault(std::vector<double>{0.0, 0.125})
        .vector("jacobian", "-", "(eps2_J eps4_J): Laplacian and bi-Laplacian coefficients on J")
        .atLeast(0)
        .ofLength(2)
        .orDefault(std::vector<double>{0.0, 0.0})
        .word("momentumSpeed", {"pressure", "shear"},
              "the wave speed c of the momentum terms: c_p (the paper's) or c_s = sqrt(mu/rho0) "
              "(nearly incompressible bodies in bending); the J terms use c_p")
        .orDefault("pressure");
}

JstDissipation::JstDissipation(const Dictionary& dict) {
    const KeywordValues v = keywords().read(dict);
    momentum2_ = v.vector("momentum")[0];
    momentum4_ = v.vector("momentum")[1];
    jacobian2_ = v.vector("jacobian")[0];
    jacobian4_ = v.vector("jacobian")[1];
    momentumOnShear_ = v.word("momentumSpeed") == "shear";
}

void JstDissipation::evaluate(const Block& b) const {
    const double c = b.waveSpeed, h = b.spacing;
    const int d = b.dimension;
    if (b.dissipationP && b.lapP) {
        const double cp = momentumOnShear_ ? b.shearSpeed : c;
        const double k2 = momentum2_ * cp * h, k4 = momentum4_ * cp * h * h * h;
        parallelFor(b.size, [&](std::size_t a) {
            for (int i = 0; i < d; ++i) {
                double D = k2 * b.lapP[a * d + i];
                if (b.lap2P) D -= k4 * b.lap2P[a * d + i];
                b.dissipationP[a * d + i] = D;
            }
        });
    }
    if (b.dissipationJ && b.lapJ) {
        const double k2 = jacobian2_ * c * h, k4 = jacobian4_ * c * h * h * h;
        parallelFor(b.size, [&](std::size_t a) {
            double D = k2 * b.lapJ[a];
            if (b.lap2J) D -= k4 * b.lap2J[a];
            b.dissipationJ[a] = D;
        });
    }
}

std::string JstDissipation::stabilityWarning(double courant, double shearOverPressure, bool evolvesJ) const {
    const double floor = courant * courant * courant / 8;
    if (!momentumOnShear_) {
        if (!(momentum4_ > 0 && momentum4_ <= floor)) return "";
        return "JST momentum eps4 " + std::to_string(momentum4_) +
               " is at or below maxCo^3/8 = " + std::to_string(floor) +
               ": the RK2 scheme is anti-diffusive at short wavelengths (doc/methods/tl-jst-sph.md App. C)";
    }
    // On c_s the pressure waves see eps4_p c_s/c_p from D(p), plus eps4_J from D(J) if J is
    // evolved; RK2 needs half their sum above the floor, and the runs above at least 1/16.
    const double onPressure = momentum4_ * shearOverPressure + (evolvesJ ? jacobian4_ : 0.0);
    if (!(momentum4_ > 0 && (onPressure < 0.0625 || onPressure / 2 <= floor))) return "";
    return "JST momentum eps4 " + std::to_string(momentum4_) +
           " on c_s (momentumSpeed shear, c_s/c_p = " + std::to_string(shearOverPressure) + ")" +
           (evolvesJ ? " with the jacobian eps4 " + std::to_string(jacobian4_)
                     : std::string(" without D(J)")) +
           " leaves the pressure waves eps4_p c_s/c_p + eps4_J = " + std::to_string(onPressure) +
           ": below 1/16 (where measured runs blew up) or at most twice maxCo^3/8 = " +
           std::to_string(floor) +
           " (the RK2 floor, doc/methods/tl-jst-sph.md App. C); use a jacobian eps4 in pFJ (1/8), "
           "or momentumSpeed pressure";
}

std::string JstDissipation::describe() const {
    std::ostringstream s;
    s << "jst: momentum (" << momentum2_ << " " << momentum4_ << "), jacobian (" << jacobian2_ << " "
      << jacobian4_ << ")" << (momentumOnShear_ ? ", momentum on c_s" : "");
    return s.str();
}

MFDYN_REGISTER(TlDissipation, JstDissipation, "jst",
               "JST: eps2 c h L[U] - eps4 c h^3 L^2[U] on p and J (Lee et al. 2016; c = c_p, or c_s on p)");

}  // namespace mfdyn
