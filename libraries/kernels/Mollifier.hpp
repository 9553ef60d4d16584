#pragma once
// The standard C-infinity bump (Friedrichs 1944; Zisis 2017 Eq. 2.4), support H = h. Equations in
// Mollifier.cpp.
#include "kernels/Kernel.hpp"

namespace mfdyn {

class Mollifier : public Kernel {
public:
    explicit Mollifier(const Dictionary& dict);
    static KeywordSchema keywords() { return commonKeywords("mollifier"); }

    double shape(double u, int dim) const override;
    double shapeDerivative(double u, int dim) const override;
};

}  // namespace mfdyn
