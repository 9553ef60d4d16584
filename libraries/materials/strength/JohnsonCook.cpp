// Johnson-Cook flow stress (Johnson & Cook 1983, "A constitutive model and data for metals
// subjected to large strains, high strain rates and high temperatures", Proc. 7th Int. Symp.
// Ballistics, The Hague, pp. 541-547, Eq. 1):
//
//     sigma_Y = (A + B epsP^n) (1 + C ln epsDot*) (1 - T*^m),
//     epsDot* = epsDot/epsilonDot0,   T* = (T - Troom)/(Tmelt - Troom),
//
// with the temperature from the plastic work (adiabatic heating, Taylor & Quinney 1934):
//
//     T = Troom + sum over steps of beta sigma_Y dEpsP / (rho c_v).
//
// Choices where the paper is silent or the model is undefined:
//   - epsDot is the equivalent total deviatoric strain rate sqrt(2/3 D':D') of the step (as
//     hydrocodes do), known before the return; epsDot* < 1 is clamped to 1, so the rate factor
//     never softens below the quasi-static curve (the log is negative there).
//   - T* is clamped to [0, 1]: below Troom no extra hardening (T*^m is undefined for T* < 0 and
//     non-integer m), at and above Tmelt sigma_Y = 0 (melt: the return removes all of tau).
//   - Rate and temperature are frozen over the step's return (explicit in time); the strain
//     hardening is implicit: dEpsP solves sigma* - 3G dEpsP = sigma_Y(epsP + dEpsP), a monotone
//     scalar equation, by Newton's method safeguarded by bisection on [0, sigma*/(3G)]. tau is then
//     scaled to sigma_Y(epsP + dEpsP) exactly, so the state lies on the surface to rounding.
// Known limits: the model is not variationally consistent (note section 5.2) and its data are
// fitted for strains below about 1 and rates below about 1e4/s; no damage (Johnson & Cook 1985).
#include "materials/strength/JohnsonCook.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace mfdyn {

template <int Dim>
KeywordSchema JohnsonCook<Dim>::keywords() {
    return Hookean<Dim>::keywords()
        .rename(Strength<Dim>::familyName, "johnsonCook")
        .scalar("A", "Pa", "Johnson-Cook yield stress A")
        .atLeast(0)
        .orEnclosing()
        .scalar("B", "Pa", "Johnson-Cook hardening coefficient B")
        .atLeast(0)
        .orEnclosing()
        .scalar("n", "-", "Johnson-Cook hardening exponent n")
        .greaterThan(0)
        .orEnclosing()
        .scalar("C", "-", "Johnson-Cook strain-rate coefficient C")
        .atLeast(0)
        .orEnclosing()
        .scalar("m", "-", "Johnson-Cook thermal-softening exponent m")
        .greaterThan(0)
        .orEnclosing()
        .scalar("epsilonDot0", "1/s", "reference strain rate")
        .greaterThan(0)
        .orDefault(1.0)
        .orEnclosing()
        .scalar("Troom", "K", "room temperature")
        .greaterThan(0)
        .orDefault(293.15)
        .orEnclosing()
        .scalar("Tmelt", "K", "melting temperature, > Troom")
        .greaterThan(0)
        .orEnclosing()
        .scalar("specificHeat", "J/kg/K", "specific heat c_v")
        .greaterThan(0)
        .orEnclosing()
        .scalar("taylorQuinney", "-",
                "Taylor-Quinney coefficient beta, the fraction of plastic work turned to heat")
        .atLeast(0)
        .atMost(1)
        .orDefault(0.9)
        .orEnclosing();
}

template <int Dim>
JohnsonCook<Dim>::JohnsonCook(const Dictionary& dict) : JohnsonCook(dict, keywords().read(dict)) {}

