// Spectra: the transforms against closed forms, and the positive-definiteness verdicts of Dehnen &
// Aly 2012 (MNRAS 425:1068, section 3 and Fig. 2): Wendland functions and the Gaussian positive in
// every dimension, the B-splines M4 and M6 with negative lobes in 2D and 3D.
#include "KernelTestTools.hpp"

#include "kernels/KernelSpectrum.hpp"

#include <gtest/gtest.h>

namespace mfdyn {
namespace {

using test::makeKernel;

TEST(KernelSpectrum, cubicSplineIn1DIsSincToTheFourth) {
    // M4 in 1D is the 4-fold convolution of a box of width H/2: W^(k) = (sin(kH/4)/(kH/4))^4.
    auto kernel = makeKernel("type cubicSpline;");
    const KernelSpectrum spectrum(*kernel, 1, 0.5);
    const double H = kernel->supportRadius(0.5);
    ASSERT_GT(spectrum.k().size(), 100u);
    EXPECT_LT(spectrum.errorEstimate(), 1e-8);  // trapezoid sums, knots on samples: O(S^-4)
    for (std::size_t m = 0; m < spectrum.k().size(); ++m) {
        const double x = spectrum.k()[m] * H / 4.0;
        const double sinc = m == 0 ? 1.0 : std::sin(x) / x;
        EXPECT_NEAR(spectrum.values()[m], std::pow(sinc, 4), spectrum.errorEstimate() + 1e-13)
            << "kH = " << 4 * x;
    }
    EXPECT_TRUE(spectrum.positiveDefinite());
}

TEST(KernelSpectrum, gaussianIn3DIsGaussianUpToTruncation) {
    // Untruncated: W^(k) = exp(-k^2 h^2/4). Truncation and renormalisation move it by at most
    // (m W^ + m)/(1 - m) <= 2 m/(1 - m) with m the removed mass.
    auto kernel = makeKernel("type gaussian;");
    const double h = 1.0;
    const KernelSpectrum spectrum(*kernel, 3, h);
    for (std::size_t m = 0; m < spectrum.k().size(); ++m) {
        const double k = spectrum.k()[m];
        EXPECT_NEAR(spectrum.values()[m], std::exp(-0.25 * k * k * h * h),
                    2.0 * spectrum.truncationBound() + spectrum.errorEstimate())
            << "kh = " << k * h;
    }
}

TEST(KernelSpectrum, fftAgreesWithDirectQuadrature) {
    // The FFTW cosine (1D) and sine (3D) transforms against Gauss-Legendre at the same k.
    for (const char* type : {"wendlandC4", "quinticSpline", "mollifier"}) {
        auto kernel = makeKernel(std::string("type ") + type + ";");
        for (int dim : {1, 3}) {
            const KernelSpectrum spectrum(*kernel, dim, 0.8);
            for (std::size_t m = 0; m < spectrum.k().size(); m += 17) {
                const double direct = KernelSpectrum::transformAt(*kernel, dim, 0.8, spectrum.k()[m], 128);
                EXPECT_NEAR(spectrum.values()[m], direct, spectrum.errorEstimate() + 1e-12)
                    << type << " d = " << dim << " k = " << spectrum.k()[m];
            }
            EXPECT_NEAR(spectrum.values()[0], 1.0, spectrum.errorEstimate() + 1e-12);
        }
    }
}

TEST(KernelSpectrum, wendlandAndGaussianArePositiveDefinite) {
    for (const char* type : {"wendlandC2", "wendlandC4", "wendlandC6", "gaussian"}) {
        auto kernel = makeKernel(std::string("type ") + type + ";");
        for (int dim = 1; dim <= 3; ++dim) {
            const KernelSpectrum spectrum(*kernel, dim);
            // The verdict must rest on an accurate transform, not on a loose tolerance (the truncated
            // Gaussian's jump at the cutoff limits its sums to O(S^-2), about 1e-7 here).
            EXPECT_LT(spectrum.errorEstimate(), 1e-6) << type << " d = " << dim;
            EXPECT_TRUE(spectrum.positiveDefinite())
                << type << " d = " << dim << ": min " << spectrum.minimum()
                << " at k = " << spectrum.kAtMinimum() << ", tolerance " << spectrum.tolerance();
        }
    }
}

TEST(KernelSpectrum, splinesHaveNegativeLobesIn2DAnd3D) {
    for (const char* type : {"cubicSpline", "quinticSpline"}) {
        auto kernel = makeKernel(std::string("type ") + type + ";");
        for (int dim = 2; dim <= 3; ++dim) {
            const KernelSpectrum spectrum(*kernel, dim);
            EXPECT_FALSE(spectrum.positiveDefinite()) << type << " d = " << dim;
            // Clearly negative: a hundred times the tolerance, not a rounding artefact.
            EXPECT_LT(spectrum.minimum(), -100.0 * spectrum.tolerance())
                << type << " d = " << dim << ": min " << spectrum.minimum()
                << " at kH = " << spectrum.kAtMinimum() * kernel->supportRadius(1.0);
        }
        // In 1D they are powers of sinc and positive (touching zero).
        EXPECT_TRUE(KernelSpectrum(*kernel, 1).positiveDefinite()) << type;
    }
}

TEST(KernelSpectrum, mollifierHasDeepNegativeLobe) {
    // Reference: 1D transform at k h = 6.67588 by a separate trapezoidal sum of 200000 intervals
    // over [-1, 1] (exponentially accurate for this C-infinity bump): -0.0974733381125.
    auto kernel = makeKernel("type mollifier;");
    EXPECT_NEAR(KernelSpectrum::transformAt(*kernel, 1, 1.0, 6.67588), -0.0974733381125, 1e-11);
    for (int dim = 1; dim <= 3; ++dim) {
        const KernelSpectrum spectrum(*kernel, dim);
        EXPECT_FALSE(spectrum.positiveDefinite()) << dim;
        EXPECT_LT(spectrum.minimum(), -0.04) << dim;
    }
}

}  // namespace
}  // namespace mfdyn
