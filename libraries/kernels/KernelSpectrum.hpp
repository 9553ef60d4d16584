#pragma once
// The Fourier transform of a radial kernel and the verdict whether it is positive definite.
//
// A kernel whose transform is negative somewhere lets the SPH density estimate, and the particle
// distribution it drives, develop the pairing instability (Dehnen & Aly 2012, MNRAS 425:1068,
// section 3; property 6 of doc/methods/sph-impact.md 1.1). For a radial W the d-dimensional transform is
//
//     d = 1:  W^(k) = 2 int_0^H W(r) cos(kr) dr             FFTW_REDFT00 (DCT-I) on samples
//     d = 2:  W^(k) = 2 pi int_0^H W(r) J0(kr) r dr         Gauss-Legendre, std::cyl_bessel_j
//     d = 3:  W^(k) = 4 pi/k int_0^H W(r) r sin(kr) dr      FFTW_RODFT00 (DST-I) on samples
//
// so W^(0) = 1. The sampled transforms are trapezoidal sums on r_j = j H/S over [0, L], L = P H
// (P = padding), which gives the wavenumbers k_m = pi m/L; the 2D quadrature uses the same k_m.
// Each transform is done twice, at S and 2S samples (or panels), and the largest difference is the
// error estimate. At the support edge a sample takes the mean of the two one-sided limits, so the
// truncated Gaussian's jump costs O(1/S^2), not O(1/S).
//
// Verdict: positive definite when min_k W^(k) >= -tolerance, tolerance = error estimate + m/(1 - m)
// + 1e-14, where m is the truncated mass (Kernel::truncatedMass): truncation can lower the
// transform of a positive-definite kernel by at most that, since |FT of the removed tail| <= m.
#include "kernels/Kernel.hpp"

#include <string>
#include <vector>

namespace mfdyn {

struct SpectrumOptions {
    int samplesPerSupport = 256;  // S: samples over the support radius H (doubled for the error)
    int padding = 8;              // P: transform length L = P H, so dk = pi/(P H)
    double kMaxH = 100.0;         // largest k H reported
};

class KernelSpectrum {
public:
    KernelSpectrum(const Kernel& kernel, int dim, double h = 1.0, const SpectrumOptions& options = {});

    int dimension() const { return dim_; }
    double h() const { return h_; }
    const std::vector<double>& k() const { return k_; }            // 1/length
    const std::vector<double>& values() const { return values_; }  // W^(k)
    // W^ for an arbitrary k by the direct quadrature in any dimension (for checks and sparse k).
    static double transformAt(const Kernel& kernel, int dim, double h, double k, int panels = 64);

    double errorEstimate() const { return errorEstimate_; }
    double truncationBound() const { return truncationBound_; }
    double tolerance() const { return errorEstimate_ + truncationBound_ + 1e-14; }
    double minimum() const { return minimum_; }
    double kAtMinimum() const { return kAtMinimum_; }
    bool positiveDefinite() const { return minimum_ >= -tolerance(); }
    const std::string& method() const { return method_; }

private:
    std::vector<double> transform(const Kernel& kernel, int samples, int count) const;

    int dim_;
    double h_;
    SpectrumOptions options_;
    std::vector<double> k_, values_;
    double errorEstimate_ = 0.0, truncationBound_ = 0.0, minimum_ = 0.0, kAtMinimum_ = 0.0;
    std::string method_;
};

}  // namespace mfdyn