template <int Dim>
JohnsonCook<Dim>::JohnsonCook(const Dictionary& dict, const KeywordValues& v)
    : Hookean<Dim>(dict, v),
      a_(v.scalar("A")),
      b_(v.scalar("B")),
      n_(v.scalar("n")),
      c_(v.scalar("C")),
      m_(v.scalar("m")),
      referenceRate_(v.scalar("epsilonDot0")),
      roomTemperature_(v.scalar("Troom")),
      meltTemperature_(v.scalar("Tmelt")),
      specificHeat_(v.scalar("specificHeat")),
      taylorQuinney_(v.scalar("taylorQuinney")) {
    if (!(meltTemperature_ > roomTemperature_))
        throw v.error("Tmelt", "expected Tmelt > Troom = " + this->formatNumber(roomTemperature_) +
                                   " K, found " + this->formatNumber(meltTemperature_) + " K");
}

template <int Dim>
double JohnsonCook<Dim>::softening(double strainRate, double temperature) const {
    const double rate = 1.0 + c_ * std::log(std::max(strainRate / referenceRate_, 1.0));
    const double tStar =
        std::clamp((temperature - roomTemperature_) / (meltTemperature_ - roomTemperature_), 0.0, 1.0);
    return rate * (1.0 - std::pow(tStar, m_));
}

template <int Dim>
double JohnsonCook<Dim>::yieldStress(double plasticStrain, double strainRate, double temperature) const {
    return (a_ + b_ * std::pow(std::max(plasticStrain, 0.0), n_)) * softening(strainRate, temperature);
}

template <int Dim>
void JohnsonCook<Dim>::returnToYieldSurface(const Fields& f, double dt) const {
    if (f.size > 0 && (!f.plasticStrain || !f.temperature || !f.density || !f.velocityGradient))
        throw std::invalid_argument(
            "johnsonCook needs the velocityGradient, density, plasticStrain and temperature fields");
    const double threeG = 1.5 * this->twoMu_;
    for (std::size_t i = 0; i < f.size; ++i) {
        const double epsP = f.plasticStrain[i];
        const double trial = this->equivalentStress(f.tau[i]);
        const double k = softening(this->equivalentStrainRate(f.velocityGradient[i]), f.temperature[i]);
        const auto flowAt = [&](double d) { return k * (a_ + b_ * std::pow(epsP + d, n_)); };
        double work = 0.0;
        if (trial > flowAt(0.0)) {
            // g(d) = trial - 3G d - flow(d) decreases from g(0) > 0 to g(hi) = -flow(hi) <= 0.
            double lo = 0.0, hi = trial / threeG, d = (trial - flowAt(0.0)) / threeG;
            if (k > 0.0) {
                for (int iteration = 0; iteration < 100; ++iteration) {
                    const double g = trial - threeG * d - flowAt(d);
                    (g > 0.0 ? lo : hi) = d;
                    const double e = epsP + d;
                    const double slope = (b_ > 0.0 && e > 0.0) ? k * b_ * n_ * std::pow(e, n_ - 1.0) : 0.0;
                    double next = d + g / (threeG + slope);
                    if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
                    const bool converged = std::abs(next - d) <= 1e-15 * trial / threeG;
                    d = next;
                    if (converged || hi - lo <= 1e-15 * trial / threeG) break;
                }
            }
            const double flow = flowAt(d);
            const double factor = std::min(1.0, flow / trial);
            for (double& c : f.tau[i].c) c *= factor;
            f.plasticStrain[i] = epsP + d;
            f.temperature[i] += taylorQuinney_ * flow * d / (f.density[i] * specificHeat_);
            work = flow * d / dt;
        }
        if (f.plasticWorkRate) f.plasticWorkRate[i] = work;
    }
}

template class JohnsonCook<1>;
template class JohnsonCook<2>;
template class JohnsonCook<3>;

MFDYN_REGISTER_DIM(
    Strength, JohnsonCook, "johnsonCook",
    "hookean + radial return to the Johnson-Cook flow stress with plastic heating (Johnson & Cook 1983)");

}  // namespace mfdyn
