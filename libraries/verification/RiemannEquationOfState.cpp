// Wave curves of the three closures of the exact Riemann solver.
//
// Ideal and stiffened gas (Toro 2009, "Riemann Solvers and Numerical Methods for Fluid Dynamics",
// 3rd ed., Ch. 4; stiffened gas by the substitution P -> Pbar = P + pRef, Ivings, Causon & Toro 1998,
// Int. J. Numer. Meth. Fluids 28:395). With A_K = 2/((g+1) rho_K), B_K = (g-1)/(g+1) Pbar_K and
// c_K^2 = g Pbar_K / rho_K:
//
//     shock (P > P_K):   f_K = (P - P_K) sqrt(A_K / (Pbar + B_K))                       (4.6)
//     rarefaction:       f_K = 2 c_K/(g-1) [(Pbar/Pbar_K)^((g-1)/(2g)) - 1]               (4.7)
//     rho behind shock:  rho_K [Pbar/Pbar_K + (g-1)/(g+1)] / [(g-1)/(g+1) Pbar/Pbar_K + 1]  (4.50)
//     shock speed:       v_K -+ c_K sqrt((g+1)/(2g) Pbar/Pbar_K + (g-1)/(2g))              (4.52)
//     fan (left):        v = 2/(g+1) [c_L + (g-1)/2 v_L + xi], c = 2/(g+1) [c_L + (g-1)/2 (v_L - xi)]
//                        rho = rho_L (c/c_L)^(2/(g-1))                                      (4.56)
//
// Linear barotropic P = c0^2 (rho - rho0) (Zisis 2017 Eq. 5.1; doc/methods/sph-impact.md 5.1), c = c0.
// Rankine-Hugoniot for mass and momentum only (no energy equation), m^2 = (P - P_K)/(1/rho_K - 1/rho):
//
//     shock:       f_K = sqrt((P - P_K)(1/rho_K - 1/rho)) = c0 [sqrt(rho/rho_K) - sqrt(rho_K/rho)]
//                  speed v_K -+ c0 sqrt(rho/rho_K)   (mass flux m = c0 sqrt(rho rho_K))
//     rarefaction: Riemann invariant v -+ c0 ln rho constant across the fan (dP/drho = c0^2), so
//                  f_K = c0 ln(rho/rho_K) and, in the fan, v = xi -+ c0, rho = rho_K exp(-+(v - v_K)/c0)
//                  (upper sign for a left-facing wave). This reproduces the note's fan of 8.2,
//                  rho = 1.64039 exp(-(v - 0.5)).
//
// Both branches meet at P = P_K with slope 1/(rho_K c_K), so f_K is C1 and increasing, which the
// Newton iteration of RiemannSolver relies on. A barotropic material may carry tension (P < 0) down
// to rho -> 0, where its rarefaction curve tends to -infinity: it never cavitates by itself.
#include "verification/RiemannEquationOfState.hpp"

#include <cmath>
#include <limits>
#include <sstream>

#include "core/Error.hpp"
#include "core/KeywordSchema.hpp"  // formatKeywordNumber: 1e-320 shows as 9.99989e-321, not 0.000000

