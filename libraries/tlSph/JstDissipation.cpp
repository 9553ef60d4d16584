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

namespace {

void readPair(const Dictionary& dict, const char* key, double& eps2, double& eps4) {
    if (!dict.found(key)) return;
    const auto v = dict.get<std::vector<double>>(key);
    if (v.size() != 2) throw dict.error(key, "expected (eps2 eps4), two non-negative numbers");
    if (v[0] < 0 || v[1] < 0) throw dict.error(key, "JST coefficients must be non-negative");
    eps2 = v[0], eps4 = v[1];
}

}  // namespace

JstDissipation::JstDissipation(const Dictionary& dict) {
    c_.momentum4 = 0.125;
    readPair(dict, "momentum", c_.momentum2, c_.momentum4);
    readPair(dict, "jacobian", c_.jacobian2, c_.jacobian4);
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
