// The strength family: conventions and shared helpers (see Strength.hpp). The equivalent stress
// and strain rate are those of von Mises plasticity (Hill 1950, The Mathematical Theory of
// Plasticity, ch. II): sigmaEq = sqrt(3 J2) with J2 = tau:tau/2, epsDotEq = sqrt(2/3 D':D').
#include "materials/strength/Strength.hpp"

#include <cmath>
#include <sstream>

namespace mfdyn {

template <int Dim>
std::string Strength<Dim>::formatNumber(double value) {
    return formatKeywordNumber(value);
}

template <int Dim>
Strength<Dim>::Strength(const Dictionary& dict) : type_(dict.get<std::string>("type")) {}

template <int Dim>
double Strength<Dim>::equivalentStress(const SymmTensor<Dim>& tau) const {
    double ss = 0.0, trace = 0.0;
    for (int i = 0; i < Dim; ++i) {
        ss += tau(i, i) * tau(i, i);
        trace += tau(i, i);
        for (int j = i + 1; j < Dim; ++j) ss += 2.0 * tau(i, j) * tau(i, j);
    }
    // Each of the k implied normal components is -trace/k: together trace^2/k.
    if (impliedComponents_ > 0) ss += trace * trace / impliedComponents_;
    return std::sqrt(1.5 * ss);
}

template <int Dim>
double Strength<Dim>::equivalentStrainRate(const Tensor<Dim>& velocityGradient) const {
    const Tensor<Dim> d = 0.5 * (velocityGradient + velocityGradient.transpose());
    const double trace = d.trace();
    Tensor<Dim> dev = d;
    dev.diagonal().array() -= deviatorWeight_ * trace;
    double dd = dev.squaredNorm();
    // Out of the plane D = 0, so each implied component of D' is -alpha tr D.
    if (impliedComponents_ > 0)
        dd += impliedComponents_ * (deviatorWeight_ * trace) * (deviatorWeight_ * trace);
    return std::sqrt(2.0 / 3.0 * dd);
}

template class Strength<1>;
template class Strength<2>;
template class Strength<3>;

}  // namespace mfdyn
