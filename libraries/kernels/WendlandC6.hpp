#pragma once
// Wendland's C6 function (Wendland 1995), support H = 2h. Equations in WendlandC6.cpp.
#include "kernels/Kernel.hpp"

namespace mfdyn {

class WendlandC6 : public Kernel {
public:
    explicit WendlandC6(const Dictionary& dict);
    static KeywordSchema keywords() { return commonKeywords("wendlandC6"); }

    double shape(double u, int dim) const override;
    double shapeDerivative(double u, int dim) const override;
};

}  // namespace mfdyn
