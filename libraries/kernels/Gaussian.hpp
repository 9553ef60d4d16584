#pragma once
// The Gaussian exp(-(r/h)^2) truncated at r = cutoff h and renormalised (Gingold & Monaghan 1977).
// Equations in Gaussian.cpp.
#include "kernels/Kernel.hpp"

namespace mfdyn {

class Gaussian : public Kernel {
public:
    explicit Gaussian(const Dictionary& dict);
    static KeywordSchema keywords();

    double shape(double u, int dim) const override;
    double shapeDerivative(double u, int dim) const override;
    double truncatedMass(int dim) const override;

    double cutoff() const { return cutoff_; }

private:
    // The cutoff is read before the base needs it as kappa.
    Gaussian(const Dictionary& dict, const KeywordValues& values);

    double cutoff_;
};

}  // namespace mfdyn