namespace mfdyn {

RiemannEquationOfState::RiemannEquationOfState(Kind kind, double gamma, double pRef, double rho0, double c0)
    : kind_(kind), gamma_(gamma), pRef_(pRef), rho0_(rho0), c0_(c0) {}

RiemannEquationOfState RiemannEquationOfState::idealGas(double gamma) {
    if (!(gamma > 1.0))
        throw Error("RiemannEquationOfState::idealGas: gamma must be > 1, found " +
                    formatKeywordNumber(gamma));
    return {Kind::idealGas, gamma, 0.0, 0.0, 0.0};
}

RiemannEquationOfState RiemannEquationOfState::stiffenedGas(double gamma, double pRef) {
    if (!(gamma > 1.0))
        throw Error("RiemannEquationOfState::stiffenedGas: gamma must be > 1, found " +
                    formatKeywordNumber(gamma));
    if (!(pRef >= 0.0))
        throw Error("RiemannEquationOfState::stiffenedGas: pRef must be >= 0, found " +
                    formatKeywordNumber(pRef));
    return {Kind::stiffenedGas, gamma, pRef, 0.0, 0.0};
}

RiemannEquationOfState RiemannEquationOfState::linearBarotropic(double rho0, double c0) {
    if (!(rho0 > 0.0) || !(c0 > 0.0))
        throw Error("RiemannEquationOfState::linearBarotropic: rho0 and c0 must be > 0, found rho0 = " +
                    formatKeywordNumber(rho0) + ", c0 = " + formatKeywordNumber(c0));
    return {Kind::linearBarotropic, 0.0, 0.0, rho0, c0};
}

std::string RiemannEquationOfState::describe() const {
    std::ostringstream s;
    s.precision(8);
    switch (kind_) {
        case Kind::idealGas:
            s << "idealGas(gamma=" << gamma_ << ")";
            break;
        case Kind::stiffenedGas:
            s << "stiffenedGas(gamma=" << gamma_ << ", pRef=" << pRef_ << ")";
            break;
        case Kind::linearBarotropic:
            s << "linearBarotropic(rho0=" << rho0_ << ", c0=" << c0_ << ")";
            break;
    }
    return s.str();
}

double RiemannEquationOfState::pressure(double rho, double e) const {
    if (kind_ == Kind::linearBarotropic) return c0_ * c0_ * (rho - rho0_);
    return (gamma_ - 1.0) * rho * e - gamma_ * pRef_;
}

double RiemannEquationOfState::internalEnergy(double rho, double p) const {
    if (kind_ == Kind::linearBarotropic) return std::numeric_limits<double>::quiet_NaN();
    return (p + gamma_ * pRef_) / ((gamma_ - 1.0) * rho);
}

double RiemannEquationOfState::soundSpeed(double rho, double p) const {
    if (kind_ == Kind::linearBarotropic) return c0_;
    return std::sqrt(gamma_ * (p + pRef_) / rho);
}

double RiemannEquationOfState::pressureFloor() const {
    if (kind_ == Kind::linearBarotropic) return -c0_ * c0_ * rho0_;
    return -pRef_;
}

double RiemannEquationOfState::barotropicDensity(double p) const {
    return rho0_ + p / (c0_ * c0_);
}

void RiemannEquationOfState::check(const PrimitiveState& k, const std::string& side) const {
    std::ostringstream s;
    s.precision(12);
    if (!(k.density > 0.0) || !std::isfinite(k.density) || !std::isfinite(k.velocity) ||
        !std::isfinite(k.pressure)) {
        s << "RiemannSolver: " << side << " state (rho = " << k.density << ", v = " << k.velocity
          << ", P = " << k.pressure << ") needs a finite positive density and finite v, P";
        throw Error(s.str());
    }
    if (kind_ == Kind::linearBarotropic) {
        // The state's pressure must be the one the material assigns to its density; a silent
        // override would hide a wrong reference state in the caller.
        const double expected = c0_ * c0_ * (k.density - rho0_);
        if (std::abs(k.pressure - expected) > 1e-10 * (std::abs(expected) + c0_ * c0_ * rho0_)) {
            s << "RiemannSolver: " << side << " state has P = " << k.pressure << " but " << describe()
              << " gives c0^2 (rho - rho0) = " << expected << " at rho = " << k.density;
            throw Error(s.str());
        }
    } else if (!(k.pressure > pressureFloor())) {
        s << "RiemannSolver: " << side << " state has P = " << k.pressure << ", at or below the floor "
          << pressureFloor() << " of " << describe() << " (c^2 would not be positive)";
        throw Error(s.str());
    }
}

RiemannEquationOfState::WaveFunction RiemannEquationOfState::waveFunction(const PrimitiveState& k,
                                                                          double p) const {
    if (kind_ == Kind::linearBarotropic) {
        const double rho = barotropicDensity(p), rhoK = k.density;
        if (rho <= 0.0)
            return {-std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity()};
        if (p > k.pressure) {
            const double s = std::sqrt(rho * rhoK);
            return {c0_ * (rho - rhoK) / s, (1.0 + rhoK / rho) / (2.0 * c0_ * s)};
        }
        return {c0_ * std::log(rho / rhoK), 1.0 / (c0_ * rho)};
    }
    const double g = gamma_, pBar = p + pRef_, pBarK = k.pressure + pRef_;
    if (p > k.pressure) {
        const double a = 2.0 / ((g + 1.0) * k.density), b = (g - 1.0) / (g + 1.0) * pBarK;
        const double q = std::sqrt(a / (pBar + b));
        return {(p - k.pressure) * q, q * (1.0 - 0.5 * (p - k.pressure) / (b + pBar))};
    }
    if (pBar <= 0.0) {
        // The isentrope reaches zero density at Pbar = 0 with a finite velocity jump (escape speed).
        const double cK = soundSpeed(k.density, k.pressure);
        return {-2.0 * cK / (g - 1.0), std::numeric_limits<double>::infinity()};
    }
    const double cK = soundSpeed(k.density, k.pressure), ratio = pBar / pBarK;
    return {2.0 * cK / (g - 1.0) * (std::pow(ratio, (g - 1.0) / (2.0 * g)) - 1.0),
            std::pow(ratio, -(g + 1.0) / (2.0 * g)) / (k.density * cK)};
}

double RiemannEquationOfState::densityBehind(const PrimitiveState& k, double pStar) const {
    if (kind_ == Kind::linearBarotropic) return barotropicDensity(pStar);
    const double g = gamma_, ratio = (pStar + pRef_) / (k.pressure + pRef_);
    if (pStar > k.pressure) {
        const double mu = (g - 1.0) / (g + 1.0);
        return k.density * (ratio + mu) / (mu * ratio + 1.0);
    }
    return k.density * std::pow(ratio, 1.0 / g);
}

double RiemannEquationOfState::shockSpeed(const PrimitiveState& k, double pStar, int side) const {
    if (kind_ == Kind::linearBarotropic)
        return k.velocity + side * c0_ * std::sqrt(barotropicDensity(pStar) / k.density);
    const double g = gamma_, ratio = (pStar + pRef_) / (k.pressure + pRef_);
    const double cK = soundSpeed(k.density, k.pressure);
    return k.velocity + side * cK * std::sqrt((g + 1.0) / (2.0 * g) * ratio + (g - 1.0) / (2.0 * g));
}

FlowState RiemannEquationOfState::fan(const PrimitiveState& k, double xi, int side) const {
    if (kind_ == Kind::linearBarotropic) {
        const double v = xi - side * c0_;
        const double rho = k.density * std::exp(side * (v - k.velocity) / c0_);
        return {rho, v, c0_ * c0_ * (rho - rho0_), internalEnergy(rho, 0.0)};
    }
    const double g = gamma_, cK = soundSpeed(k.density, k.pressure);
    const double v = 2.0 / (g + 1.0) * (-side * cK + 0.5 * (g - 1.0) * k.velocity + xi);
    const double c = 2.0 / (g + 1.0) * (cK + side * 0.5 * (g - 1.0) * (xi - k.velocity));
    const double rho = k.density * std::pow(c / cK, 2.0 / (g - 1.0));
    const double p = (k.pressure + pRef_) * std::pow(c / cK, 2.0 * g / (g - 1.0)) - pRef_;
    return {rho, v, p, internalEnergy(rho, p)};
}

}  // namespace mfdyn
