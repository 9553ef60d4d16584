// Tillotson equation of state (Tillotson 1962, "Metallic equations of state for hypervelocity
// impact", General Atomic report GA-3216; as written in Melosh 1989, "Impact Cratering", Appendix
// II, Eqs. AII.1-AII.3, and Brundage 2013, "Implementation of Tillotson Equation of State for
// Hypervelocity Impact of Metals, Geologic Materials, and Liquids", Procedia Eng. 58:461):
//
//     eta = rho/rho0,  mu = eta - 1,  x = rho0/rho - 1,  omega = e/(E0 eta^2) + 1.
//
//   compressed, rho >= rho0, or e <= Eiv (cold expanded states):
//     P_c = (a + b/omega) rho e + A mu + B mu^2
//   expanded, rho < rho0 and e >= Ecv:
//     P_e = a rho e + [b rho e/omega + A mu exp(-beta x)] exp(-alpha x^2)
//   in between, rho < rho0 and Eiv < e < Ecv (Melosh 1989 AII.3, the linear blend in e):
//     P = [(e - Eiv) P_e + (Ecv - e) P_c] / (Ecv - Eiv).
//
// P is continuous everywhere: at e = Eiv and e = Ecv by construction, and at rho = rho0, where
// x = mu = 0 and both branches reduce to (a + b/omega) rho0 e. Its derivatives jump across these
// lines.
//
// `branch compressed` uses P_c for every rho and e: the "partial Tillotson" of von Nida 2005,
// Eq. 2.9 (doc/methods/fpm.md section 1), written there for iron and aluminium near rho0 (alpha,
// beta, Eiv and Ecv are then not used and need not be given). The default, `branch full`, is the
// three regions above.
//
// Derivatives, analytic per branch: on P_c, with omega_e = 1/(E0 eta^2) and e omega_e = omega - 1,
//
//     g = dP_c/de|_rho = rho (a + b/omega^2),
//
// and on P_e, g = a rho + G (b rho/omega - b rho e omega_e/omega^2) = rho (a + G b/omega^2),
// G = exp(-alpha x^2); in the blend g also carries (P_e - P_c)/(Ecv - Eiv). Sound speed:
// c^2 = dP/drho|_e + (P/rho^2) g. On a branch line the branch chosen above is used. c^2 may be
// negative in expanded states (a + b/omega small, the A mu term dominant); it is returned as is and
// the solver decides.
//
// Range: designed for hypervelocity impact (shock pressures of tens to hundreds of GPa and
// vaporisation); it has no phase transitions and in cold tension P_c is unbounded below, so
// `minimumPressure` offers the same cut-off as mieGruneisen (P = max(P, pMin), c^2 uncut; where P
// is cut it does not depend on e, and g = 0).
#include "materials/equationOfState/Tillotson.hpp"

#include <algorithm>
#include <cmath>

