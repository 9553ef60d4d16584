#include "kernels/GaussLegendre.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace mfdyn {

GaussLegendre::GaussLegendre(int n) : nodes_(n), weights_(n) {
    if (n < 1) throw std::invalid_argument("GaussLegendre: order must be positive");
    for (int i = 0; i < n; ++i) {
        // Tricomi's estimate of the i-th root, then Newton on the three-term recurrence.
        double x = std::cos(std::numbers::pi * (i + 0.75) / (n + 0.5));
        double dp = 1.0;
        for (int iter = 0; iter < 100; ++iter) {
            double p0 = 1.0, p1 = x;
            for (int k = 2; k <= n; ++k) {
                const double p2 = ((2.0 * k - 1.0) * x * p1 - (k - 1.0) * p0) / k;
                p0 = p1;
                p1 = p2;
            }
            const double p = n == 1 ? x : p1;
            const double pm1 = n == 1 ? 1.0 : p0;
            dp = n * (x * p - pm1) / (x * x - 1.0);
            const double dx = p / dp;
            x -= dx;
            if (std::abs(dx) < 1e-16) break;
        }
        nodes_[i] = x;
        weights_[i] = 2.0 / ((1.0 - x * x) * dp * dp);
    }
}

void GaussLegendre::panelNodes(double a, double b, const std::vector<double>& breaks, int panels,
                               std::vector<double>& x, std::vector<double>& w) const {
    std::vector<double> cuts{a};
    std::vector<double> inside;
    for (double c : breaks)
        if (c > a && c < b) inside.push_back(c);
    std::sort(inside.begin(), inside.end());
    cuts.insert(cuts.end(), inside.begin(), inside.end());
    cuts.push_back(b);
    x.clear();
    w.clear();
    for (std::size_t s = 0; s + 1 < cuts.size(); ++s) {
        const double len = (cuts[s + 1] - cuts[s]) / panels;
        for (int p = 0; p < panels; ++p) {
            const double mid = cuts[s] + (p + 0.5) * len;
            for (std::size_t i = 0; i < nodes_.size(); ++i) {
                x.push_back(mid + 0.5 * len * nodes_[i]);
                w.push_back(0.5 * len * weights_[i]);
            }
        }
    }
}

double GaussLegendre::integrate(const std::function<double(double)>& f, double a, double b,
                                const std::vector<double>& breaks, int panels) const {
    std::vector<double> x, w;
    panelNodes(a, b, breaks, panels, x, w);
    // Pairwise-free summation is enough here: a few thousand terms of one sign pattern.
    double sum = 0.0;
    for (std::size_t i = 0; i < x.size(); ++i) sum += w[i] * f(x[i]);
    return sum;
}

}  // namespace mfdyn
