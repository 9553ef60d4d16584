#pragma once
// Composite Gauss-Legendre quadrature on [a, b] split at given break points. Kernels are piecewise
// polynomials (splines, Wendland) or smooth functions (Gaussian, mollifier); with the panels
// aligned to the spline knots every piece is integrated exactly up to degree 2n-1, and smooth
// integrands converge exponentially, so one rule serves normalisation, moments and the 2D Hankel
// transform.
#include <functional>
#include <vector>

namespace mfdyn {

class GaussLegendre {
public:
    // An n-point rule; nodes are found by Newton iteration on P_n to machine precision.
    explicit GaussLegendre(int n = 20);

    int order() const { return int(nodes_.size()); }
    const std::vector<double>& nodes() const { return nodes_; }      // on [-1, 1]
    const std::vector<double>& weights() const { return weights_; }  // summing to 2

    // Integral of f over [a, b]: the interval is cut at `breaks` (those inside (a, b)), and each
    // piece into `panels` equal panels.
    double integrate(const std::function<double(double)>& f, double a, double b,
                     const std::vector<double>& breaks, int panels) const;

    // The same panels as (abscissa, weight) pairs, for callers that reuse the nodes many times.
    void panelNodes(double a, double b, const std::vector<double>& breaks, int panels, std::vector<double>& x,
                    std::vector<double>& w) const;

private:
    std::vector<double> nodes_, weights_;
};

}  // namespace mfdyn
