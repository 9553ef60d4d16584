#pragma once
// The M6 quintic B-spline (Morris et al. 1997, Monaghan 2005), support H = 3h. Equations in
// QuinticSpline.cpp.
#include "kernels/Kernel.hpp"

namespace mfdyn {

class QuinticSpline : public Kernel {
public:
    explicit QuinticSpline(const Dictionary& dict);
    static KeywordSchema keywords() { return commonKeywords("quinticSpline"); }

    double shape(double u, int dim) const override;
    double shapeDerivative(double u, int dim) const override;
    std::vector<double> knots() const override { return {1.0 / 3.0, 2.0 / 3.0}; }
};

}  // namespace mfdyn
