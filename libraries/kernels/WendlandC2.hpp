#pragma once
// Wendland's C2 function (Wendland 1995), support H = 2h. Equations in WendlandC2.cpp.
#include "kernels/Kernel.hpp"

namespace mfdyn {

class WendlandC2 : public Kernel {
public:
    explicit WendlandC2(const Dictionary& dict);
    static KeywordSchema keywords() { return commonKeywords("wendlandC2"); }

    double shape(double u, int dim) const override;
    double shapeDerivative(double u, int dim) const override;
};

}  // namespace mfdyn
