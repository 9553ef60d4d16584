#pragma once
// `hookean`: hypoelastic deviatoric stress, Hooke's law in Jaumann-rate form, no yield
// (doc/methods/sph-impact.md section 5.2; Libersky et al. 1993). The base of vonMises and johnsonCook, which
// add a return to the yield surface.
//
//     strength { type hookean; shearModulus 27.1e9; }
//
//     keyword       meaning                                               unit  required  default
//     shearModulus  G                                                     Pa    yes
//     shearFactor   2mu = shearFactor G: 2 standard, 1 the thesis's 6.7   -     no        2
//     deviator      dimension (alpha = 1/d, thesis) | three (1/3)          -     no        dimension
//
// Keywords may also be given in the enclosing material dictionary.
#include "materials/strength/Strength.hpp"

namespace mfdyn {

template <int Dim>
class Hookean : public Strength<Dim> {
public:
    using typename Strength<Dim>::Fields;

    explicit Hookean(const Dictionary& dict);
    static KeywordSchema keywords();

    void update(const Fields& fields, double dt) const override;
    void stressRate(const Fields& fields) const override;
    void returnToYieldSurface(const Fields& fields, double dt) const override;
    double yieldStress(double plasticStrain, double strainRate, double temperature) const override;

    // 2mu, the factor of the deviatoric strain rate (2G unless shearFactor 1).
    double twoMu() const { return twoMu_; }
    // 2mu (1 - alpha): 4G/3 for the standard law in 3D (Strength.hpp).
    double longitudinalStiffness() const override { return twoMu_ * (1.0 - this->deviatorWeight_); }

protected:
    // For laws built on this one (vonMises, johnsonCook): the values read through their schema,
    // which appends to this one's.
    Hookean(const Dictionary& dict, const KeywordValues& values);

    // W tau - tau W + 2mu (D - alpha tr(D) I).
    SymmTensor<Dim> jaumannRate(const SymmTensor<Dim>& tau, const Tensor<Dim>& L) const {
        const Tensor<Dim> t = tau.full();
        const Tensor<Dim> w = 0.5 * (L - L.transpose());
        Tensor<Dim> rate = w * t - t * w + 0.5 * twoMu_ * (L + L.transpose());
        rate.diagonal().array() -= twoMu_ * this->deviatorWeight_ * L.trace();
        return SymmTensor<Dim>::fromFull(rate);
    }

    double twoMu_ = 0.0;
};

}  // namespace mfdyn
