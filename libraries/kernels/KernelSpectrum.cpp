#include "kernels/KernelSpectrum.hpp"

#include "kernels/GaussLegendre.hpp"

#include <fftw3.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <numbers>
#include <stdexcept>

namespace mfdyn {

namespace {

constexpr double pi = std::numbers::pi;

// W at u = r/H sampled for a trapezoidal transform: the mean of both limits at the support edge.
double sample(const Kernel& kernel, int dim, double H, int j, int samplesPerSupport) {
    if (j > samplesPerSupport) return 0.0;
    const double u = double(j) / samplesPerSupport;
    const double value = kernel.normalisation(dim) * std::pow(H, -dim) * kernel.shape(u, dim);
    return j == samplesPerSupport ? 0.5 * value : value;
}

// RAII for FFTW's aligned buffers and plans.
struct FftwBuffer {
    explicit FftwBuffer(int n) : data(fftw_alloc_real(n)) {
        if (!data) throw std::bad_alloc();
    }
    ~FftwBuffer() { fftw_free(data); }
    double* data;
};

std::vector<double> realToReal(std::vector<double> input, fftw_r2r_kind kind) {
    const int n = int(input.size());
    FftwBuffer in(n), out(n);
    fftw_plan plan = fftw_plan_r2r_1d(n, in.data, out.data, kind, FFTW_ESTIMATE);
    if (!plan) throw std::runtime_error("FFTW could not plan a transform of length " + std::to_string(n));
    std::copy(input.begin(), input.end(), in.data);
    fftw_execute(plan);
    fftw_destroy_plan(plan);
    return std::vector<double>(out.data, out.data + n);
}

}  // namespace

double KernelSpectrum::transformAt(const Kernel& kernel, int dim, double h, double k, int panels) {
    static const GaussLegendre rule(20);
    const double H = kernel.supportRadius(h);
    std::vector<double> breaks;
    for (double u : kernel.knots()) breaks.push_back(u * H);
    // Inside the support only, so the truncated Gaussian's jump sits at the end of the last panel.
    std::vector<double> r, w;
    rule.panelNodes(0.0, H, breaks, panels, r, w);
    double sum = 0.0;
    for (std::size_t i = 0; i < r.size(); ++i) {
        const double W = kernel.normalisation(dim) * std::pow(H, -dim) * kernel.shape(r[i] / H, dim);
        double radial;
        if (dim == 1)
            radial = 2.0 * std::cos(k * r[i]);
        else if (dim == 2)
            radial = 2.0 * pi * r[i] * std::cyl_bessel_j(0.0, k * r[i]);
        else
            radial = 4.0 * pi * r[i] * r[i] * (k * r[i] > 1e-8 ? std::sin(k * r[i]) / (k * r[i]) : 1.0);
        sum += w[i] * W * radial;
    }
    return sum;
}

std::vector<double> KernelSpectrum::transform(const Kernel& kernel, int samples, int count) const {
    const double H = kernel.supportRadius(h_);
    const int N = samples * options_.padding;  // intervals over [0, L]
    const double dr = H / samples;
    std::vector<double> result(count);
    if (dim_ == 1) {
        // DCT-I over x_j = j dr, j = 0..N: Y_m = X_0 + (-1)^m X_N + 2 sum X_j cos(pi j m/N), and
        // cos(pi j m/N) = cos(k_m x_j), so dr Y_m is the trapezoidal sum of int_-L^L W cos(kx).
        std::vector<double> x(N + 1);
        for (int j = 0; j <= N; ++j) x[j] = sample(kernel, 1, H, j, samples);
        const auto y = realToReal(std::move(x), FFTW_REDFT00);
        for (int m = 0; m < count; ++m) result[m] = dr * y[m];
    } else if (dim_ == 3) {
        // DST-I over r_j = (j+1) dr, j = 0..N-2: Y_m = 2 sum X_j sin(pi (j+1)(m+1)/N) with
        // sin(...) = sin(k_{m+1} r_j); k = 0 is the plain radial sum.
        std::vector<double> x(N - 1);
        double mass = 0.0;
        for (int j = 0; j < N - 1; ++j) {
            const double r = (j + 1) * dr, W = sample(kernel, 3, H, j + 1, samples);
            x[j] = W * r;
            mass += W * r * r;
        }
        const auto y = realToReal(std::move(x), FFTW_RODFT00);
        result[0] = 4.0 * pi * dr * mass;
        const double L = options_.padding * H;
        for (int m = 1; m < count; ++m) {
            const double k = pi * m / L;
            result[m] = 4.0 * pi / k * dr * 0.5 * y[m - 1];
        }
    } else {
        // No fast Hankel transform in FFTW: Gauss-Legendre with panels short enough that kH/panels
        // stays below about pi at the largest k, where 20 points are exact to rounding.
        const double L = options_.padding * H;
        const int panels = std::max(8, samples / 16);
        for (int m = 0; m < count; ++m) result[m] = transformAt(kernel, 2, h_, pi * m / L, panels);
    }
    return result;
}

KernelSpectrum::KernelSpectrum(const Kernel& kernel, int dim, double h, const SpectrumOptions& options)
    : dim_(dim), h_(h), options_(options) {
    if (dim < 1 || dim > 3) throw std::invalid_argument("kernelSpectrum: dimension must be 1, 2 or 3");
    if (options.samplesPerSupport < 16 || options.padding < 2 || !(options.kMaxH > 0.0))
        throw std::invalid_argument("kernelSpectrum: need samplesPerSupport >= 16, padding >= 2, kMaxH > 0");
    const double H = kernel.supportRadius(h);
    const double L = options.padding * H;
    const int nyquist = options.samplesPerSupport * options.padding;  // k_m = pi m/L up to pi/dr
    const int count = std::min(nyquist - 1, int(std::floor(options.kMaxH * options.padding / pi)) + 1);
    k_.resize(count);
    for (int m = 0; m < count; ++m) k_[m] = pi * m / L;

    const auto coarse = transform(kernel, options.samplesPerSupport, count);
    values_ = transform(kernel, 2 * options.samplesPerSupport, count);
    for (int m = 0; m < count; ++m)
        errorEstimate_ = std::max(errorEstimate_, std::abs(values_[m] - coarse[m]));
    const double mass = kernel.truncatedMass(dim);
    truncationBound_ = mass / (1.0 - mass);
    const auto it = std::min_element(values_.begin(), values_.end());
    minimum_ = *it;
    kAtMinimum_ = k_[it - values_.begin()];
    method_ = dim == 1   ? "FFTW REDFT00 (cosine transform)"
              : dim == 2 ? "Gauss-Legendre Hankel transform (J0)"
                         : "FFTW RODFT00 (sine transform)";
}

}  // namespace mfdyn
