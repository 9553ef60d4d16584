// No strength: tau = 0 at all times, sigma = -P I. A material without a `strength` entry behaves
// the same; this type exists so that the choice can be written down and selected.
#include "materials/strength/NoStrength.hpp"

namespace mfdyn {

template <int Dim>
NoStrength<Dim>::NoStrength(const Dictionary& dict) : Strength<Dim>(dict) {
    keywords().read(dict);
}

// A caller that allocated tau anyway (a mixed block) gets zero stress rather than stale values.
template <int Dim>
void NoStrength<Dim>::update(const Fields& fields, double /*dt*/) const {
    if (fields.tau)
        for (std::size_t i = 0; i < fields.size; ++i) fields.tau[i] = SymmTensor<Dim>{};
    if (fields.plasticWorkRate)
        for (std::size_t i = 0; i < fields.size; ++i) fields.plasticWorkRate[i] = 0.0;
}

template <int Dim>
void NoStrength<Dim>::stressRate(const Fields& fields) const {
    if (fields.tauRate)
        for (std::size_t i = 0; i < fields.size; ++i) fields.tauRate[i] = SymmTensor<Dim>{};
}

template <int Dim>
double NoStrength<Dim>::yieldStress(double, double, double) const {
    return 0.0;
}

template class NoStrength<1>;
template class NoStrength<2>;
template class NoStrength<3>;

MFDYN_REGISTER_DIM(Strength, NoStrength, "none",
                   "no deviatoric stress (fluids); the solver allocates no tau");

}  // namespace mfdyn
