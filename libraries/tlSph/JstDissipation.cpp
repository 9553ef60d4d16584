// JST dissipation for total-Lagrangian mixed SPH (Lee et al. 2016 eqs. 35-38; Jameson, Schmidt,
// Turkel 1981):
//     D(U_a)  = D2 + D4,   D2 = eps2_U c_p h L[U]_a,   D4 = -eps4_U c_p h^3 L^2[U]_a,
// on U = p (eps4_p removes hourglass modes, eps2_p shock over/undershoots) and U = J (pressure
// checkerboarding near incompressibility); D(F) = D(H) = 0 keeps the involutions CURL F = 0,
// DIV H = 0. Defaults are the paper's: momentum (0 1/8), jacobian (0 0).
// Stability of the RK2 scheme needs eps4 > alpha_CFL^3/8 (the note's App. C: the modified
// equation's u_xxxx coefficient -(eps4 - alpha^3/8) c h^3); the solver warns below it.
#include "tlSph/JstDissipation.hpp"

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
    c_.momentum2 = v.vector("momentum")[0];
    c_.momentum4 = v.vector("momentum")[1];
    c_.jacobian2 = v.vector("jacobian")[0];
    c_.jacobian4 = v.vector("jacobian")[1];
}

std::string JstDissipation::describe() const {
    std::ostringstream s;
    s << "jst: momentum (" << c_.momentum2 << " " << c_.momentum4 << "), jacobian (" << c_.jacobian2 << " "
      << c_.jacobian4 << ")";
    return s.str();
}

MFDYN_REGISTER(TlDissipation, JstDissipation, "jst",
               "JST: eps2 c h L[U] - eps4 c h^3 L^2[U] on p and J (Lee et al. 2016)");

}  // namespace mfdyn
