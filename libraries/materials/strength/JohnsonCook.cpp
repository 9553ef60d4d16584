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

namespace {

template <int Dim>
using Key = typename Strength<Dim>::Keyword;

template <int Dim>
const Key<Dim> aKey{"A", "Pa", "Johnson-Cook yield stress A", std::nullopt, 0.0, false};
template <int Dim>
const Key<Dim> bKey{"B", "Pa", "Johnson-Cook hardening coefficient B", std::nullopt, 0.0, false};
template <int Dim>
const Key<Dim> nKey{"n", "-", "Johnson-Cook hardening exponent n", std::nullopt, 0.0, true};
template <int Dim>
const Key<Dim> cKey{"C", "-", "Johnson-Cook strain-rate coefficient C", std::nullopt, 0.0, false};
template <int Dim>
const Key<Dim> mKey{"m", "-", "Johnson-Cook thermal-softening exponent m", std::nullopt, 0.0, true};
template <int Dim>
const Key<Dim> rateKey{"epsilonDot0", "1/s", "reference strain rate", 1.0, 0.0, true};
template <int Dim>
const Key<Dim> roomKey{"Troom", "K", "room temperature", 293.15, 0.0, true};
template <int Dim>
const Key<Dim> meltKey{"Tmelt", "K", "melting temperature", std::nullopt, 0.0, true};
template <int Dim>
const Key<Dim> heatKey{"specificHeat", "J/kg/K", "specific heat c_v", std::nullopt, 0.0, true};
template <int Dim>
const Key<Dim> betaKey{"taylorQuinney", "-", "Taylor-Quinney coefficient beta", 0.9, 0.0, false, 1.0};

}  // namespace

template <int Dim>
JohnsonCook<Dim>::JohnsonCook(const Dictionary& dict)
    : Hookean<Dim>(dict),
      a_(this->read(dict, aKey<Dim>)),
      b_(this->read(dict, bKey<Dim>)),
      n_(this->read(dict, nKey<Dim>)),
      c_(this->read(dict, cKey<Dim>)),
      m_(this->read(dict, mKey<Dim>)),
      referenceRate_(this->read(dict, rateKey<Dim>)),
      roomTemperature_(this->read(dict, roomKey<Dim>)),
      meltTemperature_(this->read(dict, meltKey<Dim>)),
      specificHeat_(this->read(dict, heatKey<Dim>)),
      taylorQuinney_(this->read(dict, betaKey<Dim>)) {
    if (!(meltTemperature_ > roomTemperature_))
        throw dict.error("Tmelt", "expected Tmelt > Troom = " + this->formatNumber(roomTemperature_) +
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

template <int Dim>
std::vector<typename Strength<Dim>::Keyword> JohnsonCook<Dim>::keywords() const {
    auto keys = Hookean<Dim>::keywords();
    keys.insert(keys.end(), {aKey<Dim>, bKey<Dim>, nKey<Dim>, cKey<Dim>, mKey<Dim>, rateKey<Dim>,
                             roomKey<Dim>, meltKey<Dim>, heatKey<Dim>, betaKey<Dim>});
    return keys;
}

template class JohnsonCook<1>;
template class JohnsonCook<2>;
template class JohnsonCook<3>;

MFDYN_REGISTER_DIM(
    Strength, JohnsonCook, "johnsonCook",
    "hookean + radial return to the Johnson-Cook flow stress with plastic heating (Johnson & Cook 1983)");

}  // namespace mfdyn
