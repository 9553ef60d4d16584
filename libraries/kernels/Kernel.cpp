#include "kernels/Kernel.hpp"

#include "kernels/GaussLegendre.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>

namespace mfdyn {

namespace {

// Surface of the unit sphere in d dimensions: the radial measure of a radial function.
double sphereSurface(int dim) {
    constexpr double pi = std::numbers::pi;
    return dim == 1 ? 2.0 : dim == 2 ? 2.0 * pi : 4.0 * pi;
}

// Radial integral of w(u) u^p over [0, 1], with the panel count doubled until two successive values
// agree to 1e-15 relative: exact at once for piecewise polynomials, and to the 1e-12 the brief asks
// of the mollifier's constant with orders of magnitude to spare.
double radialMoment(const Kernel& kernel, int dim, int p) {
    static const GaussLegendre rule(20);
    auto f = [&](double u) { return kernel.shape(u, dim) * std::pow(u, p); };
    double previous = rule.integrate(f, 0.0, 1.0, kernel.knots(), 8);
    for (int panels = 16; panels <= 4096; panels *= 2) {
        const double next = rule.integrate(f, 0.0, 1.0, kernel.knots(), panels);
        if (std::abs(next - previous) <= 1e-15 * std::abs(next)) return next;
        previous = next;
    }
    return previous;
}

}  // namespace

KeywordSchema Kernel::commonKeywords(const std::string& type) {
    return KeywordSchema(familyName, type)
        .word("hConvention", {"standard", "supportRadius"},
              "smoothing length convention: standard, H = kappa h (kappa per type), or supportRadius, H = h "
              "(the note's)")
        .orDefault("standard");
}

Kernel::Kernel(const Dictionary& dict, double standardKappa)
    : Kernel(dict, commonKeywords(dict.get<std::string>("type")).read(dict), standardKappa) {}

Kernel::Kernel(const Dictionary& dict, const KeywordValues& values, double standardKappa)
    : type_(dict.get<std::string>("type")) {
    kappa_ = values.word("hConvention") == "standard" ? standardKappa : 1.0;
}

int Kernel::index(int dim) {
    if (dim < 1 || dim > 3)
        throw std::invalid_argument("kernel dimension must be 1, 2 or 3, got " + std::to_string(dim));
    return dim - 1;
}

void Kernel::initialise() {
    for (int dim = 1; dim <= 3; ++dim) {
        const double mass = sphereSurface(dim) * radialMoment(*this, dim, dim - 1);
        const double second = sphereSurface(dim) * radialMoment(*this, dim, dim + 1);
        norm_[dim - 1] = 1.0 / mass;
        momentUnit_[dim - 1] = std::sqrt(second / mass);

        // Cubic Hermite pieces from w and w' at the cell edges, as Horner coefficients in the local
        // coordinate s in [0, 1] (KernelEvaluator::shape).
        std::vector<double>& table = tables_[dim - 1];
        table.assign(4 * tableCells, 0.0);
        const double du = 1.0 / tableCells;
        double w0 = shape(0.0, dim), d0 = shapeDerivative(0.0, dim) * du;
        for (int i = 0; i < tableCells; ++i) {
            const double u1 = double(i + 1) / tableCells;
            const double w1 = shape(u1, dim), d1 = shapeDerivative(u1, dim) * du;
            double* a = &table[4 * i];
            a[0] = w0;
            a[1] = d0;
            a[2] = 3.0 * (w1 - w0) - 2.0 * d0 - d1;
            a[3] = 2.0 * (w0 - w1) + d0 + d1;
            w0 = w1;
            d0 = d1;
        }
    }
}

double Kernel::W(double r, double h, int dim) const {
    const double H = kappa_ * h, u = r / H;
    return u < 1.0 ? normalisation(dim) * std::pow(H, -dim) * shape(u, dim) : 0.0;
}

double Kernel::dWdr(double r, double h, int dim) const {
    const double H = kappa_ * h, u = r / H;
    return u < 1.0 ? normalisation(dim) * std::pow(H, -dim - 1) * shapeDerivative(u, dim) : 0.0;
}

double Kernel::dWdh(double r, double h, int dim) const {
    const double H = kappa_ * h, u = r / H;
    if (u >= 1.0) return 0.0;
    return -normalisation(dim) * std::pow(H, -dim) / h * (dim * shape(u, dim) + u * shapeDerivative(u, dim));
}

double matchedSmoothingLength(const Kernel& from, double hFrom, const Kernel& to, int dim) {
    return hFrom * from.secondMoment(dim) / to.secondMoment(dim);
}

}  // namespace mfdyn