namespace mfdyn {

KeywordSchema Tillotson::keywords() {
    return KeywordSchema(familyName, "tillotson")
        .scalar("rho0", "kg/m^3", "reference density")
        .greaterThan(0)
        .orEnclosing()
        .scalar("A", "Pa", "bulk-modulus-like coefficient")
        .greaterThan(0)
        .orEnclosing()
        .scalar("B", "Pa", "second-order coefficient")
        .orEnclosing()
        .scalar("a", "-", "Tillotson constant a (a + b ~ Grueneisen parameter)")
        .orEnclosing()
        .scalar("b", "-", "Tillotson constant b")
        .orEnclosing()
        .scalar("E0", "J/kg", "reference specific energy")
        .greaterThan(0)
        .orEnclosing()
        .word("branch", {"full", "compressed"},
              "full: compressed, expanded and blended regions; compressed: P_c everywhere (von Nida 2005 "
              "Eq. 2.9)")
        .orDefault("full")
        .scalar("alpha", "-",
                "decay constant of the expanded branch, exp(-alpha x^2); required with branch full")
        .atLeast(0)
        .optional()
        .orEnclosing()
        .scalar("beta", "-", "decay constant of the expanded branch, exp(-beta x); required with branch full")
        .atLeast(0)
        .optional()
        .orEnclosing()
        .scalar("Eiv", "J/kg", "specific energy of incipient vaporisation; required with branch full")
        .atLeast(0)
        .optional()
        .orEnclosing()
        .scalar("Ecv", "J/kg", "specific energy of complete vaporisation, > Eiv; required with branch full")
        .optional()
        .orEnclosing()
        .scalar("minimumPressure", "Pa", "tension cut-off pMin: P = max(P, pMin), c^2 uncut, g = 0 where cut")
        .atMost(0)
        .optional()
        .orEnclosing();
}

Tillotson::Tillotson(const Dictionary& dict) : EquationOfState(dict) {
    const KeywordValues v = keywords().read(dict);
    setReferenceDensity(v.scalar("rho0"));
    A_ = v.scalar("A");
    B_ = v.scalar("B");
    a_ = v.scalar("a");
    b_ = v.scalar("b");
    E0_ = v.scalar("E0");
    branch_ = v.word("branch") == "full" ? Branch::full : Branch::compressed;
    if (branch_ == Branch::full) {
        // Required with the expanded branch only; the schema declares them optional.
        auto required = [&](const char* key) {
            if (auto value = v.optionalScalar(key)) return *value;
            throw InputError(
                dict.where(), dict.scope(),
                std::string("missing keyword '") + key +
                    "' (a real number, required with branch full), looked for in '" + dict.scope() + "'" +
                    (dict.parent() ? " and in the enclosing '" + dict.parent()->scope() + "'" : ""));
        };
        alpha_ = required("alpha");
        beta_ = required("beta");
        Eiv_ = required("Eiv");
        Ecv_ = required("Ecv");
        if (!(Ecv_ > Eiv_))
            throw v.error("Ecv", "expected a real number greater than Eiv = " + formatKeywordNumber(Eiv_) +
                                     ", found " + formatKeywordNumber(Ecv_));
    }
    if (auto pMin = v.optionalScalar("minimumPressure")) pMin_ = *pMin;
}

void Tillotson::compressed(double rho, double e, double& p, double& pRho, double& pE) const {
    const double rho0 = referenceDensity();
    const double eta = rho / rho0, mu = eta - 1.0;
    const double omega = e / (E0_ * eta * eta) + 1.0;
    const double omegaRho = -2.0 * e / (E0_ * eta * eta * eta * rho0);
    const double omegaE = 1.0 / (E0_ * eta * eta);
    const double g = a_ + b_ / omega;
    p = g * rho * e + A_ * mu + B_ * mu * mu;
    pRho = g * e - b_ * rho * e * omegaRho / (omega * omega) + (A_ + 2.0 * B_ * mu) / rho0;
    pE = g * rho - b_ * rho * e * omegaE / (omega * omega);
}

void Tillotson::expanded(double rho, double e, double& p, double& pRho, double& pE) const {
    const double rho0 = referenceDensity();
    const double eta = rho / rho0, mu = eta - 1.0, x = rho0 / rho - 1.0, xRho = -rho0 / (rho * rho);
    const double omega = e / (E0_ * eta * eta) + 1.0;
    const double omegaRho = -2.0 * e / (E0_ * eta * eta * eta * rho0);
    const double omegaE = 1.0 / (E0_ * eta * eta);
    const double G = std::exp(-alpha_ * x * x), GRho = -2.0 * alpha_ * x * xRho * G;
    const double H = std::exp(-beta_ * x), HRho = -beta_ * xRho * H;
    const double F = b_ * rho * e / omega + A_ * mu * H;
    const double FRho =
        b_ * e / omega - b_ * rho * e * omegaRho / (omega * omega) + A_ * H / rho0 + A_ * mu * HRho;
    const double FE = b_ * rho / omega - b_ * rho * e * omegaE / (omega * omega);
    p = a_ * rho * e + F * G;
    pRho = a_ * e + FRho * G + F * GRho;
    pE = a_ * rho + FE * G;
}

void Tillotson::uncut(double rho, double e, double& p, double& pRho, double& pE) const {
    if (branch_ == Branch::compressed || rho >= referenceDensity() || e <= Eiv_) {
        compressed(rho, e, p, pRho, pE);
    } else if (e >= Ecv_) {
        expanded(rho, e, p, pRho, pE);
    } else {
        double pc, pcRho, pcE, pe, peRho, peE;
        compressed(rho, e, pc, pcRho, pcE);
        expanded(rho, e, pe, peRho, peE);
        const double dE = Ecv_ - Eiv_, w = (e - Eiv_) / dE;
        p = w * pe + (1.0 - w) * pc;
        pRho = w * peRho + (1.0 - w) * pcRho;
        pE = w * peE + (1.0 - w) * pcE + (pe - pc) / dE;
    }
}

void Tillotson::state(double rho, double e, double& p, double& c2) const {
    double pRho, pE;
    uncut(rho, e, p, pRho, pE);
    c2 = pRho + p * pE / (rho * rho);
    p = std::max(p, pMin_);
}

double Tillotson::pressure(double rho, double e) const {
    double p, c2;
    state(rho, e, p, c2);
    return p;
}

double Tillotson::soundSpeedSquared(double rho, double e) const {
    double p, c2;
    state(rho, e, p, c2);
    return c2;
}

double Tillotson::energyDerivative(double rho, double e) const {
    double p, pRho, pE;
    uncut(rho, e, p, pRho, pE);
    return p < pMin_ ? 0.0 : pE;
}

void Tillotson::evaluate(std::size_t n, const double* rho, const double* e, double* p, double* c) const {
    evaluateBlock(*this, n, rho, e, p, c);
}

MFDYN_REGISTER(EquationOfState, Tillotson, "tillotson", "Tillotson 1962 (compressed, expanded, blended)");

}  // namespace mfdyn
