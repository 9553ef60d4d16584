#pragma once
// Wendland's C4 function (Wendland 1995), support H = 2h. Equations in WendlandC4.cpp.
#include "kernels/Kernel.hpp"

namespace mfdyn {

class WendlandC4 : public Kernel {
public:
    explicit WendlandC4(const Dictionary& dict);
    static KeywordSchema keywords() { return commonKeywords("wendlandC4"); }

    double shape(double u, int dim) const override;
    double shapeDerivative(double u, int dim) const override;
};

}  // namespace mfdyn
