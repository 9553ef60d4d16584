#pragma once
// The M4 cubic B-spline (Monaghan 1992), support H = 2h. Equations in CubicSpline.cpp.
#include "kernels/Kernel.hpp"

namespace mfdyn {

class CubicSpline : public Kernel {
public:
    explicit CubicSpline(const Dictionary& dict);
    static KeywordSchema keywords() { return commonKeywords("cubicSpline"); }

    double shape(double u, int dim) const override;
    double shapeDerivative(double u, int dim) const override;
    std::vector<double> knots() const override { return {0.5}; }
};

}  // namespace mfdyn
