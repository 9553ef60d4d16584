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
        .orDefault(std::vector<double>{0.0, 0.0});
}

JstDissipation::JstDissipation(const Dictionary& dict) {
    const KeywordValues v = keywords().read(dict);
    momentum2_ = v.vector("momentum")[0];
    momentum4_ = v.vector("momentum")[1];
    jacobian2_ = v.vector("jacobian")[0];
    jacobian4_ = v.vector("jacobian")[1];
}

void JstDissipation::evaluate(const Block& b) const {
    const double c = b.waveSpeed, h = b.spacing;
    const int d = b.dimension;
    if (b.dissipationP && b.lapP) {
        const double k2 = momentum2_ * c * h, k4 = momentum4_ * c * h * h * h;
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

std::string JstDissipation::stabilityWarning(double courant) const {
    const double floor = courant * courant * courant / 8;
    if (!(momentum4_ > 0 && momentum4_ <= floor)) return "";
    return "JST momentum eps4 " + std::to_string(momentum4_) +
           " is at or below maxCo^3/8 = " + std::to_string(floor) +
           ": the RK2 scheme is anti-diffusive at short wavelengths (doc/methods/tl-jst-sph.md App. C)";
}

std::string JstDissipation::describe() const {
    std::ostringstream s;
    s << "jst: momentum (" << momentum2_ << " " << momentum4_ << "), jacobian (" << jacobian2_ << " "
      << jacobian4_ << ")";
    return s.str();
}

MFDYN_REGISTER(TlDissipation, JstDissipation, "jst",
               "JST: eps2 c h L[U] - eps4 c h^3 L^2[U] on p and J (Lee et al. 2016)");

}  // namespace mfdyn
